// The FMI 2.0 vocabulary shared by the component SDK, libstride and the FMU checker: the
// attribute values of a ScalarVariable and the fmi2Status names, each with its FMI spelling.
// Header-only, so every user of stride::fmi_api gets it without linking anything.
#ifndef STRIDE_FMI2_VOCABULARY_HPP
#define STRIDE_FMI2_VOCABULARY_HPP

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace stride::fmi2 {

// One byte each, as the SDK keeps them in every entry of its variable table.

/// Base type of a variable (the type child of <ScalarVariable>).
enum class value_type : std::uint8_t { real, integer, boolean, string, enumeration };
/// The causality attribute.
enum class causality : std::uint8_t {
  parameter,
  calculated_parameter,
  input,
  output,
  local,
  independent
};
/// The variability attribute.
enum class variability : std::uint8_t { constant, fixed, tunable, discrete, continuous };
/// The initial attribute; `none` stands for its absence and has no spelling.
enum class initial_kind : std::uint8_t { none, exact, approx, calculated };
/// fmi2Status, with the values the C API gives its enumerators.
enum class status : int { ok, warning, discard, error, fatal, pending };

inline constexpr value_type all_value_types[] = {value_type::real, value_type::integer,
                                                 value_type::boolean, value_type::string,
                                                 value_type::enumeration};
inline constexpr causality all_causalities[] = {
    causality::parameter, causality::calculated_parameter, causality::input, causality::output,
    causality::local,     causality::independent};
inline constexpr variability all_variabilities[] = {variability::constant, variability::fixed,
                                                    variability::tunable, variability::discrete,
                                                    variability::continuous};
inline constexpr initial_kind all_initial_kinds[] = {
    initial_kind::none, initial_kind::exact, initial_kind::approx, initial_kind::calculated};

// The spellings are string literals, so data() of every result is NUL-terminated.

/// "Real", "Integer", "Boolean", "String", "Enumeration".
constexpr std::string_view to_string(value_type t) noexcept {
  switch (t) {
    case value_type::real:
      return "Real";
    case value_type::integer:
      return "Integer";
    case value_type::boolean:
      return "Boolean";
    case value_type::string:
      return "String";
    case value_type::enumeration:
      return "Enumeration";
  }
  return "?";
}

/// "parameter", "calculatedParameter", "input", "output", "local", "independent".
constexpr std::string_view to_string(causality c) noexcept {
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
    case causality::independent:
      return "independent";
  }
  return "?";
}

/// "constant", "fixed", "tunable", "discrete", "continuous".
constexpr std::string_view to_string(variability v) noexcept {
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

/// "exact", "approx", "calculated"; "" for none.
constexpr std::string_view to_string(initial_kind i) noexcept {
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

/// "fmi2OK", "fmi2Warning", ...; "unknown status" for a value outside the enumeration, which
/// a foreign FMU can return.
constexpr std::string_view to_string(status s) noexcept {
  switch (s) {
    case status::ok:
      return "fmi2OK";
    case status::warning:
      return "fmi2Warning";
    case status::discard:
      return "fmi2Discard";
    case status::error:
      return "fmi2Error";
    case status::fatal:
      return "fmi2Fatal";
    case status::pending:
      return "fmi2Pending";
  }
  return "unknown status";
}

namespace detail {
template <class Enum, std::size_t N>
constexpr std::optional<Enum> parse(std::string_view text, const Enum (&all)[N]) noexcept {
  for (Enum e : all) {
    if (to_string(e) == text) return e;
  }
  return std::nullopt;
}
}  // namespace detail

// Parsing the FMI spelling; nullopt for anything else (case matters, no whitespace trimmed).

constexpr std::optional<value_type> parse_value_type(std::string_view text) noexcept {
  return detail::parse(text, all_value_types);
}
constexpr std::optional<causality> parse_causality(std::string_view text) noexcept {
  return detail::parse(text, all_causalities);
}
constexpr std::optional<variability> parse_variability(std::string_view text) noexcept {
  return detail::parse(text, all_variabilities);
}
/// Only "exact", "approx" and "calculated": an empty attribute is not `none`.
constexpr std::optional<initial_kind> parse_initial_kind(std::string_view text) noexcept {
  if (text.empty()) return std::nullopt;
  return detail::parse(text, all_initial_kinds);
}

}  // namespace stride::fmi2

#endif  // STRIDE_FMI2_VOCABULARY_HPP
