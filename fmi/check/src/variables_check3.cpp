// FMI 3.0 ModelVariables: each variable element's name, valueReference, causality, variability
// and initial, and the rules that combine variables (one independent variable, derivative)
// (docs/fmi3-rules.md §5).
#include <algorithm>

#include "model_description_check3.hpp"
#include "xs_values.hpp"

namespace stride::fmi_check::detail {

namespace {

using fmi2::initial_kind;
using fmi2::variability;

bool is_parameter(causality3 c) {
  return c == causality3::parameter || c == causality3::calculated_parameter ||
         c == causality3::structural_parameter;
}

bool combination_allowed(causality3 c, variability v) {
  if (is_parameter(c)) return v == variability::fixed || v == variability::tunable;
  switch (c) {
    case causality3::input:
      return v == variability::discrete || v == variability::continuous;
    case causality3::output:
      return v == variability::constant || v == variability::discrete ||
             v == variability::continuous;
    case causality3::independent:
      return v == variability::continuous;
    default:
      return true;  // local
  }
}

/// The default and the allowed values of initial for a legal combination (the table of
/// docs/fmi3-rules.md §5); an empty list means initial must not be given.
struct initial_rule {
  std::optional<initial_kind> default_value;
  std::vector<initial_kind> allowed;
};

initial_rule initial_rule_for(causality3 c, variability v) {
  using enum initial_kind;
  if (c == causality3::independent) return {std::nullopt, {}};
  if (c == causality3::input) return {exact, {exact}};
  if (v == variability::constant) return {exact, {exact}};
  if (c == causality3::parameter || c == causality3::structural_parameter) return {exact, {exact}};
  if (c == causality3::calculated_parameter ||
      (c == causality3::local && (v == variability::fixed || v == variability::tunable))) {
    return {calculated, {approx, calculated}};
  }
  return {calculated, {exact, approx, calculated}};  // output or local, discrete or continuous
}

const std::set<std::string_view>& attributes_of(kind3 k) {
  static const std::set<std::string_view> common = {"name",
                                                    "valueReference",
                                                    "description",
                                                    "causality",
                                                    "variability",
                                                    "initial",
                                                    "canHandleMultipleSetPerTimeInstant",
                                                    "intermediateUpdate",
                                                    "previous",
                                                    "clocks",
                                                    "declaredType"};
  auto with = [](std::initializer_list<std::string_view> more) {
    std::set<std::string_view> s = common;
    s.insert(more.begin(), more.end());
    return s;
  };
  static const std::set<std::string_view> floats =
      with({"quantity", "unit", "displayUnit", "relativeQuantity", "unbounded", "min", "max",
            "nominal", "derivative", "reinit", "start"});
  static const std::set<std::string_view> integers = with({"quantity", "min", "max", "start"});
  static const std::set<std::string_view> booleans = with({"start"});
  static const std::set<std::string_view> binaries = with({"mimeType", "maxSize"});
  static const std::set<std::string_view> clocks =
      with({"canBeDeactivated", "priority", "intervalVariability", "intervalDecimal",
            "shiftDecimal", "supportsFraction", "resolution", "intervalCounter", "shiftCounter"});
  if (is_float(k)) return floats;
  if (is_integer(k) || k == kind3::enumeration) return integers;
  if (k == kind3::boolean) return booleans;
  if (k == kind3::binary) return binaries;
  if (k == kind3::clock) return clocks;
  return common;  // String
}

void read_identity(md3_context& md, variable3& v, const XMLElement& e) {
  if (const char* name = e.Attribute("name"); name == nullptr || std::string_view(name).empty()) {
    md.out.error("fmi3.variable.name", at(e) + ": <" + e.Name() + "> (index " +
                                           std::to_string(v.index) + ") has no name");
  } else {
    v.name = name;
  }
  if (v.name.empty()) {
    v.name.push_back('#');
    v.name += std::to_string(v.index);
  }
  const char* vr = e.Attribute("valueReference");
  if (vr == nullptr) {
    md.out.error("fmi3.variable.value_reference", describe(v) + ": no valueReference");
  } else if (!(v.vr = parse_xs_unsigned_int(vr))) {
    md.out.error("fmi3.variable.value_reference",
                 describe(v) + ": valueReference " + quote(vr) + " is not an unsigned int");
  }
}

void read_kinds(md3_context& md, variable3& v, const XMLElement& e) {
  const char* causality_text = e.Attribute("causality");
  const char* variability_text = e.Attribute("variability");
  v.caus = causality_text != nullptr ? parse_causality3(causality_text) : causality3::local;
  if (!v.caus) {
    md.out.error("fmi3.variable.causality",
                 describe(v) + ": causality " + quote(causality_text) +
                     " is not one of parameter, calculatedParameter, input, output, local, "
                     "independent, structuralParameter");
  }
  if (variability_text != nullptr) {
    v.var = fmi2::parse_variability(variability_text);
    if (!v.var) {
      md.out.error("fmi3.variable.variability",
                   describe(v) + ": variability " + quote(variability_text) +
                       " is not one of constant, fixed, tunable, discrete, continuous");
    }
  } else if (v.caus && is_parameter(*v.caus)) {
    v.var = variability::fixed;
  } else if (v.kind) {
    v.var = is_float(*v.kind) ? variability::continuous : variability::discrete;
  }
  if (v.var == variability::continuous && v.kind && !is_float(*v.kind)) {
    md.out.error("fmi3.variable.continuous_non_float",
                 describe(v) + ": a " + std::string(to_string(*v.kind)) +
                     " variable cannot be continuous; only Float32 and Float64 can");
  }
}

void read_initial(md3_context& md, variable3& v, const XMLElement& e) {
  const char* initial_text = e.Attribute("initial");
  if (initial_text != nullptr) {
    v.initial = fmi2::parse_initial_kind(initial_text);
    if (!v.initial) {
      md.out.error("fmi3.variable.initial", describe(v) + ": initial " + quote(initial_text) +
                                                " is not one of exact, approx, calculated");
    }
  }
  if (!v.caus || !v.var) return;
  if (!combination_allowed(*v.caus, *v.var)) {
    md.out.error("fmi3.variable.causality_variability",
                 describe(v) + ": causality " + std::string(to_string(*v.caus)) +
                     " with variability " + std::string(to_string(*v.var)) +
                     " is not allowed (parameters: fixed|tunable; input: discrete|continuous; "
                     "output: constant|discrete|continuous; independent: continuous)");
    return;
  }
  const initial_rule rule = initial_rule_for(*v.caus, *v.var);
  if (initial_text != nullptr && rule.allowed.empty()) {
    md.out.error("fmi3.variable.initial", describe(v) +
                                              ": initial must not be given for causality " +
                                              std::string(to_string(*v.caus)));
  } else if (v.initial && std::find(rule.allowed.begin(), rule.allowed.end(), *v.initial) ==
                              rule.allowed.end()) {
    std::string allowed;
    for (initial_kind k : rule.allowed) {
      if (!allowed.empty()) allowed.push_back('|');
      allowed += to_string(k);
    }
    md.out.error("fmi3.variable.initial",
                 describe(v) + ": initial " + std::string(to_string(*v.initial)) +
                     " is not allowed for " + std::string(to_string(*v.caus)) + " " +
                     std::string(to_string(*v.var)) + " (allowed: " + allowed + ")");
  }
  if (initial_text == nullptr) v.initial = rule.default_value;
}

void check_variable(md3_context& md, variable3& v, const XMLElement& e) {
  v.element = &e;
  v.kind = parse_kind3(e.Name());
  read_identity(md, v, e);
  if (!v.kind) {
    md.out.error("fmi3.variable.type",
                 describe(v) + ": <" + e.Name() +
                     "> is not a variable type of FMI 3.0 (Float32, Float64, Int8 ... UInt64, "
                     "Boolean, String, Binary, Enumeration, Clock)");
    return;
  }
  check_attributes(md.out, e, attributes_of(*v.kind), "3.0");
  read_kinds(md, v, e);
  read_initial(md, v, e);
  v.has_start = e.Attribute("start") != nullptr || e.FirstChildElement("Start") != nullptr;
  if (v.caus == causality3::independent && !is_float(*v.kind)) {
    md.out.error("fmi3.variable.independent",
                 describe(v) + ": the independent variable must be a Float32 or Float64, not " +
                     std::string(to_string(*v.kind)));
  }
  check_start_presence3(md, v, e.Attribute("initial") != nullptr);
  check_values3(md, v);
}

void check_derivatives(md3_context& md) {
  for (variable3& v : md.vars) {
    if (!v.kind || !is_float(*v.kind)) continue;
    const char* text = v.element->Attribute("derivative");
    if (text == nullptr) continue;
    const auto d = parse_xs_unsigned_int(text);
    const variable3* state = d ? md.find(*d) : nullptr;
    if (state == nullptr) {
      md.out.error("fmi3.variable.derivative", describe(v) + ": derivative=" + quote(text) +
                                                   " is not the valueReference of a variable");
    } else if (!state->kind || !is_float(*state->kind)) {
      md.out.error("fmi3.variable.derivative", describe(v) + ": derivative=" + quote(text) +
                                                   " names " + quote(state->name) +
                                                   ", which is not a float variable");
    } else {
      v.derivative_of = *d;
    }
  }
}

}  // namespace

void check_model_variables3(md3_context& md, const XMLElement* mv) {
  if (mv == nullptr) {
    md.out.error("fmi3.variables.empty", "there is no <ModelVariables> element");
    return;
  }
  std::map<std::string, std::size_t, std::less<>> names;
  for (const XMLElement* e = mv->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
    variable3 v;
    v.index = md.vars.size() + 1;
    v.line = e->GetLineNum();
    check_variable(md, v, *e);
    if (const auto [it, inserted] = names.emplace(v.name, v.index); !inserted) {
      md.out.error(
          "fmi3.variable.name_unique",
          describe(v) + ": the name is already used by index " + std::to_string(it->second));
    }
    if (v.vr) {
      if (const variable3* other = md.find(*v.vr)) {
        md.out.error("fmi3.variable.value_reference_unique",
                     describe(v) + ": valueReference " + std::to_string(*v.vr) +
                         " is already used by " + quote(other->name) +
                         " (FMI 3.0 has no aliases by valueReference)");
      } else {
        md.by_vr.emplace(*v.vr, md.vars.size());
      }
    }
    md.vars.push_back(std::move(v));
  }
  if (md.vars.empty()) {
    md.out.error("fmi3.variables.empty", at(*mv) + ": <ModelVariables> has no variable");
    return;
  }
  const auto independent = std::count_if(md.vars.begin(), md.vars.end(), [](const variable3& v) {
    return v.caus == causality3::independent;
  });
  if (independent != 1) {
    md.out.error("fmi3.variable.independent",
                 at(*mv) + ": " + std::to_string(independent) +
                     " variables have causality independent; FMI 3.0 requires exactly one");
  }
  check_derivatives(md);
  for (const variable3& v : md.vars) check_dimensions3(md, v);
}

}  // namespace stride::fmi_check::detail
