// FMI 3.0 start values, ranges, units, declared types and array dimensions: when start is
// required or forbidden, whether every value parses as the variable's type and lies in
// [min, max], and whether an array has one start value per element (docs/fmi3-rules.md §5).
#include <cmath>
#include <limits>

#include "model_description_check3.hpp"
#include "xs_values.hpp"

namespace stride::fmi_check::detail {

namespace {

using fmi2::initial_kind;

/// The start values of `v` as written: the list of the start attribute, or the value of each
/// <Start> child (String and Binary).
std::vector<std::string> start_values(const variable3& v) {
  std::vector<std::string> values;
  if (const char* start = v.element->Attribute("start")) {
    for (std::string_view part : split_ws(start)) values.emplace_back(part);
  }
  for (const XMLElement* s = v.element->FirstChildElement("Start"); s != nullptr;
       s = s->NextSiblingElement("Start")) {
    const char* value = s->Attribute("value");
    values.emplace_back(value != nullptr ? value : "");
  }
  return values;
}

/// The attribute of the variable, else of its declared type for min, max, nominal and unit,
/// which the variable inherits.
const char* attribute(const md3_context& md, const variable3& v, const char* name) {
  if (const char* text = v.element->Attribute(name)) return text;
  if (std::string_view(name) == "start") return nullptr;
  const char* declared = v.element->Attribute("declaredType");
  if (declared == nullptr) return nullptr;
  const auto it = md.types.find(std::string_view(declared));
  return it != md.types.end() ? it->second->Attribute(name) : nullptr;
}

void bad_value(md3_context& md, const variable3& v, std::string_view name, std::string_view text,
               std::string_view expected) {
  md.out.error("fmi3.variable.value", describe(v) + ": " + std::string(name) + "=" + quote(text) +
                                          " is not " + std::string(expected));
}

/// min, max and every start value parsed by `parse` as T in [lo, hi], then min <= start <= max.
template <class T, class Parse>
void check_range(md3_context& md, const variable3& v, T lo, T hi, Parse parse) {
  const std::string type(to_string(*v.kind));
  const std::string expected = is_float(*v.kind) ? "a " + type + " number"
                                                 : "a " + type + " in [" + std::to_string(lo) +
                                                       ", " + std::to_string(hi) + "]";
  auto read = [&](std::string_view name, std::string_view text) -> std::optional<T> {
    const auto value = parse(text);
    if (!value || *value < lo || *value > hi) {
      bad_value(md, v, name, text, expected);
      return std::nullopt;
    }
    return static_cast<T>(*value);
  };
  std::optional<T> min;
  std::optional<T> max;
  if (const char* text = attribute(md, v, "min")) min = read("min", text);
  if (const char* text = attribute(md, v, "max")) max = read("max", text);
  if (min && max && *min > *max) {
    md.out.error("fmi3.variable.range",
                 describe(v) + ": min " + std::to_string(*min) + " > max " + std::to_string(*max));
  }
  for (const std::string& text : start_values(v)) {
    const auto s = read("start", text);
    if (s && ((min && *s < *min) || (max && *s > *max))) {
      md.out.error("fmi3.variable.range",
                   describe(v) + ": start " + text + " is outside [min, max]");
      return;
    }
  }
}

void check_float_values(md3_context& md, const variable3& v) {
  const double limit = v.kind == kind3::float32 ? double{std::numeric_limits<float>::max()}
                                                : std::numeric_limits<double>::max();
  auto parse = [&](std::string_view text) -> std::optional<double> {
    const auto d = parse_xs_double(text);
    // NaN is no value to start from; infinities bound ranges (unbounded min/max)
    if (!d || std::isnan(*d) || (std::isfinite(*d) && std::fabs(*d) > limit)) return std::nullopt;
    return d;
  };
  constexpr double inf = std::numeric_limits<double>::infinity();
  check_range<double>(md, v, -inf, inf, parse);
  if (const char* nominal = attribute(md, v, "nominal")) {
    const auto n = parse(nominal);
    if (!n || !(*n > 0.0)) bad_value(md, v, "nominal", nominal, "a positive number");
  }
  for (const char* name : {"relativeQuantity", "unbounded", "reinit"}) {
    if (const char* text = v.element->Attribute(name); text != nullptr && !parse_xs_boolean(text))
      bad_value(md, v, name, text, "an xs:boolean");
  }
}

void check_integer_values(md3_context& md, const variable3& v) {
  switch (*v.kind) {
    case kind3::int8:
      return check_range<std::int64_t>(md, v, INT8_MIN, INT8_MAX, parse_xs_long);
    case kind3::int16:
      return check_range<std::int64_t>(md, v, INT16_MIN, INT16_MAX, parse_xs_long);
    case kind3::int32:
    case kind3::enumeration:  // read through fmi3GetInt64, but its items are xs:int
      return check_range<std::int64_t>(md, v, INT32_MIN, INT32_MAX, parse_xs_long);
    case kind3::int64:
      return check_range<std::int64_t>(md, v, INT64_MIN, INT64_MAX, parse_xs_long);
    case kind3::uint8:
      return check_range<std::uint64_t>(md, v, 0, UINT8_MAX, parse_xs_unsigned_long);
    case kind3::uint16:
      return check_range<std::uint64_t>(md, v, 0, UINT16_MAX, parse_xs_unsigned_long);
    case kind3::uint32:
      return check_range<std::uint64_t>(md, v, 0, UINT32_MAX, parse_xs_unsigned_long);
    case kind3::uint64:
      return check_range<std::uint64_t>(md, v, 0, UINT64_MAX, parse_xs_unsigned_long);
    default:
      return;
  }
}

/// String and Binary take <Start value=".."/> children, every other type the start attribute.
void check_start_syntax(md3_context& md, const variable3& v) {
  const bool children = v.kind == kind3::string || v.kind == kind3::binary;
  const XMLElement* first = v.element->FirstChildElement("Start");
  if (!children && first != nullptr) {
    md.out.error("fmi3.variable.start_syntax",
                 describe(v) + ": a " + std::string(to_string(*v.kind)) +
                     " gives its start in the start attribute, not in <Start> children");
  }
  if (!children) return;
  for (const XMLElement* s = first; s != nullptr; s = s->NextSiblingElement("Start")) {
    const char* value = s->Attribute("value");
    if (value == nullptr) {
      md.out.error("fmi3.variable.start_syntax", describe(v) + ": <Start> without a value");
    } else if (v.kind == kind3::binary && !is_xs_hex_binary(value)) {
      md.out.error("fmi3.variable.start_syntax", describe(v) + ": Binary start " + quote(value) +
                                                     " is not hex (an even number of hex digits)");
    }
  }
}

void check_declared_type(md3_context& md, const variable3& v) {
  const char* declared = v.element->Attribute("declaredType");
  if (declared == nullptr) {
    if (v.kind == kind3::enumeration) {
      md.out.error("fmi3.variable.declared_type",
                   describe(v) + ": an Enumeration needs a declaredType");
    }
    return;
  }
  const auto it = md.types.find(std::string_view(declared));
  const std::string expected = std::string(to_string(*v.kind)) + "Type";
  if (it == md.types.end()) {
    md.out.error("fmi3.variable.declared_type", describe(v) + ": declaredType " + quote(declared) +
                                                    " is not defined in <TypeDefinitions>");
  } else if (it->second->Name() != expected) {
    md.out.error("fmi3.variable.declared_type", describe(v) + ": declaredType " + quote(declared) +
                                                    " is a <" + it->second->Name() + ">, a " +
                                                    std::string(to_string(*v.kind)) + " needs a <" +
                                                    expected + ">");
  }
}

void check_unit(md3_context& md, const variable3& v) {
  const char* unit = attribute(md, v, "unit");
  const char* display = attribute(md, v, "displayUnit");
  if (unit == nullptr) {
    if (display != nullptr) {
      md.out.error("fmi3.variable.unit",
                   describe(v) + ": displayUnit " + quote(display) + " without a unit");
    }
    return;
  }
  const auto it = md.units.find(std::string_view(unit));
  if (it == md.units.end()) {
    md.out.error("fmi3.variable.unit",
                 describe(v) + ": unit " + quote(unit) + " is not declared in <UnitDefinitions>");
  } else if (display != nullptr && !it->second.contains(std::string_view(display))) {
    md.out.error("fmi3.variable.unit", describe(v) + ": displayUnit " + quote(display) +
                                           " is not a <DisplayUnit> of " + quote(unit));
  }
}

}  // namespace

void check_start_presence3(md3_context& md, const variable3& v, bool initial_given) {
  if (v.kind == kind3::clock) return;  // a clock has no start value
  const bool required = v.initial == initial_kind::exact || v.initial == initial_kind::approx ||
                        v.caus == causality3::input || v.var == fmi2::variability::constant;
  const bool forbidden = v.initial == initial_kind::calculated || v.caus == causality3::independent;
  if (required && !v.has_start) {
    std::string why = v.caus == causality3::input ? std::string("an input")
                      : v.var == fmi2::variability::constant
                          ? std::string("a constant")
                          : "initial=" + std::string(to_string(*v.initial)) +
                                (initial_given ? "" : " (the default)");
    md.out.error("fmi3.variable.start_required", describe(v) + ": start is required for " + why);
  } else if (forbidden && v.has_start) {
    const std::string why =
        v.caus == causality3::independent
            ? std::string("causality independent")
            : "initial=calculated" + std::string(initial_given ? "" : " (the default)");
    md.out.error("fmi3.variable.start_forbidden",
                 describe(v) + ": start must not be given with " + why);
  }
}

void check_values3(md3_context& md, const variable3& v) {
  check_declared_type(md, v);
  check_start_syntax(md, v);
  if (is_float(*v.kind)) {
    check_float_values(md, v);
    check_unit(md, v);
  } else if (is_integer(*v.kind) || v.kind == kind3::enumeration) {
    check_integer_values(md, v);
  } else if (v.kind == kind3::boolean) {
    for (const std::string& text : start_values(v)) {
      if (!parse_xs_boolean(text)) bad_value(md, v, "start", text, "an xs:boolean (true|false)");
    }
  }
}

void check_dimensions3(md3_context& md, const variable3& v) {
  if (!v.kind) return;
  // the number of elements, while every dimension's size is known
  std::optional<std::uint64_t> elements = 1;
  for (const XMLElement* d = v.element->FirstChildElement("Dimension"); d != nullptr;
       d = d->NextSiblingElement("Dimension")) {
    const char* start = d->Attribute("start");
    const char* vr = d->Attribute("valueReference");
    if (v.kind == kind3::clock || (start == nullptr) == (vr == nullptr)) {
      md.out.error("fmi3.dimension.attribute",
                   at(*d) + ": a <Dimension> of " + quote(v.name) +
                       (v.kind == kind3::clock ? " (a Clock cannot be an array)"
                                               : " needs exactly one of start and valueReference"));
      elements.reset();
      continue;
    }
    std::optional<std::uint64_t> size;
    if (start != nullptr) {
      size = parse_xs_unsigned_long(start);
      if (!size || *size == 0) {
        md.out.error("fmi3.dimension.start", at(*d) + ": <Dimension start=" + quote(start) +
                                                 "> of " + quote(v.name) +
                                                 " is not a positive integer");
        size.reset();
      }
    } else {
      const auto ref = parse_xs_unsigned_int(vr);
      const variable3* sized_by = ref ? md.find(*ref) : nullptr;
      if (sized_by == nullptr || sized_by->kind != kind3::uint64 ||
          (sized_by->caus != causality3::structural_parameter &&
           sized_by->var != fmi2::variability::constant)) {
        md.out.error("fmi3.dimension.reference",
                     at(*d) + ": <Dimension valueReference=" + quote(vr) + "> of " + quote(v.name) +
                         " must name a UInt64 variable that is a structuralParameter or a "
                         "constant");
      } else if (const char* n = sized_by->element->Attribute("start")) {
        size = parse_xs_unsigned_long(n);  // the size before any reconfiguration
      }
    }
    if (elements && size) {
      elements = *elements * *size;
    } else {
      elements.reset();
    }
  }
  const auto values = start_values(v);
  if (elements && !values.empty() && values.size() != *elements) {
    md.out.error("fmi3.variable.start_count", describe(v) + ": " + std::to_string(values.size()) +
                                                  " start values for " + std::to_string(*elements) +
                                                  (*elements == 1 ? " element" : " elements"));
  }
}

}  // namespace stride::fmi_check::detail
