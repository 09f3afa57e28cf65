// The checkpoint file of an interrupted run (`checkpoint.stride`, docs/checkpoint-format.md):
// versioned, its numbers little-endian on every host, with the byte order of the machine whose
// components wrote the state images inside (those of Stride's components are portable).
#ifndef STRIDE_COSIM_RUN_CHECKPOINT_HPP
#define STRIDE_COSIM_RUN_CHECKPOINT_HPP

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "stride/cosim/execution.hpp"
#include "stride/cosim/time.hpp"

namespace stride::cosim::detail {

/// The version this build writes and reads (the earlier ones held components' images in their
/// host's memory layout).
inline constexpr std::uint32_t k_checkpoint_version = 3;

struct checkpoint_data {
  time_point time{};
  std::vector<std::byte> state;  ///< execution::save_state_bytes()
};

/// Writes `file` whole or not at all. \throws error when it cannot be written.
void write_checkpoint(const std::filesystem::path& file, time_point t,
                      std::span<const std::byte> state);
/// \throws validation_error naming the file for a file that is not a checkpoint, is damaged, has
/// another version, or comes from a host of the other byte order with a component image that is
/// not portable (not of a Stride component).
checkpoint_data read_checkpoint(const std::filesystem::path& file);

/// execution::simulate_until(stop, interrupt), calling `save` between two steps every `every` of
/// simulated time (nullopt: never). A `save` that throws is reported to `failed` and not called
/// again: the run goes on without checkpoints.
run_result simulate_saving(execution& ex, time_point stop, std::optional<duration> every,
                           const std::atomic<bool>* interrupt, const std::function<void()>& save,
                           const std::function<void(const std::string&)>& failed);

}  // namespace stride::cosim::detail

#endif  // STRIDE_COSIM_RUN_CHECKPOINT_HPP
