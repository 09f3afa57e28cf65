// FMI 3.0: the fmiModelDescription attributes, the interface type elements, UnitDefinitions and
// TypeDefinitions (docs/fmi3-rules.md §5).
#include <algorithm>
#include <cmath>
#include <span>

#include "model_description_check3.hpp"
#include "xs_values.hpp"

namespace stride::fmi_check::detail {

namespace {

// flags every interface type has (§2.4.2 of the standard)
constexpr std::string_view k_common_flags[] = {"needsExecutionTool",
                                               "canBeInstantiatedOnlyOncePerProcess",
                                               "canGetAndSetFMUState",
                                               "canSerializeFMUState",
                                               "providesDirectionalDerivatives",
                                               "providesAdjointDerivatives",
                                               "providesPerElementDependencies"};

constexpr std::string_view k_co_simulation_flags[] = {"canHandleVariableCommunicationStepSize",
                                                      "providesIntermediateUpdate",
                                                      "mightReturnEarlyFromDoStep",
                                                      "canReturnEarlyAfterIntermediateUpdate",
                                                      "hasEventMode",
                                                      "providesEvaluateDiscreteStates"};

constexpr std::string_view k_co_simulation_unsigned[] = {"maxOutputDerivativeOrder",
                                                         "recommendedIntermediateInputSmoothness"};

constexpr std::string_view k_model_exchange_flags[] = {"needsCompletedIntegratorStep",
                                                       "providesEvaluateDiscreteStates"};

constexpr std::string_view k_type_definitions[] = {
    "Float32Type", "Float64Type", "Int8Type",   "UInt8Type",       "Int16Type",
    "UInt16Type",  "Int32Type",   "UInt32Type", "Int64Type",       "UInt64Type",
    "BooleanType", "StringType",  "BinaryType", "EnumerationType", "ClockType"};

/// Checks the attributes of one interface type element; returns its modelIdentifier if valid.
std::string check_interface(md3_context& md, const XMLElement& e,
                            std::span<const std::string_view> own_flags,
                            std::span<const std::string_view> unsigned_attributes) {
  std::set<std::string_view> allowed(std::begin(k_common_flags), std::end(k_common_flags));
  allowed.insert(own_flags.begin(), own_flags.end());
  allowed.insert(unsigned_attributes.begin(), unsigned_attributes.end());
  allowed.insert("modelIdentifier");
  const bool co_simulation = std::string_view(e.Name()) == "CoSimulation";
  if (co_simulation) allowed.insert("fixedInternalStepSize");
  check_attributes(md.out, e, allowed, "3.0");

  for (std::string_view flag : allowed) {
    if (flag == "modelIdentifier" || flag == "fixedInternalStepSize") continue;
    const char* value = e.Attribute(std::string(flag).c_str());
    if (value == nullptr) continue;
    const bool is_unsigned = std::find(unsigned_attributes.begin(), unsigned_attributes.end(),
                                       flag) != unsigned_attributes.end();
    if (is_unsigned ? !parse_xs_unsigned_int(value) : !parse_xs_boolean(value)) {
      md.out.error("fmi3.interface.flag",
                   at(e) + ": <" + e.Name() + "> " + std::string(flag) + "=" + quote(value) +
                       (is_unsigned ? " is not an unsigned integer" : " is not an xs:boolean"));
    }
  }
  if (const char* step = e.Attribute("fixedInternalStepSize"); co_simulation && step != nullptr) {
    const auto h = parse_xs_double(step);
    if (!h || !std::isfinite(*h) || *h <= 0.0) {
      md.out.error("fmi3.interface.flag",
                   at(e) + ": fixedInternalStepSize=" + quote(step) + " is not a positive number");
    }
  }
  // a flag that is absent or unreadable counts as false, its default
  auto is_set = [&](const char* flag) {
    const char* value = e.Attribute(flag);
    return value != nullptr && parse_xs_boolean(value) == true;
  };
  if (is_set("canSerializeFMUState") && !is_set("canGetAndSetFMUState")) {
    md.out.error("fmi3.interface.flag",
                 at(e) + ": <" + e.Name() + "> canSerializeFMUState needs canGetAndSetFMUState");
  }

  const char* id = e.Attribute("modelIdentifier");
  if (id == nullptr) {
    md.out.error("fmi3.interface.model_identifier",
                 at(e) + ": <" + e.Name() + "> has no modelIdentifier");
  } else if (!is_c_identifier(id)) {
    md.out.error(
        "fmi3.interface.model_identifier",
        at(e) + ": modelIdentifier " + quote(id) +
            " is not a C identifier (it names binaries/x86_64-linux/<modelIdentifier>.so)");
  } else {
    return id;
  }
  return {};
}

}  // namespace

void check_root_attributes3(md3_context& md, const XMLElement& root) {
  check_attributes(md.out, root,
                   {"fmiVersion", "modelName", "instantiationToken", "description", "author",
                    "version", "copyright", "license", "generationTool", "generationDateAndTime",
                    "variableNamingConvention"},
                   "3.0");
  // dispatched here for any "3.x"; this checker knows 3.0 and its maintenance releases 3.0.x
  const std::string_view version = root.Attribute("fmiVersion");
  const bool maintenance = version.starts_with("3.0.") && version.size() > 4 &&
                           version.substr(4).find_first_not_of("0123456789") == std::string::npos;
  if (version != "3.0" && !maintenance) {
    md.out.error("fmi3.root.fmi_version", "fmiVersion is " + quote(version) +
                                              ", this checker knows FMI \"3.0\" (and 3.0.x)");
  }
  if (root.Attribute("modelName") == nullptr) {
    md.out.error("fmi3.root.model_name", "fmiModelDescription has no modelName attribute");
  }
  const char* token = root.Attribute("instantiationToken");
  if (token == nullptr) {
    md.out.error(
        "fmi3.root.instantiation_token",
        std::string("fmiModelDescription has no instantiationToken attribute") +
            (root.Attribute("guid") != nullptr ? " (FMI 2.0's guid is not read in 3.0)" : ""));
  } else if (trim(token).empty()) {
    md.out.error("fmi3.root.instantiation_token",
                 "fmiModelDescription has an empty "
                 "instantiationToken");
  }
  if (const char* date = root.Attribute("generationDateAndTime");
      date != nullptr && !is_xs_date_time(date)) {
    md.out.error("root.generation_date", "generationDateAndTime " + quote(date) +
                                             " is not an xs:dateTime (e.g. 2026-11-22T10:00:00Z)");
  }
  if (const char* naming = root.Attribute("variableNamingConvention");
      naming != nullptr && std::string_view(naming) != "flat" &&
      std::string_view(naming) != "structured") {
    md.out.error("fmi3.root.naming_convention", "variableNamingConvention " + quote(naming) +
                                                    " is neither \"flat\" nor \"structured\"");
  }
}

void check_interfaces3(md3_context& md, const XMLElement& root) {
  if (const XMLElement* me = root.FirstChildElement("ModelExchange")) {
    md.me_model_identifier = check_interface(md, *me, k_model_exchange_flags, {});
  }
  if (const XMLElement* se = root.FirstChildElement("ScheduledExecution")) {
    check_interface(md, *se, {}, {});
    md.out.warning("fmi3.interface.not_usable",
                   at(*se) +
                       ": <ScheduledExecution> is not usable by Stride, which imports "
                       "Co-Simulation and Model Exchange");
  }
  const XMLElement* cs = root.FirstChildElement("CoSimulation");
  if (cs != nullptr) {
    md.model_identifier = check_interface(md, *cs, k_co_simulation_flags, k_co_simulation_unsigned);
  } else if (root.FirstChildElement("ModelExchange") == nullptr) {
    md.out.error("fmi3.interface.missing",
                 "there is neither a <CoSimulation> nor a <ModelExchange> element");
  }
}

void check_unit_definitions3(md3_context& md, const XMLElement* ud) {
  if (ud == nullptr) return;
  for (const XMLElement* u = ud->FirstChildElement(); u != nullptr; u = u->NextSiblingElement()) {
    if (std::string_view(u->Name()) != "Unit") {
      md.out.error("structure.child_order",
                   at(*u) + ": unexpected element <" + u->Name() + "> in <UnitDefinitions>");
      continue;
    }
    const char* name = u->Attribute("name");
    if (name == nullptr) {
      md.out.error("fmi3.unit.name", at(*u) + ": <Unit> without a name");
      continue;
    }
    const auto [it, inserted] = md.units.try_emplace(name);
    if (!inserted) {
      md.out.error("fmi3.unit.name", at(*u) + ": unit " + quote(name) + " is declared twice");
      continue;
    }
    for (const XMLElement* d = u->FirstChildElement("DisplayUnit"); d != nullptr;
         d = d->NextSiblingElement("DisplayUnit")) {
      const char* display = d->Attribute("name");
      if (display == nullptr || !it->second.emplace(display).second) {
        md.out.error("fmi3.unit.name", at(*d) + ": a <DisplayUnit> of " + quote(name) +
                                           " has no name or repeats one");
      }
    }
  }
}

void check_type_definitions3(md3_context& md, const XMLElement* td) {
  if (td == nullptr) return;
  for (const XMLElement* t = td->FirstChildElement(); t != nullptr; t = t->NextSiblingElement()) {
    const std::string_view element = t->Name();
    if (std::find(std::begin(k_type_definitions), std::end(k_type_definitions), element) ==
        std::end(k_type_definitions)) {
      md.out.error("structure.child_order",
                   at(*t) + ": unexpected element <" + std::string(element) +
                       "> in <TypeDefinitions> (Float64Type, Int32Type, EnumerationType, ...)");
      continue;
    }
    const char* name = t->Attribute("name");
    if (name == nullptr || trim(name).empty()) {
      md.out.error("fmi3.type_definitions.name",
                   at(*t) + ": <" + std::string(element) + "> without a name");
    } else if (!md.types.emplace(name, t).second) {
      md.out.error("fmi3.type_definitions.name",
                   at(*t) + ": type definition name " + quote(name) + " is used twice");
    }
  }
}

}  // namespace stride::fmi_check::detail
