// A value of any FMI type, and its text form (system XML, --set, CSV).
#ifndef STRIDE_COSIM_SCALAR_VALUE_HPP
#define STRIDE_COSIM_SCALAR_VALUE_HPP

#include <string>
#include <string_view>
#include <variant>

#include "stride/cosim/model_description.hpp"

namespace stride::cosim {

/// A value of any FMI type (enumerations travel as int).
using scalar_value = std::variant<double, int, bool, std::string>;

/// Parses text as a value of `type` ("1.5", "-3", "true"/"false"/"1"/"0", any string).
/// \throws std::invalid_argument with a message naming the expected type.
scalar_value parse_scalar(variable_type type, std::string_view text);
/// Text of a value, parseable again by parse_scalar (doubles in shortest round-trip form).
std::string format_scalar(const scalar_value& value);

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_SCALAR_VALUE_HPP
