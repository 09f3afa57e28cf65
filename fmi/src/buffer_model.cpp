#include <algorithm>
#include <cstdint>
#include <cstring>

#include "stride/sdk/model.hpp"

namespace stride::sdk {

// Each reserved value by its type: the same image on every host (the buffer's own layout,
// alignment gaps included, stays a detail of this process).
void buffer_model::save_buffer(common::byte_writer& w) const {
  for (const storage_run& run : storage_) {
    for (std::size_t i = 0; i < run.count; ++i) {
      const std::size_t at = run.offset + i * run.element_size;
      switch (run.type) {
        case value_type::real:
          w.put(value<double>(at));
          break;
        case value_type::integer:
        case value_type::enumeration:  // stored as int
          w.put(static_cast<std::int32_t>(value<int>(at)));
          break;
        case value_type::boolean:
          w.put(static_cast<std::uint8_t>(value<bool>(at) ? 1 : 0));
          break;
        case value_type::string:
          w.put_raw(std::span(data_).subspan(at, run.element_size));
          break;
      }
    }
  }
}

std::vector<std::byte> buffer_model::read_buffer(state_reader& r) const {
  std::vector<std::byte> restored = data_;
  const auto put = [&restored](std::size_t at, const auto& v) {
    std::memcpy(restored.data() + at, &v, sizeof v);
  };
  for (const storage_run& run : storage_) {
    for (std::size_t i = 0; i < run.count; ++i) {
      const std::size_t at = run.offset + i * run.element_size;
      switch (run.type) {
        case value_type::real:
          put(at, r.get<double>());
          break;
        case value_type::integer:
        case value_type::enumeration:  // stored as int
          put(at, static_cast<int>(r.get<std::int32_t>()));
          break;
        case value_type::boolean: {
          const auto b = r.get<std::uint8_t>();
          if (b > 1) r.fail();
          put(at, b == 1);
          break;
        }
        case value_type::string: {
          const auto chars = r.get_raw(run.element_size);
          std::memcpy(restored.data() + at, chars.data(), chars.size());
          break;
        }
      }
    }
  }
  return restored;
}

// copied, not moved: the glue holds the buffer's address (data())
void buffer_model::set_buffer(const std::vector<std::byte>& values) {
  std::copy(values.begin(), values.end(), data_.begin());
}

}  // namespace stride::sdk
