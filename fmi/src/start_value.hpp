// Reading and formatting a variable's value from a data struct at the variable's offset.
#pragma once

#include <cstring>
#include <string>

#include "stride/sdk/variable_table.hpp"

namespace stride::sdk {

template <class T>
T read_value(const void* data, std::size_t offset) {
  T value;
  std::memcpy(&value, static_cast<const char*>(data) + offset, sizeof(T));
  return value;
}

inline const char* string_at(const void* data, std::size_t offset) {
  return static_cast<const char*>(data) + offset;
}

/// The value of `v` in `data`, formatted as modelDescription.xml writes start values.
std::string format_start_value(const variable& v, const void* data);

}  // namespace stride::sdk
