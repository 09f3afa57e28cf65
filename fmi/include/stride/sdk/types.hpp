// Basic vocabulary of the component SDK: FMI variable attributes (the shared stride::fmi2 ones),
// simulation time and the fixed-capacity string used to keep String variables inside a
// trivially copyable data struct.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

#include "stride/fmi2/vocabulary.hpp"

namespace stride::sdk {

/// Simulation time in integer nanoseconds: no drift from accumulated doubles.
using time_ns = std::int64_t;
inline constexpr time_ns ns_per_second = 1'000'000'000;

/// Converts seconds (as FMI passes them) to integer nanoseconds, rounding to nearest.
time_ns to_time_ns(double seconds);
inline double to_seconds(time_ns t) {
  return static_cast<double>(t) / 1e9;
}

// The SDK never declares Enumeration or independent variables.
using fmi2::causality;
using fmi2::initial_kind;
using fmi2::to_string;
using fmi2::value_type;
using fmi2::variability;

/// A string with fixed capacity, so that String variables can live in a trivially copyable
/// struct (FMU state = struct copy). Setting a longer value is an error, never a truncation.
template <std::size_t Capacity>
struct fixed_string {
  char text[Capacity + 1] = {};

  static constexpr std::size_t capacity() { return Capacity; }
  std::string_view view() const { return std::string_view(text); }
  const char* c_str() const { return text; }
  bool empty() const { return text[0] == '\0'; }

  /// Throws std::length_error when `value` does not fit.
  void assign(std::string_view value) {
    if (value.size() > Capacity) {
      throw std::length_error("string of " + std::to_string(value.size()) +
                              " characters exceeds the capacity of " + std::to_string(Capacity));
    }
    std::memcpy(text, value.data(), value.size());
    text[value.size()] = '\0';
  }

  /// Its state image (stride/sdk/state_fields.hpp): the characters as they are.
  template <class F>
  friend void state_fields(fixed_string& s, F&& f) {
    f(s.text);
  }
};

/// Default capacity for paths and other free text in component data.
using text = fixed_string<1023>;

}  // namespace stride::sdk
