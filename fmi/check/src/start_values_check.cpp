// Start values and ranges: when start is required or forbidden, and whether start, min, max
// and nominal parse as the variable's type and fit together (docs/fmi-rules.md §2.2).
#include <cmath>

#include "model_description_check.hpp"
#include "xs_values.hpp"

namespace stride::fmi_check::detail {

void check_start_presence(md_context& md, const variable& v, bool initial_given) {
  using fmi2::causality;
  using fmi2::initial_kind;
  using fmi2::variability;
  const bool required = v.initial == initial_kind::exact || v.initial == initial_kind::approx ||
                        v.caus == causality::input || v.var == variability::constant;
  const bool forbidden = v.initial == initial_kind::calculated || v.caus == causality::independent;
  if (required && !v.has_start) {
    std::string why;
    if (v.caus == causality::input) {
      why = "an input";
    } else if (v.var == variability::constant) {
      why = "a constant";
    } else {
      why = "initial=" + std::string(to_string(*v.initial)) +
            (!initial_given ? " (the default for " + std::string(to_string(*v.caus)) + " " +
                                  std::string(to_string(*v.var)) + ")"
                            : "");
    }
    md.out.error("variable.start_required", describe(v) + ": start is required for " + why);
  } else if (forbidden && v.has_start) {
    std::string why =
        v.caus == causality::independent
            ? std::string("causality independent")
            : "initial=calculated" + (!initial_given ? std::string(" (the default)") : "");
    md.out.error("variable.start_forbidden", describe(v) + ": start must not be given with " + why);
  }
}

void check_values(md_context& md, const variable& v) {
  const XMLElement& t = *v.type_element;
  const XMLElement* declared = nullptr;
  if (const char* dt = t.Attribute("declaredType")) {
    const auto it = md.simple_types.find(std::string_view(dt));
    if (it != md.simple_types.end() && it->second.type == fmi2::to_string(*v.type))
      declared = it->second.element;
  }
  // min/max fall back to the declared type, as the spec inherits them
  auto attribute = [&](const char* name, bool inherit) -> const char* {
    const char* text = t.Attribute(name);
    if (text == nullptr && inherit && declared != nullptr) text = declared->Attribute(name);
    return text;
  };
  auto bad_value = [&](const char* name, const char* text, std::string_view expected) {
    md.out.error("variable.value", describe(v) + ": " + name + "=" + quote(text) + " is not " +
                                       std::string(expected));
  };

  using enum fmi2::value_type;
  if (v.type == real) {
    std::map<std::string, double> values;
    for (const char* name : {"start", "min", "max", "nominal"}) {
      const char* text = attribute(name, std::string_view(name) != "start");
      if (text == nullptr) continue;
      const auto d = parse_xs_double(text);
      if (!d) {
        bad_value(name, text, "an xs:double");
      } else {
        values[name] = *d;
      }
    }
    for (const char* name : {"unbounded", "relativeQuantity", "reinit"}) {
      if (const char* text = t.Attribute(name); text != nullptr && !parse_xs_boolean(text))
        bad_value(name, text, "an xs:boolean");
    }
    if (values.contains("nominal") && !(values["nominal"] > 0.0)) {
      md.out.error("variable.value", describe(v) + ": nominal must be positive");
    }
    const bool has_min = values.contains("min");
    const bool has_max = values.contains("max");
    if (has_min && has_max && values["min"] > values["max"]) {
      md.out.error("variable.range", describe(v) + ": min " + std::to_string(values["min"]) +
                                         " > max " + std::to_string(values["max"]));
    }
    if (values.contains("start")) {
      const double s = values["start"];
      if (std::isnan(s)) {
        md.out.error("variable.value", describe(v) + ": start is NaN");
      } else if ((has_min && s < values["min"]) || (has_max && s > values["max"])) {
        md.out.error("variable.range",
                     describe(v) + ": start " + std::to_string(s) + " is outside [min, max]");
      }
    }
  } else if (v.type == integer || v.type == enumeration) {
    std::map<std::string, std::int32_t> values;
    for (const char* name : {"start", "min", "max"}) {
      const char* text = attribute(name, std::string_view(name) != "start");
      if (text == nullptr) continue;
      const auto i = parse_xs_int(text);
      if (!i) {
        bad_value(name, text, "an xs:int");
      } else {
        values[name] = *i;
      }
    }
    const bool has_min = values.contains("min");
    const bool has_max = values.contains("max");
    if (has_min && has_max && values["min"] > values["max"]) {
      md.out.error("variable.range", describe(v) + ": min " + std::to_string(values["min"]) +
                                         " > max " + std::to_string(values["max"]));
    }
    if (values.contains("start")) {
      const std::int32_t s = values["start"];
      if ((has_min && s < values["min"]) || (has_max && s > values["max"])) {
        md.out.error("variable.range",
                     describe(v) + ": start " + std::to_string(s) + " is outside [min, max]");
      }
    }
  } else if (v.type == boolean) {
    if (const char* text = t.Attribute("start"); text != nullptr && !parse_xs_boolean(text))
      bad_value("start", text, "an xs:boolean (true|false)");
  }
  if (v.type == real) {
    if (const char* text = t.Attribute("derivative")) {
      const auto d = parse_xs_unsigned_int(text);
      if (!d) bad_value("derivative", text, "an unsigned index");
    }
  }
}

}  // namespace stride::fmi_check::detail
