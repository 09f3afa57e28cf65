// FMI 3.0 ModelStructure: <Output>, <ContinuousStateDerivative> and <InitialUnknown> name the
// right variables by valueReference, in order, with dependencies on knowns only
// (docs/fmi3-rules.md §5).
#include <algorithm>
#include <array>

#include "model_description_check3.hpp"
#include "xs_values.hpp"

namespace stride::fmi_check::detail {

namespace {

using fmi2::initial_kind;

constexpr std::array<std::string_view, 5> k_unknown_elements = {
    "Output", "ContinuousStateDerivative", "ClockedState", "InitialUnknown", "EventIndicator"};

bool approx_or_calculated(const variable3& v) {
  return v.initial == initial_kind::approx || v.initial == initial_kind::calculated;
}

/// The variables an unknown may depend on: inputs, the independent variable and continuous
/// states; in Initialization Mode also every variable with initial exact.
bool is_known(const md3_context& md, const variable3& v, bool initialization) {
  if (v.caus == causality3::input || v.caus == causality3::independent) return true;
  if (initialization && v.initial == initial_kind::exact) return true;
  return v.vr && std::any_of(md.vars.begin(), md.vars.end(),
                             [&](const variable3& d) { return d.derivative_of == v.vr; });
}

void check_dependencies(md3_context& md, const XMLElement& unknown, const std::string& where,
                        bool initialization) {
  const char* deps_text = unknown.Attribute("dependencies");
  const char* kinds_text = unknown.Attribute("dependenciesKind");
  std::size_t count = 0;
  if (deps_text != nullptr) {
    const auto parts = split_ws(deps_text);
    count = parts.size();
    for (std::string_view p : parts) {
      const auto vr = parse_xs_unsigned_int(p);
      const variable3* known = vr ? md.find(*vr) : nullptr;
      if (known == nullptr) {
        md.out.error(
            "fmi3.dependencies.value_reference",
            where + " dependency " + quote(p) + " is not the valueReference of a variable");
      } else if (!is_known(md, *known, initialization)) {
        md.out.error("fmi3.dependencies.known",
                     where + " depends on " + quote(known->name) +
                         ", which is no input, continuous state or independent variable" +
                         (initialization ? " and has no initial exact" : ""));
      }
    }
  }
  if (kinds_text == nullptr) return;
  const auto kinds = split_ws(kinds_text);
  if (deps_text == nullptr) {
    md.out.error("fmi3.dependencies.kind", where + " has dependenciesKind without dependencies");
  } else if (kinds.size() != count) {
    md.out.error("fmi3.dependencies.kind", where + " has " + std::to_string(count) +
                                               " dependencies but " + std::to_string(kinds.size()) +
                                               " dependenciesKind entries");
  }
  for (std::string_view k : kinds) {
    if (initialization && k != "dependent" && k != "constant") {
      md.out.error("fmi3.initial_unknowns.kind", where + " dependenciesKind " + quote(k) +
                                                     " is not allowed in <InitialUnknown> "
                                                     "(dependent|constant)");
    } else if (k != "dependent" && k != "constant" && k != "fixed" && k != "tunable" &&
               k != "discrete") {
      md.out.error("fmi3.dependencies.kind",
                   where + " dependenciesKind " + quote(k) +
                       " is not one of dependent, constant, fixed, tunable, discrete");
    }
  }
}

/// The variables listed by the children named `element`, in document order.
std::vector<const variable3*> check_unknowns(md3_context& md, const XMLElement& ms,
                                             const char* element) {
  std::vector<const variable3*> listed;
  const bool initialization = std::string_view(element) == "InitialUnknown";
  for (const XMLElement* u = ms.FirstChildElement(element); u != nullptr;
       u = u->NextSiblingElement(element)) {
    check_attributes(md.out, *u, {"valueReference", "dependencies", "dependenciesKind"}, "3.0");
    const std::string where = at(*u) + ": <" + element + ">";
    const char* text = u->Attribute("valueReference");
    const auto vr = text != nullptr ? parse_xs_unsigned_int(text) : std::nullopt;
    const variable3* v = vr ? md.find(*vr) : nullptr;
    if (v == nullptr) {
      md.out.error("fmi3.unknown.value_reference", where + " valueReference " +
                                                       quote(text != nullptr ? text : "") +
                                                       " is not the valueReference of a variable");
      continue;
    }
    check_dependencies(md, *u, where + " of " + quote(v->name), initialization);
    listed.push_back(v);
  }
  return listed;
}

void check_child_sequence(md3_context& md, const XMLElement& ms) {
  std::size_t last = 0;
  for (const XMLElement* c = ms.FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    const auto it = std::find(k_unknown_elements.begin(), k_unknown_elements.end(), c->Name());
    if (it == k_unknown_elements.end()) {
      md.out.error("structure.child_order",
                   at(*c) + ": unexpected element <" + c->Name() + "> in <ModelStructure>");
      continue;
    }
    const auto rank = static_cast<std::size_t>(it - k_unknown_elements.begin());
    if (rank < last) {
      md.out.error("structure.child_order", at(*c) + ": <" + c->Name() + "> must come before <" +
                                                std::string(k_unknown_elements[last]) +
                                                "> in <ModelStructure>");
    }
    last = std::max(last, rank);
  }
}

void check_outputs(md3_context& md, const std::vector<const variable3*>& outputs) {
  std::set<std::size_t> seen;
  std::size_t previous = 0;
  for (const variable3* v : outputs) {
    if (v->caus != causality3::output) {
      md.out.error("fmi3.outputs.not_output", describe(*v) +
                                                  ": listed as <Output> but its causality "
                                                  "is not output");
    }
    if (!seen.insert(v->index).second) {
      md.out.error("fmi3.outputs.order", describe(*v) + ": listed twice as <Output>");
    } else if (v->index < previous) {
      md.out.error("fmi3.outputs.order",
                   describe(*v) + ": the <Output> elements are not in ModelVariables order");
    }
    previous = std::max(previous, v->index);
  }
  for (const variable3& v : md.vars) {
    if (v.caus == causality3::output && !seen.contains(v.index)) {
      md.out.error("fmi3.outputs.missing", describe(v) +
                                               ": an output without an <Output> in "
                                               "<ModelStructure>");
    }
  }
}

void check_initial_unknowns(md3_context& md, const std::vector<const variable3*>& derivatives,
                            const std::vector<const variable3*>& listed) {
  std::set<std::size_t> required;
  for (const variable3& v : md.vars) {
    if (v.caus == causality3::output && approx_or_calculated(v)) required.insert(v.index);
    if (v.caus == causality3::calculated_parameter) required.insert(v.index);
  }
  for (const variable3* d : derivatives) {
    if (approx_or_calculated(*d)) required.insert(d->index);
    const variable3* state = d->derivative_of ? md.find(*d->derivative_of) : nullptr;
    if (state != nullptr && approx_or_calculated(*state)) required.insert(state->index);
  }
  std::set<std::size_t> seen;
  for (const variable3* v : listed) {
    if (!seen.insert(v->index).second) {
      md.out.error("fmi3.initial_unknowns.order",
                   describe(*v) + ": listed twice as <InitialUnknown>");
    } else if (!required.contains(v->index)) {
      md.out.error("fmi3.initial_unknowns.extra",
                   describe(*v) +
                       ": listed as <InitialUnknown> but is no output with initial "
                       "approx|calculated, no calculatedParameter and no continuous state or "
                       "derivative with initial approx|calculated");
    }
  }
  for (std::size_t index : required) {
    if (!seen.contains(index)) {
      const variable3& v = md.vars[index - 1];
      md.out.error("fmi3.initial_unknowns.missing",
                   describe(v) + ": must be listed as <InitialUnknown> (" +
                       (v.caus ? std::string(to_string(*v.caus)) : std::string("?")) +
                       " with initial " + std::string(to_string(*v.initial)) + ")");
    }
  }
}

}  // namespace

void check_model_structure3(md3_context& md, const XMLElement* ms) {
  if (ms == nullptr) {
    md.out.error("structure.model_structure", "there is no <ModelStructure> element");
    return;
  }
  check_child_sequence(md, *ms);
  if (md.vars.empty()) return;
  check_outputs(md, check_unknowns(md, *ms, "Output"));
  const auto derivatives = check_unknowns(md, *ms, "ContinuousStateDerivative");
  for (const variable3* d : derivatives) {
    if (!d->derivative_of) {
      md.out.error("fmi3.derivatives.value_reference",
                   describe(*d) +
                       ": listed as <ContinuousStateDerivative> but has no derivative attribute "
                       "(list the derivative, not the state)");
    }
  }
  check_initial_unknowns(md, derivatives, check_unknowns(md, *ms, "InitialUnknown"));
  // references and dependencies only: Stride offers neither clocks nor Model Exchange
  check_unknowns(md, *ms, "ClockedState");
  check_unknowns(md, *ms, "EventIndicator");
}

}  // namespace stride::fmi_check::detail
