// ModelStructure: Outputs, Derivatives and InitialUnknowns list the right variables, in order,
// with well-formed dependencies (docs/fmi-rules.md §2.2).
#include <algorithm>

#include "model_description_check.hpp"
#include "xs_values.hpp"

namespace stride::fmi_check::detail {

namespace {

using fmi2::causality;
using fmi2::initial_kind;

void check_dependencies(md_context& md, const XMLElement& unknown, std::string_view where,
                        bool initial_unknowns) {
  const char* deps_text = unknown.Attribute("dependencies");
  const char* kinds_text = unknown.Attribute("dependenciesKind");
  const std::string prefix(where);
  std::size_t dependency_count = 0;
  if (deps_text != nullptr) {
    const auto parts = split_ws(deps_text);
    dependency_count = parts.size();
    std::uint64_t previous = 0;
    for (std::string_view p : parts) {
      const auto d = parse_xs_unsigned_int(p);
      if (!d || *d == 0 || *d > md.vars.size()) {
        md.out.error("dependencies.index", prefix + " dependency " + quote(p) +
                                               " is not an index in 1.." +
                                               std::to_string(md.vars.size()));
        continue;
      }
      if (*d <= previous) {
        md.out.error("dependencies.order", prefix + " dependencies " + quote(deps_text) +
                                               " are not sorted ascending without duplicates");
        break;
      }
      previous = *d;
    }
  }
  if (kinds_text == nullptr) return;
  const auto kinds = split_ws(kinds_text);
  if (deps_text == nullptr) {
    md.out.error("dependencies.kind", prefix + " has dependenciesKind without dependencies");
  } else if (kinds.size() != dependency_count) {
    md.out.error("dependencies.kind", prefix + " has " + std::to_string(dependency_count) +
                                          " dependencies but " + std::to_string(kinds.size()) +
                                          " dependenciesKind entries");
  }
  for (std::string_view k : kinds) {
    if (initial_unknowns) {
      if (k != "dependent" && k != "constant") {
        md.out.error("initial_unknowns.kind", prefix + " dependenciesKind " + quote(k) +
                                                  " is not allowed in InitialUnknowns "
                                                  "(dependent|constant)");
      }
    } else if (k != "dependent" && k != "constant" && k != "fixed" && k != "tunable" &&
               k != "discrete") {
      md.out.error("dependencies.kind",
                   prefix + " dependenciesKind " + quote(k) +
                       " is not one of dependent, constant, fixed, tunable, discrete");
    }
  }
}

std::vector<std::size_t> check_unknowns(md_context& md, const XMLElement& list,
                                        std::string_view rule_prefix, bool initial_unknowns) {
  const std::string index_rule = std::string(rule_prefix) + ".index";
  std::vector<std::size_t> indices;
  for (const XMLElement* u = list.FirstChildElement(); u != nullptr; u = u->NextSiblingElement()) {
    if (std::string_view(u->Name()) != "Unknown") {
      md.out.error("structure.child_order",
                   at(*u) + ": unexpected element <" + u->Name() + "> in <" + list.Name() + ">");
      continue;
    }
    check_attributes(md.out, *u, {"index", "dependencies", "dependenciesKind"});
    const std::string where = at(*u) + ": <" + list.Name() + "><Unknown>";
    const char* text = u->Attribute("index");
    if (text == nullptr) {
      md.out.error(index_rule, where + " has no index");
      continue;
    }
    const auto index = parse_xs_unsigned_int(text);
    if (!index) {
      md.out.error(index_rule, where + " index " + quote(text) + " is not an unsigned integer");
      continue;
    }
    if (*index == 0) {
      md.out.error(index_rule, where +
                                   " index 0 is invalid: indices are 1-based positions in "
                                   "<ModelVariables>");
      continue;
    }
    if (*index > md.vars.size()) {
      std::string hint;
      for (const variable& v : md.vars) {
        if (v.vr == *index) {
          hint = " (is it the valueReference of " + quote(v.name) +
                 "? indices are positions in <ModelVariables>, not valueReferences)";
          break;
        }
      }
      md.out.error(index_rule, where + " index " + std::to_string(*index) + " is out of range 1.." +
                                   std::to_string(md.vars.size()) + hint);
      continue;
    }
    check_dependencies(md, *u, where, initial_unknowns);
    indices.push_back(*index);
  }
  return indices;
}

}  // namespace

void check_model_structure(md_context& md, const XMLElement* ms) {
  if (ms == nullptr) {
    md.out.error("structure.model_structure", "there is no <ModelStructure> element");
    return;
  }
  check_child_order(md.out, *ms, {"Outputs", "Derivatives", "InitialUnknowns"});
  if (md.vars.empty()) return;

  // Outputs: exactly the output variables, in ModelVariables order
  std::vector<std::size_t> outputs;
  if (const XMLElement* o = ms->FirstChildElement("Outputs")) {
    outputs = check_unknowns(md, *o, "outputs", false);
    std::set<std::size_t> seen;
    std::size_t previous = 0;
    for (std::size_t index : outputs) {
      const variable& v = md.vars[index - 1];
      if (v.caus != causality::output) {
        md.out.error("outputs.not_output",
                     describe(v) + ": listed in <Outputs> but its causality is " +
                         (v.caus ? std::string(fmi2::to_string(*v.caus)) : std::string("invalid")));
      }
      if (!seen.insert(index).second) {
        md.out.error("outputs.order", describe(v) + ": listed twice in <Outputs>");
      } else if (index < previous) {
        md.out.error("outputs.order", describe(v) + ": <Outputs> is not in ModelVariables order");
      }
      previous = std::max(previous, index);
    }
  }
  const std::set<std::size_t> listed_outputs(outputs.begin(), outputs.end());
  for (const variable& v : md.vars) {
    if (v.caus == causality::output && !listed_outputs.contains(v.index)) {
      md.out.error("outputs.missing", describe(v) +
                                          ": an output missing from "
                                          "<ModelStructure><Outputs>");
    }
  }

  // Derivatives: Real variables with a derivative attribute
  const XMLElement* derivatives_element = ms->FirstChildElement("Derivatives");
  std::vector<std::size_t> derivatives;
  if (derivatives_element != nullptr) {
    derivatives = check_unknowns(md, *derivatives_element, "derivatives", false);
    for (std::size_t index : derivatives) {
      const variable& v = md.vars[index - 1];
      if (!v.derivative_of) {
        md.out.error("derivatives.index",
                     describe(v) +
                         ": listed in <Derivatives> but is not a Real with a derivative "
                         "attribute (list the derivative, not the state)");
      }
    }
  }

  // InitialUnknowns: exactly the required set, sorted, no duplicates
  std::set<std::size_t> required;
  auto approx_or_calculated = [](const variable& v) {
    return v.initial == initial_kind::approx || v.initial == initial_kind::calculated;
  };
  for (const variable& v : md.vars) {
    if (v.caus == causality::output && approx_or_calculated(v)) required.insert(v.index);
    if (v.caus == causality::calculated_parameter) required.insert(v.index);
  }
  for (std::size_t index : derivatives) {
    const variable& d = md.vars[index - 1];
    if (approx_or_calculated(d)) required.insert(index);
    if (d.derivative_of && approx_or_calculated(md.vars[*d.derivative_of - 1])) {
      required.insert(*d.derivative_of);
    }
  }
  std::vector<std::size_t> initial_unknowns;
  const XMLElement* iu = ms->FirstChildElement("InitialUnknowns");
  if (iu != nullptr) {
    initial_unknowns = check_unknowns(md, *iu, "initial_unknowns", true);
    std::size_t previous = 0;
    std::set<std::size_t> seen;
    for (std::size_t index : initial_unknowns) {
      const variable& v = md.vars[index - 1];
      if (!seen.insert(index).second) {
        md.out.error("initial_unknowns.order", describe(v) + ": listed twice in <InitialUnknowns>");
      } else if (index < previous) {
        md.out.error("initial_unknowns.order",
                     describe(v) + ": <InitialUnknowns> is not sorted by index");
      }
      previous = std::max(previous, index);
      if (!required.contains(index)) {
        md.out.error("initial_unknowns.extra",
                     describe(v) +
                         ": listed in <InitialUnknowns> but is not an output with "
                         "initial approx|calculated, a calculatedParameter, or a "
                         "state/derivative with initial approx|calculated");
      }
    }
  }
  const std::set<std::size_t> listed_initial(initial_unknowns.begin(), initial_unknowns.end());
  for (std::size_t index : required) {
    if (!listed_initial.contains(index)) {
      const variable& v = md.vars[index - 1];
      md.out.error("initial_unknowns.missing",
                   describe(v) + ": must be listed in <ModelStructure><InitialUnknowns> (" +
                       (v.caus ? std::string(fmi2::to_string(*v.caus)) : std::string("?")) +
                       " with initial " +
                       (v.initial ? std::string(fmi2::to_string(*v.initial)) : "?") + ")");
    }
  }
}

}  // namespace stride::fmi_check::detail
