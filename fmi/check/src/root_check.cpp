// The fmiModelDescription element and the children before the variables: root attributes,
// CoSimulation (ModelExchange: model_exchange_check.cpp), LogCategories and DefaultExperiment
// (docs/fmi-rules.md §2.2).
#include <cmath>

#include "model_description_check.hpp"
#include "xs_values.hpp"

namespace stride::fmi_check::detail {

void check_root_attributes(md_context& md, const XMLElement& root) {
  check_attributes(md.out, root,
                   {"fmiVersion", "modelName", "guid", "description", "author", "version",
                    "copyright", "license", "generationTool", "generationDateAndTime",
                    "variableNamingConvention", "numberOfEventIndicators"});
  const char* version = root.Attribute("fmiVersion");
  if (version == nullptr) {
    md.out.error("root.fmi_version", "fmiModelDescription has no fmiVersion attribute");
  } else if (std::string_view(version) != "2.0") {
    md.out.error("root.fmi_version",
                 "fmiVersion is " + quote(version) + ", an FMI 2.0 FMU must declare \"2.0\"");
  }
  const char* model_name = root.Attribute("modelName");
  if (model_name == nullptr) {
    md.out.error("root.model_name", "fmiModelDescription has no modelName attribute");
  }
  const char* guid = root.Attribute("guid");
  if (guid == nullptr) {
    md.out.error("root.guid", "fmiModelDescription has no guid attribute");
  } else if (trim(guid).empty()) {
    md.out.error("root.guid", "fmiModelDescription has an empty guid");
  }
  if (const char* date = root.Attribute("generationDateAndTime");
      date != nullptr && !is_xs_date_time(date)) {
    md.out.error("root.generation_date", "generationDateAndTime " + quote(date) +
                                             " is not an xs:dateTime (e.g. 2026-11-22T10:00:00Z)");
  }
  if (const char* naming = root.Attribute("variableNamingConvention");
      naming != nullptr && std::string_view(naming) != "flat" &&
      std::string_view(naming) != "structured") {
    md.out.error("root.attribute_value", "variableNamingConvention " + quote(naming) +
                                             " is neither \"flat\" nor \"structured\"");
  }
  if (const char* n = root.Attribute("numberOfEventIndicators");
      n != nullptr && !parse_xs_unsigned_int(n)) {
    md.out.error("root.attribute_value",
                 "numberOfEventIndicators " + quote(n) + " is not an unsigned integer");
  }
}

void check_interfaces(md_context& md, const XMLElement& root) {
  const XMLElement* cs = root.FirstChildElement("CoSimulation");
  const XMLElement* me = root.FirstChildElement("ModelExchange");
  if (cs == nullptr && me == nullptr) {
    // the rule keeps its id from the time Stride took Co-Simulation FMUs only
    md.out.error("cosim.missing",
                 "there is neither <CoSimulation> nor <ModelExchange>: the FMU implements no "
                 "interface type");
  }
  if (cs != nullptr) check_co_simulation(md, *cs);
  if (me != nullptr) check_model_exchange(md, *me);
}

std::string check_interface_element(md_context& md, const XMLElement& element,
                                    const std::string& rule,
                                    std::initializer_list<std::string_view> flags,
                                    std::initializer_list<std::string_view> other_attributes) {
  std::set<std::string_view> allowed(flags);
  allowed.insert(other_attributes);
  allowed.insert("modelIdentifier");
  check_attributes(md.out, element, allowed);
  std::string identifier;
  const char* id = element.Attribute("modelIdentifier");
  if (id == nullptr) {
    md.out.error(rule + ".model_identifier",
                 at(element) + ": <" + element.Name() + "> has no modelIdentifier");
  } else if (!is_c_identifier(id)) {
    md.out.error(rule + ".model_identifier",
                 at(element) + ": modelIdentifier " + quote(id) +
                     " is not a C identifier (it names binaries/linux64/<modelIdentifier>.so)");
  } else {
    identifier = id;
  }
  for (std::string_view flag : flags) {
    const char* value = element.Attribute(std::string(flag).c_str());
    if (value != nullptr && !parse_xs_boolean(value)) {
      md.out.error(rule + ".flag", at(element) + ": " + std::string(flag) + "=" + quote(value) +
                                       " is not an xs:boolean (true|false)");
    }
  }
  return identifier;
}

void check_co_simulation(md_context& md, const XMLElement& cs) {
  md.model_identifier = check_interface_element(
      md, cs, "cosim",
      {"needsExecutionTool", "canHandleVariableCommunicationStepSize", "canInterpolateInputs",
       "canRunAsynchronuously", "canBeInstantiatedOnlyOncePerProcess",
       "canNotUseMemoryManagementFunctions", "canGetAndSetFMUstate", "canSerializeFMUstate",
       "providesDirectionalDerivative"},
      {"maxOutputDerivativeOrder"});
  if (const char* order = cs.Attribute("maxOutputDerivativeOrder");
      order != nullptr && !parse_xs_unsigned_int(order)) {
    md.out.error("cosim.flag", at(cs) + ": maxOutputDerivativeOrder=" + quote(order) +
                                   " is not an unsigned integer");
  }
}

void check_log_categories(md_context& md, const XMLElement* lc) {
  if (lc == nullptr) return;
  std::set<std::string, std::less<>> names;
  for (const XMLElement* c = lc->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    if (std::string_view(c->Name()) != "Category") {
      md.out.error("structure.child_order",
                   at(*c) + ": unexpected element <" + c->Name() + "> in <LogCategories>");
      continue;
    }
    check_attributes(md.out, *c, {"name", "description"});
    const char* name = c->Attribute("name");
    if (name == nullptr) {
      md.out.error("log_categories.name", at(*c) + ": <Category> without a name");
    } else if (!names.emplace(name).second) {
      md.out.error("log_categories.unique",
                   at(*c) + ": log category " + quote(name) + " is declared twice");
    }
  }
}

void check_default_experiment(md_context& md, const XMLElement* de) {
  if (de == nullptr) return;
  check_attributes(md.out, *de, {"startTime", "stopTime", "tolerance", "stepSize"});
  auto number = [&](const char* attribute) -> std::optional<double> {
    const char* text = de->Attribute(attribute);
    if (text == nullptr) return std::nullopt;
    const auto v = parse_xs_double(text);
    if (!v || !std::isfinite(*v)) {
      md.out.error("default_experiment.value", at(*de) + ": DefaultExperiment " + attribute + "=" +
                                                   quote(text) + " is not a finite number");
      return std::nullopt;
    }
    return v;
  };
  const auto start = number("startTime");
  const auto stop = number("stopTime");
  const auto tolerance = number("tolerance");
  const auto step = number("stepSize");
  if (stop && *stop <= start.value_or(0.0)) {
    md.out.error("default_experiment.interval",
                 at(*de) + ": DefaultExperiment stopTime " + std::to_string(*stop) +
                     " is not after startTime " + std::to_string(start.value_or(0.0)));
  }
  if (step && *step <= 0.0) {
    md.out.error("default_experiment.step_size", at(*de) + ": DefaultExperiment stepSize " +
                                                     std::to_string(*step) + " is not positive");
  }
  if (tolerance && *tolerance <= 0.0) {
    md.out.error("default_experiment.tolerance", at(*de) + ": DefaultExperiment tolerance " +
                                                     std::to_string(*tolerance) +
                                                     " is not positive");
  }
}

}  // namespace stride::fmi_check::detail
