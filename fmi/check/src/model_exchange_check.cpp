// FMI 2.0 Model Exchange (docs/fmi-rules.md §2.5): the <ModelExchange> element, and the
// continuous states that <ModelStructure><Derivatives> defines for an importer's integrator.
// The rules that hold for Co-Simulation as well (derivatives.index, initial_unknowns.*) live in
// model_structure_check.cpp; the ones here only run when <ModelExchange> is present, so a
// Co-Simulation-only FMU is checked exactly as before.
#include <map>

#include "model_description_check.hpp"
#include "xs_values.hpp"

namespace stride::fmi_check::detail {

namespace {

using fmi2::causality;
using fmi2::variability;

/// The indices <Derivatives> lists, in document order; invalid ones are left out (they are
/// reported as derivatives.index by check_model_structure).
std::vector<std::size_t> listed_derivatives(const md_context& md, const XMLElement* ms) {
  std::vector<std::size_t> indices;
  const XMLElement* list = ms != nullptr ? ms->FirstChildElement("Derivatives") : nullptr;
  if (list == nullptr) return indices;
  for (const XMLElement* u = list->FirstChildElement("Unknown"); u != nullptr;
       u = u->NextSiblingElement("Unknown")) {
    const char* text = u->Attribute("index");
    const auto index = text != nullptr ? parse_xs_unsigned_int(text) : std::nullopt;
    if (index && *index >= 1 && *index <= md.vars.size()) indices.push_back(*index);
  }
  return indices;
}

/// Why `v` cannot be a continuous state, or "" when it can.
std::string state_defect(const variable& v) {
  if (v.caus == causality::parameter || v.caus == causality::calculated_parameter) {
    return "its causality is " + std::string(fmi2::to_string(*v.caus)) +
           "; an integrator cannot change a parameter";
  }
  if (v.var && v.var != variability::continuous) {
    return "its variability is " + std::string(fmi2::to_string(*v.var)) +
           "; a state must be continuous";
  }
  return "";
}

/// Each listed derivative is continuous and names a state that can be one, once.
/// Returns the states, by index.
std::set<std::size_t> check_derivatives(md_context& md, const std::vector<std::size_t>& listed) {
  std::set<std::size_t> states;
  std::map<std::size_t, std::size_t> derivative_of_state;
  for (std::size_t index : listed) {
    const variable& d = md.vars[index - 1];
    if (d.var && d.var != variability::continuous) {
      md.out.error("me.derivative_continuous",
                   describe(d) + ": listed in <Derivatives> but its variability is " +
                       std::string(fmi2::to_string(*d.var)) +
                       "; the integrator needs continuous state derivatives");
    }
    if (!d.derivative_of) continue;  // derivatives.index
    const std::size_t state = *d.derivative_of;
    const auto [it, first] = derivative_of_state.emplace(state, index);
    if (!first) {
      const std::string earlier =
          it->second == index ? "has this derivative twice"
                              : "already has the derivative " + quote(md.vars[it->second - 1].name);
      md.out.error("me.state_unique", describe(d) + ": its state " +
                                          quote(md.vars[state - 1].name) + " " + earlier +
                                          " in <Derivatives>; every state occurs once in the "
                                          "state vector");
      continue;
    }
    states.insert(state);
    if (const std::string why = state_defect(md.vars[state - 1]); !why.empty()) {
      md.out.error("me.state", describe(md.vars[state - 1]) + ": the state of " + quote(d.name) +
                                   " in <Derivatives>, but " + why);
    }
  }
  return states;
}

/// The standard names the derivative attribute also for input or output derivatives; a state
/// derivative is every other one, so those must all be in <Derivatives>.
void check_unlisted(md_context& md, const std::vector<std::size_t>& listed) {
  const std::set<std::size_t> in_list(listed.begin(), listed.end());
  for (const variable& v : md.vars) {
    if (!v.derivative_of || in_list.contains(v.index)) continue;
    const variable& of = md.vars[*v.derivative_of - 1];
    if (v.caus == causality::input || of.caus == causality::input) continue;
    md.out.error("me.derivative_unlisted",
                 describe(v) + ": the derivative of " + quote(of.name) +
                     " is missing from <ModelStructure><Derivatives>, which defines the "
                     "continuous-state vector of a Model Exchange FMU");
  }
}

/// reinit says whether an event may reset a continuous state: anything else must not have it.
void check_reinit(md_context& md, const std::set<std::size_t>& states) {
  for (const variable& v : md.vars) {
    if (v.type_element == nullptr || v.type_element->Attribute("reinit") == nullptr) continue;
    if (!states.contains(v.index)) {
      md.out.error("me.reinit", describe(v) +
                                    ": has reinit but is not a continuous state (none of the "
                                    "variables in <Derivatives> is its derivative)");
    }
  }
}

}  // namespace

void check_model_exchange(md_context& md, const XMLElement& me) {
  md.model_exchange = true;
  md.me_model_identifier = check_interface_element(
      md, me, "me",
      {"needsExecutionTool", "completedIntegratorStepNotNeeded",
       "canBeInstantiatedOnlyOncePerProcess", "canNotUseMemoryManagementFunctions",
       "canGetAndSetFMUstate", "canSerializeFMUstate", "providesDirectionalDerivative"},
      {});
}

void check_model_exchange_states(md_context& md, const XMLElement* ms) {
  if (md.vars.empty()) return;
  const std::vector<std::size_t> listed = listed_derivatives(md, ms);
  const std::set<std::size_t> states = check_derivatives(md, listed);
  check_unlisted(md, listed);
  check_reinit(md, states);
}

}  // namespace stride::fmi_check::detail
