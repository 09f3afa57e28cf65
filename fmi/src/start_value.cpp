#include "start_value.hpp"

#include <cstdio>

namespace stride::sdk {

std::string format_start_value(const variable& v, const void* data) {
  switch (v.type) {
    case value_type::real: {
      char buffer[40];
      std::snprintf(buffer, sizeof buffer, "%.17g", read_value<double>(data, v.offset));
      return buffer;
    }
    case value_type::integer:
    case value_type::enumeration:
      return std::to_string(read_value<int>(data, v.offset));
    case value_type::boolean:
      return read_value<bool>(data, v.offset) ? "true" : "false";
    case value_type::string:
      return string_at(data, v.offset);
  }
  return {};
}

}  // namespace stride::sdk
