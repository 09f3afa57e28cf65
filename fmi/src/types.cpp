#include "stride/sdk/types.hpp"

#include <cmath>

namespace stride::sdk {

time_ns to_time_ns(double seconds) {
  return static_cast<time_ns>(std::llround(seconds * 1e9));
}

const char* to_string(value_type t) {
  switch (t) {
    case value_type::real:
      return "Real";
    case value_type::integer:
      return "Integer";
    case value_type::boolean:
      return "Boolean";
    case value_type::string:
      return "String";
  }
  return "?";
}

const char* to_string(causality c) {
  switch (c) {
    case causality::parameter:
      return "parameter";
    case causality::calculated_parameter:
      return "calculatedParameter";
    case causality::input:
      return "input";
    case causality::output:
      return "output";
    case causality::local:
      return "local";
  }
  return "?";
}

const char* to_string(variability v) {
  switch (v) {
    case variability::constant:
      return "constant";
    case variability::fixed:
      return "fixed";
    case variability::tunable:
      return "tunable";
    case variability::discrete:
      return "discrete";
    case variability::continuous:
      return "continuous";
  }
  return "?";
}

const char* to_string(initial_kind i) {
  switch (i) {
    case initial_kind::none:
      return "";
    case initial_kind::exact:
      return "exact";
    case initial_kind::approx:
      return "approx";
    case initial_kind::calculated:
      return "calculated";
  }
  return "?";
}

}  // namespace stride::sdk
