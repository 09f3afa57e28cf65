// ModelVariables: each ScalarVariable's name, valueReference, type child, causality,
// variability and initial, and the rules that combine variables (one independent, aliases,
// derivative, array names) (docs/fmi-rules.md §2.2).
#include <algorithm>

#include "model_description_check.hpp"
#include "xs_values.hpp"

namespace stride::fmi_check::detail {

namespace {

using fmi2::causality;
using fmi2::initial_kind;
using fmi2::value_type;
using fmi2::variability;

bool combination_allowed(causality c, variability v) {
  switch (c) {
    case causality::parameter:
    case causality::calculated_parameter:
      return v == variability::fixed || v == variability::tunable;
    case causality::input:
      return v == variability::discrete || v == variability::continuous;
    case causality::output:
      return v != variability::fixed && v != variability::tunable;
    case causality::local:
      return true;
    case causality::independent:
      return v == variability::continuous;
  }
  return false;
}

/// The spec table of `initial`: the default and the allowed values of a legal combination.
/// An empty allowed list means `initial` must not be given.
struct initial_rule {
  std::optional<initial_kind> default_value;
  std::vector<initial_kind> allowed;
};

initial_rule initial_rule_for(causality c, variability v) {
  using enum initial_kind;
  if (c == causality::input || c == causality::independent) return {std::nullopt, {}};
  if (v == variability::constant) return {exact, {exact}};
  if (c == causality::parameter) return {exact, {exact}};
  if (c == causality::calculated_parameter ||
      (c == causality::local && (v == variability::fixed || v == variability::tunable))) {
    return {calculated, {approx, calculated}};
  }
  // output or local, discrete or continuous
  return {calculated, {exact, approx, calculated}};
}

void check_variable(md_context& md, variable& v, const XMLElement& sv) {
  check_attributes(md.out, sv,
                   {"name", "valueReference", "description", "causality", "variability", "initial",
                    "canHandleMultipleSetPerTimeInstant"});
  if (const char* name = sv.Attribute("name"); name == nullptr || std::string_view(name).empty()) {
    md.out.error("variable.name",
                 at(sv) + ": <ScalarVariable> (index " + std::to_string(v.index) + ") has no name");
  } else {
    v.name = name;
  }
  if (v.name.empty()) {
    // built piecewise: GCC 12 reports a false -Wrestrict on "#" + ... (GCC bug 105329)
    v.name.push_back('#');
    v.name += std::to_string(v.index);
  }

  const char* vr = sv.Attribute("valueReference");
  if (vr == nullptr) {
    md.out.error("variable.value_reference", describe(v) + ": no valueReference");
  } else if (!(v.vr = parse_xs_unsigned_int(vr))) {
    md.out.error("variable.value_reference",
                 describe(v) + ": valueReference " + quote(vr) + " is not an unsigned int");
  }

  // type child: exactly one of the five, Annotations aside
  int type_children = 0;
  for (const XMLElement* c = sv.FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    const std::string_view name = c->Name();
    if (name == "Annotations") continue;
    const auto type = fmi2::parse_value_type(name);
    if (!type) {
      md.out.error("variable.type", describe(v) + ": unexpected child <" + std::string(name) + ">");
      continue;
    }
    ++type_children;
    if (type_children == 1) {
      v.type = type;
      v.type_element = c;
    }
  }
  if (type_children != 1) {
    md.out.error("variable.type", describe(v) + ": has " + std::to_string(type_children) +
                                      " type elements, expected exactly one of Real, Integer, "
                                      "Boolean, String, Enumeration");
    v.type.reset();
    v.type_element = nullptr;
  }
  if (v.type_element != nullptr) check_type_element(md, v);

  const char* causality_text = sv.Attribute("causality");
  const char* variability_text = sv.Attribute("variability");
  const char* initial_text = sv.Attribute("initial");
  v.caus = causality_text != nullptr ? fmi2::parse_causality(causality_text) : causality::local;
  if (!v.caus) {
    md.out.error("variable.causality", describe(v) + ": causality " + quote(causality_text) +
                                           " is not one of parameter, calculatedParameter, input, "
                                           "output, local, independent");
  }
  v.var = variability_text != nullptr ? fmi2::parse_variability(variability_text)
                                      : variability::continuous;
  if (!v.var) {
    md.out.error("variable.variability", describe(v) + ": variability " + quote(variability_text) +
                                             " is not one of constant, fixed, tunable, discrete, "
                                             "continuous");
  }
  std::optional<initial_kind> given_initial;
  if (initial_text != nullptr) {
    given_initial = fmi2::parse_initial_kind(initial_text);
    if (!given_initial) {
      md.out.error("variable.initial", describe(v) + ": initial " + quote(initial_text) +
                                           " is not one of exact, approx, calculated");
    }
  }
  v.initial = given_initial;

  if (v.caus && v.var) {
    if (!combination_allowed(*v.caus, *v.var)) {
      md.out.error("variable.causality_variability",
                   describe(v) + ": causality " + std::string(to_string(*v.caus)) +
                       " with variability " + std::string(to_string(*v.var)) +
                       " is not allowed (parameter/calculatedParameter: fixed|tunable; input: "
                       "discrete|continuous; output: constant|discrete|continuous; independent: "
                       "continuous)");
    } else {
      const initial_rule rule = initial_rule_for(*v.caus, *v.var);
      if (initial_text != nullptr && rule.allowed.empty()) {
        md.out.error("variable.initial", describe(v) +
                                             ": initial must not be given for causality " +
                                             std::string(to_string(*v.caus)));
      } else if (given_initial && std::find(rule.allowed.begin(), rule.allowed.end(),
                                            *given_initial) == rule.allowed.end()) {
        std::string allowed;
        for (initial_kind k : rule.allowed) {
          allowed += (allowed.empty() ? "" : "|") + std::string(to_string(k));
        }
        md.out.error("variable.initial",
                     describe(v) + ": initial " + std::string(to_string(*given_initial)) +
                         " is not allowed for " + std::string(to_string(*v.caus)) + " " +
                         std::string(to_string(*v.var)) + " (allowed: " + allowed + ")");
      }
      if (initial_text == nullptr) v.initial = rule.default_value;
    }
  }

  if (v.var == variability::continuous && v.type && v.type != value_type::real) {
    md.out.error(
        "variable.continuous_non_real",
        describe(v) + ": a " + std::string(to_string(*v.type)) + " variable cannot be continuous" +
            (variability_text == nullptr ? " (continuous is the default variability)" : ""));
  }
  if (v.caus == causality::independent && v.type && v.type != value_type::real) {
    md.out.error("variable.independent", describe(v) +
                                             ": the independent variable must be a Real, not " +
                                             std::string(to_string(*v.type)));
  }

  if (v.type_element != nullptr) {
    check_start_presence(md, v, initial_text != nullptr);
    check_values(md, v);
  }
}

void check_aliases(md_context& md) {
  // keyed by the type's name, so the groups are reported in the order of that name
  std::map<std::pair<std::string_view, std::uint32_t>, std::vector<const variable*>> groups;
  for (const variable& v : md.vars) {
    if (v.vr && v.type) groups[{to_string(*v.type), *v.vr}].push_back(&v);
  }
  for (const auto& [key, members] : groups) {
    std::vector<const variable*> with_start;
    for (const variable* v : members) {
      if (v->has_start && v->var != variability::constant) with_start.push_back(v);
    }
    if (with_start.size() > 1) {
      std::string names;
      for (const variable* v : with_start) {
        names += (names.empty() ? "" : ", ") + quote(v->name);
      }
      md.out.error("variable.alias_start",
                   describe(*with_start[1]) + ": " + std::string(key.first) +
                       " aliases with valueReference " + std::to_string(key.second) +
                       " have more than one start (" + names + ")");
    }
  }
}

void check_derivative_attributes(md_context& md) {
  for (variable& v : md.vars) {
    if (v.type != value_type::real) continue;
    const char* text = v.type_element->Attribute("derivative");
    if (text == nullptr) continue;
    const auto d = parse_xs_unsigned_int(text);
    if (!d) continue;  // reported by check_values
    if (*d < 1 || *d > md.vars.size()) {
      md.out.error("variable.derivative", describe(v) + ": derivative=" + quote(text) +
                                              " is not an index in 1.." +
                                              std::to_string(md.vars.size()));
    } else if (md.vars[*d - 1].type != value_type::real) {
      md.out.error("variable.derivative", describe(v) + ": derivative=" + quote(text) + " names " +
                                              quote(md.vars[*d - 1].name) +
                                              ", which is not a Real");
    } else {
      v.derivative_of = *d;
    }
  }
}

void check_array_names(md_context& md) {
  // name[k] with a single trailing index; structured names such as a[2].b are not grouped
  std::map<std::string, std::vector<std::pair<std::uint32_t, const variable*>>> groups;
  for (const variable& v : md.vars) {
    const std::string& n = v.name;
    if (n.size() < 4 || n.back() != ']') continue;
    const auto open = n.rfind('[');
    if (open == std::string::npos || open == 0) continue;
    const std::string_view digits(n.data() + open + 1, n.size() - open - 2);
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos) {
      continue;
    }
    const auto k = parse_xs_unsigned_int(digits);
    if (!k) continue;
    groups[n.substr(0, open)].emplace_back(*k, &v);
  }
  for (auto& [base, members] : groups) {
    std::sort(members.begin(), members.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t i = 0; i < members.size(); ++i) {
      if (members[i].first != i + 1) {
        const std::string expected = std::to_string(i + 1);
        md.out.warning("variable.array_index",
                       describe(*members[i].second) + ": array " + quote(base) +
                           " should have contiguous 1-based indices; expected " + base + "[" +
                           expected + "]");
        break;
      }
    }
  }
}

}  // namespace

void check_model_variables(md_context& md, const XMLElement* mv) {
  if (mv == nullptr) {
    md.out.error("variables.empty", "there is no <ModelVariables> element");
    return;
  }
  std::map<std::string, std::size_t, std::less<>> names;
  for (const XMLElement* sv = mv->FirstChildElement(); sv != nullptr;
       sv = sv->NextSiblingElement()) {
    if (std::string_view(sv->Name()) != "ScalarVariable") {
      md.out.error("structure.child_order",
                   at(*sv) + ": unexpected element <" + sv->Name() + "> in <ModelVariables>");
      continue;
    }
    variable v;
    v.index = md.vars.size() + 1;
    v.line = sv->GetLineNum();
    check_variable(md, v, *sv);
    if (!v.name.empty()) {
      auto [it, inserted] = names.emplace(v.name, v.index);
      if (!inserted) {
        md.out.error("variable.name_unique", describe(v) + ": the name is already used by index " +
                                                 std::to_string(it->second));
      }
    }
    md.vars.push_back(std::move(v));
  }
  if (md.vars.empty()) {
    md.out.error("variables.empty", at(*mv) + ": <ModelVariables> has no <ScalarVariable>");
    return;
  }
  bool seen_independent = false;
  for (const variable& v : md.vars) {
    if (v.caus != causality::independent) continue;
    if (seen_independent) {
      md.out.error("variable.independent",
                   describe(v) + ": more than one variable has causality independent");
    }
    seen_independent = true;
  }
  check_aliases(md);
  check_derivative_attributes(md);
  check_array_names(md);
}

}  // namespace stride::fmi_check::detail
