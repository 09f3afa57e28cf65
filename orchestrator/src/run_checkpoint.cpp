#include "run_checkpoint.hpp"

#include <algorithm>
#include <bit>
#include <fstream>
#include <iterator>

#include "run_files.hpp"
#include "state_bytes.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim::detail {

namespace fs = std::filesystem;

namespace {

// version 1 named its version in the magic and had no byte-order field
constexpr std::string_view k_magic_v1 = "stride run checkpoint 1";
constexpr std::string_view k_magic = "stride run checkpoint";

enum class byte_order : std::uint8_t { little = 0, big = 1 };

constexpr byte_order host_order() {
  return std::endian::native == std::endian::big ? byte_order::big : byte_order::little;
}

std::string order_name(byte_order o) {
  return o == byte_order::big ? "big-endian" : "little-endian";
}

// The state image of a component built with Stride's SDK (format 2) reads the same on every
// host; any other FMU's image is its own, in the byte order of the host that wrote it.
bool portable_image(std::span<const std::byte> image) {
  constexpr std::string_view k_sdk_state = "STRDSTA2";
  return image.size() >= k_sdk_state.size() &&
         std::equal(k_sdk_state.begin(), k_sdk_state.end(), image.begin(),
                    [](char c, std::byte b) { return static_cast<std::byte>(c) == b; });
}

// Another host's checkpoint: its images must all be portable.
void require_portable_images(const fs::path& file, byte_order order,
                             std::span<const std::byte> state) {
  for (const saved_component& c : saved_components(state)) {
    if (!portable_image(c.image)) {
      throw validation_error(file.string() + ": written on a " + order_name(order) +
                             " host, and the state of component '" + c.name +
                             "' is in its FMU's own format, in that host's byte order (this host "
                             "is " +
                             order_name(host_order()) +
                             "; only the states of Stride's components are portable, "
                             "docs/checkpoint-format.md)");
    }
  }
}

[[noreturn]] void refuse_version(const fs::path& file, std::uint32_t version) {
  if (version < k_checkpoint_version) {
    throw validation_error(file.string() + ": checkpoint version " + std::to_string(version) +
                           " was written by an earlier stride, whose components saved their "
                           "state in their host's memory layout; this stride reads version " +
                           std::to_string(k_checkpoint_version) +
                           " only: run again, or resume with the stride that wrote it "
                           "(docs/checkpoint-format.md)");
  }
  throw validation_error(file.string() + ": checkpoint version " + std::to_string(version) +
                         " is unknown: this stride reads version " +
                         std::to_string(k_checkpoint_version) + " (docs/checkpoint-format.md)");
}

}  // namespace

void write_checkpoint(const fs::path& file, time_point t, std::span<const std::byte> state) {
  byte_writer w;
  w.put_string(std::string(k_magic));
  w.put(k_checkpoint_version);
  // Stride's components write portable images; any other FMU's is in this host's byte order
  w.put(host_order());
  w.put(static_cast<std::int64_t>(t.time_since_epoch().count()));
  w.put_bytes(state);
  const std::vector<std::byte> bytes = w.take();
  // whole or not at all: a checkpoint cut short would be worse than none
  write_file(file, std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

checkpoint_data read_checkpoint(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.eof() && !in) throw error("cannot read " + file.string());
  const auto bytes = std::as_bytes(std::span(text.data(), text.size()));
  byte_reader r(bytes, file.string());
  const std::string magic = r.get_string();
  if (magic == k_magic_v1) refuse_version(file, 1);
  if (magic != k_magic) throw validation_error(file.string() + ": not a checkpoint of stride");
  const auto version = r.get<std::uint32_t>();
  if (version != k_checkpoint_version) refuse_version(file, version);
  const auto order = r.get<byte_order>();
  if (order != byte_order::little && order != byte_order::big) r.fail();
  checkpoint_data c;
  c.time = time_point(duration(r.get<std::int64_t>()));
  const auto state = r.get_bytes();
  c.state.assign(state.begin(), state.end());
  if (!r.at_end()) r.fail();
  if (order != host_order()) require_portable_images(file, order, c.state);
  return c;
}

run_result simulate_saving(execution& ex, time_point stop, std::optional<duration> every,
                           const std::atomic<bool>* interrupt, const std::function<void()>& save,
                           const std::function<void(const std::string&)>& failed) {
  if (!every) return ex.simulate_until(stop, interrupt);
  // the components are told the run's stop, not the first checkpoint's
  if (!ex.initialized()) ex.initialize(stop);
  const duration h = ex.base_step();
  for (;;) {
    // at least one step between two checkpoints
    const time_point until = std::min(stop, ex.current_time() + std::max(*every, h));
    const run_result r = ex.simulate_until(until, interrupt);
    const bool over = r.interrupted || r.terminated_by_component || !r.stopped_by.empty() ||
                      r.end_time + h > stop;
    if (over) return r;
    try {
      save();
    } catch (const std::exception& e) {
      failed(e.what());
      return ex.simulate_until(stop, interrupt);
    }
  }
}

}  // namespace stride::cosim::detail
