// Parsers for the XML Schema value types used by the FMI 2.0 and 3.0 model description schemas.
#ifndef STRIDE_FMI_CHECK_XS_VALUES_HPP
#define STRIDE_FMI_CHECK_XS_VALUES_HPP

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stride::fmi_check::detail {

/// Strips XML whitespace (space, tab, CR, LF) from both ends.
std::string_view trim(std::string_view s);

/// Splits on XML whitespace, dropping empty pieces.
std::vector<std::string_view> split_ws(std::string_view s);

/// xs:boolean: "true", "false", "1", "0" (surrounding whitespace allowed).
std::optional<bool> parse_xs_boolean(std::string_view s);

/// xs:unsignedInt: optional '+', decimal digits, at most 4294967295.
std::optional<std::uint32_t> parse_xs_unsigned_int(std::string_view s);

/// xs:int: optional sign, decimal digits, 32-bit range.
std::optional<std::int32_t> parse_xs_int(std::string_view s);

/// xs:long: optional sign, decimal digits, 64-bit range.
std::optional<std::int64_t> parse_xs_long(std::string_view s);

/// xs:unsignedLong: optional '+', decimal digits, at most 18446744073709551615.
std::optional<std::uint64_t> parse_xs_unsigned_long(std::string_view s);

/// xs:hexBinary: an even number of hex digits (surrounding whitespace allowed).
bool is_xs_hex_binary(std::string_view s);

/// xs:double: decimal or exponent notation, "INF", "-INF", "+INF", "NaN".
std::optional<double> parse_xs_double(std::string_view s);

/// xs:dateTime: [-]YYYY-MM-DDThh:mm:ss[.fff][Z|(+|-)hh:mm], with range checks of every field.
bool is_xs_date_time(std::string_view s);

/// [A-Za-z_][A-Za-z0-9_]*
bool is_c_identifier(std::string_view s);

/// Quotes a value for a message: "name".
std::string quote(std::string_view s);

}  // namespace stride::fmi_check::detail

#endif  // STRIDE_FMI_CHECK_XS_VALUES_HPP
