// modelDescription.xml rules of checklist §2.1 (archive ties) and §2.2.
#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "reporter.hpp"
#include "stride/fmi_check/fmu_check.hpp"
#include "xs_values.hpp"

namespace stride::fmi_check {

namespace {

using detail::quote;
using tinyxml2::XMLAttribute;
using tinyxml2::XMLElement;

enum class causality { parameter, calculated_parameter, input, output, local, independent };
enum class variability { constant, fixed, tunable, discrete, continuous };
enum class initial_kind { exact, approx, calculated };

std::optional<causality> parse_causality(std::string_view s) {
  if (s == "parameter") return causality::parameter;
  if (s == "calculatedParameter") return causality::calculated_parameter;
  if (s == "input") return causality::input;
  if (s == "output") return causality::output;
  if (s == "local") return causality::local;
  if (s == "independent") return causality::independent;
  return std::nullopt;
}

std::optional<variability> parse_variability(std::string_view s) {
  if (s == "constant") return variability::constant;
  if (s == "fixed") return variability::fixed;
  if (s == "tunable") return variability::tunable;
  if (s == "discrete") return variability::discrete;
  if (s == "continuous") return variability::continuous;
  return std::nullopt;
}

std::optional<initial_kind> parse_initial(std::string_view s) {
  if (s == "exact") return initial_kind::exact;
  if (s == "approx") return initial_kind::approx;
  if (s == "calculated") return initial_kind::calculated;
  return std::nullopt;
}

std::string_view name_of(causality c) {
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

std::string_view name_of(variability v) {
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

std::string_view name_of(initial_kind i) {
  switch (i) {
    case initial_kind::exact:
      return "exact";
    case initial_kind::approx:
      return "approx";
    case initial_kind::calculated:
      return "calculated";
  }
  return "?";
}

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

const std::set<std::string_view> k_type_names = {"Real", "Integer", "Boolean", "String",
                                                 "Enumeration"};

const std::map<std::string_view, std::set<std::string_view>> k_type_attributes = {
    {"Real",
     {"declaredType", "quantity", "unit", "displayUnit", "relativeQuantity", "min", "max",
      "nominal", "unbounded", "start", "derivative", "reinit"}},
    {"Integer", {"declaredType", "quantity", "min", "max", "start"}},
    {"Boolean", {"declaredType", "start"}},
    {"String", {"declaredType", "start"}},
    {"Enumeration", {"declaredType", "quantity", "min", "max", "start"}},
};

struct variable {
  std::size_t index = 0;  // 1-based position in ModelVariables
  int line = 0;
  std::string name;
  std::optional<std::uint32_t> vr;
  std::string type;  // "Real", ... or empty when the type child is broken
  const XMLElement* type_element = nullptr;
  std::optional<causality> caus;
  std::optional<variability> var;
  std::optional<initial_kind> initial;  // effective value (given or default)
  bool has_start = false;
  std::optional<std::size_t> derivative_of;  // Real@derivative, when valid
};

struct simple_type {
  std::string type;  // base type element name
  const XMLElement* element = nullptr;
};

class model_description_checker {
 public:
  model_description_checker(detail::reporter& out, const archive_listing* archive)
      : out_(out), archive_(archive) {}

  void run(std::string_view xml);

 private:
  void check_attributes(const XMLElement& e, std::initializer_list<std::string_view> allowed);
  void check_attributes(const XMLElement& e, const std::set<std::string_view>& allowed);
  void check_root(const XMLElement& root);
  void check_child_order(const XMLElement& parent,
                         std::initializer_list<std::string_view> sequence);
  void check_co_simulation(const XMLElement* cs);
  void check_type_definitions(const XMLElement* td);
  void check_log_categories(const XMLElement* lc);
  void check_default_experiment(const XMLElement* de);
  void check_model_variables(const XMLElement* mv);
  void check_variable(variable& v, const XMLElement& sv);
  void check_values(const variable& v);
  void check_aliases();
  void check_derivative_attributes();
  void check_array_names();
  void check_model_structure(const XMLElement* ms);
  std::vector<std::size_t> check_unknowns(const XMLElement& list, std::string_view rule_prefix,
                                          bool initial_unknowns);
  void check_dependencies(const XMLElement& unknown, std::string_view where, bool initial_unknowns);
  void check_archive();

  static std::string at(const XMLElement& e) { return "line " + std::to_string(e.GetLineNum()); }
  static std::string describe(const variable& v) {
    return "line " + std::to_string(v.line) + ": variable " + quote(v.name) + " (index " +
           std::to_string(v.index) + ")";
  }

  detail::reporter& out_;
  const archive_listing* archive_;
  std::string model_identifier_;
  std::vector<variable> vars_;
  std::map<std::string, simple_type, std::less<>> simple_types_;
};

void model_description_checker::check_attributes(const XMLElement& e,
                                                 std::initializer_list<std::string_view> allowed) {
  check_attributes(e, std::set<std::string_view>(allowed));
}

void model_description_checker::check_attributes(const XMLElement& e,
                                                 const std::set<std::string_view>& allowed) {
  for (const XMLAttribute* a = e.FirstAttribute(); a != nullptr; a = a->Next()) {
    const std::string_view name = a->Name();
    if (allowed.contains(name) || name.starts_with("xmlns") || name.starts_with("xsi:")) continue;
    std::string message =
        at(e) + ": <" + e.Name() + "> has no attribute " + quote(name) + " in FMI 2.0";
    if (name == "canGetAndSetFMUState" || name == "canSerializeFMUState" ||
        name == "providesDirectionalDerivatives") {
      message +=
          " (FMI 3.0 spelling; FMI 2.0 writes canGetAndSetFMUstate, canSerializeFMUstate, "
          "providesDirectionalDerivative)";
    }
    out_.error("schema.attribute", std::move(message));
  }
}

void model_description_checker::run(std::string_view xml) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
    out_.error("xml.well_formed", std::string("modelDescription.xml is not well-formed XML: ") +
                                      (doc.ErrorStr() != nullptr ? doc.ErrorStr() : "parse error"));
    return;
  }
  const XMLElement* root = doc.RootElement();
  if (root == nullptr) {
    out_.error("xml.well_formed", "modelDescription.xml has no root element");
    return;
  }
  if (std::string_view(root->Name()) != "fmiModelDescription") {
    out_.error("root.element", at(*root) + ": the root element is <" + root->Name() +
                                   ">, expected <fmiModelDescription>");
    return;
  }
  check_root(*root);
  check_child_order(*root, {"ModelExchange", "CoSimulation", "UnitDefinitions", "TypeDefinitions",
                            "LogCategories", "DefaultExperiment", "VendorAnnotations",
                            "ModelVariables", "ModelStructure"});
  check_co_simulation(root->FirstChildElement("CoSimulation"));
  check_type_definitions(root->FirstChildElement("TypeDefinitions"));
  check_log_categories(root->FirstChildElement("LogCategories"));
  check_default_experiment(root->FirstChildElement("DefaultExperiment"));
  check_model_variables(root->FirstChildElement("ModelVariables"));
  check_model_structure(root->FirstChildElement("ModelStructure"));
  check_archive();
}

void model_description_checker::check_root(const XMLElement& root) {
  check_attributes(root, {"fmiVersion", "modelName", "guid", "description", "author", "version",
                          "copyright", "license", "generationTool", "generationDateAndTime",
                          "variableNamingConvention", "numberOfEventIndicators"});
  const char* version = root.Attribute("fmiVersion");
  if (version == nullptr) {
    out_.error("root.fmi_version", "fmiModelDescription has no fmiVersion attribute");
  } else if (std::string_view(version) != "2.0") {
    out_.error("root.fmi_version",
               "fmiVersion is " + quote(version) + ", an FMI 2.0 FMU must declare \"2.0\"");
  }
  const char* model_name = root.Attribute("modelName");
  if (model_name == nullptr) {
    out_.error("root.model_name", "fmiModelDescription has no modelName attribute");
  }
  const char* guid = root.Attribute("guid");
  if (guid == nullptr) {
    out_.error("root.guid", "fmiModelDescription has no guid attribute");
  } else if (detail::trim(guid).empty()) {
    out_.error("root.guid", "fmiModelDescription has an empty guid");
  }
  if (const char* date = root.Attribute("generationDateAndTime");
      date != nullptr && !detail::is_xs_date_time(date)) {
    out_.error("root.generation_date", "generationDateAndTime " + quote(date) +
                                           " is not an xs:dateTime (e.g. 2026-11-22T10:00:00Z)");
  }
  if (const char* naming = root.Attribute("variableNamingConvention");
      naming != nullptr && std::string_view(naming) != "flat" &&
      std::string_view(naming) != "structured") {
    out_.error("root.attribute_value", "variableNamingConvention " + quote(naming) +
                                           " is neither \"flat\" nor \"structured\"");
  }
  if (const char* n = root.Attribute("numberOfEventIndicators");
      n != nullptr && !detail::parse_xs_unsigned_int(n)) {
    out_.error("root.attribute_value",
               "numberOfEventIndicators " + quote(n) + " is not an unsigned integer");
  }
}

void model_description_checker::check_child_order(
    const XMLElement& parent, std::initializer_list<std::string_view> sequence) {
  const std::vector<std::string_view> order(sequence);
  std::ptrdiff_t last = -1;
  std::string_view last_name;
  for (const XMLElement* c = parent.FirstChildElement(); c != nullptr;
       c = c->NextSiblingElement()) {
    const std::string_view name = c->Name();
    const auto it = std::find(order.begin(), order.end(), name);
    if (it == order.end()) {
      out_.error("structure.child_order", at(*c) + ": unexpected element <" + std::string(name) +
                                              "> in <" + parent.Name() + ">");
      continue;
    }
    const std::ptrdiff_t rank = it - order.begin();
    if (rank == last) {
      out_.error("structure.child_order", at(*c) + ": <" + std::string(name) +
                                              "> occurs more than once in <" + parent.Name() + ">");
    } else if (rank < last) {
      out_.error("structure.child_order", at(*c) + ": <" + std::string(name) +
                                              "> must come before <" + std::string(last_name) +
                                              "> in <" + parent.Name() + ">");
    } else {
      last = rank;
      last_name = name;
    }
  }
}

void model_description_checker::check_co_simulation(const XMLElement* cs) {
  if (cs == nullptr) {
    out_.error("cosim.missing", "there is no <CoSimulation> element: not a Co-Simulation FMU");
    return;
  }
  static const std::initializer_list<std::string_view> k_flags = {
      "needsExecutionTool",
      "canHandleVariableCommunicationStepSize",
      "canInterpolateInputs",
      "canRunAsynchronuously",
      "canBeInstantiatedOnlyOncePerProcess",
      "canNotUseMemoryManagementFunctions",
      "canGetAndSetFMUstate",
      "canSerializeFMUstate",
      "providesDirectionalDerivative"};
  std::set<std::string_view> allowed(k_flags);
  allowed.insert("modelIdentifier");
  allowed.insert("maxOutputDerivativeOrder");
  check_attributes(*cs, allowed);
  const char* id = cs->Attribute("modelIdentifier");
  if (id == nullptr) {
    out_.error("cosim.model_identifier", at(*cs) + ": <CoSimulation> has no modelIdentifier");
  } else if (!detail::is_c_identifier(id)) {
    out_.error("cosim.model_identifier",
               at(*cs) + ": modelIdentifier " + quote(id) +
                   " is not a C identifier (it names binaries/linux64/<modelIdentifier>.so)");
  } else {
    model_identifier_ = id;
  }
  for (std::string_view flag : k_flags) {
    const char* value = cs->Attribute(std::string(flag).c_str());
    if (value != nullptr && !detail::parse_xs_boolean(value)) {
      out_.error("cosim.flag", at(*cs) + ": " + std::string(flag) + "=" + quote(value) +
                                   " is not an xs:boolean (true|false)");
    }
  }
  if (const char* order = cs->Attribute("maxOutputDerivativeOrder");
      order != nullptr && !detail::parse_xs_unsigned_int(order)) {
    out_.error("cosim.flag", at(*cs) + ": maxOutputDerivativeOrder=" + quote(order) +
                                 " is not an unsigned integer");
  }
}

void model_description_checker::check_type_definitions(const XMLElement* td) {
  if (td == nullptr) return;
  for (const XMLElement* st = td->FirstChildElement(); st != nullptr;
       st = st->NextSiblingElement()) {
    if (std::string_view(st->Name()) != "SimpleType") {
      out_.error("structure.child_order",
                 at(*st) + ": unexpected element <" + st->Name() + "> in <TypeDefinitions>");
      continue;
    }
    const char* name = st->Attribute("name");
    if (name == nullptr || detail::trim(name).empty()) {
      out_.error("type_definitions.name", at(*st) + ": <SimpleType> without a name");
      continue;
    }
    const XMLElement* base = st->FirstChildElement();
    while (base != nullptr && std::string_view(base->Name()) == "Annotations") {
      base = base->NextSiblingElement();
    }
    simple_type t{base != nullptr ? base->Name() : "", base};
    if (!simple_types_.emplace(name, t).second) {
      out_.error("type_definitions.name",
                 at(*st) + ": SimpleType name " + quote(name) + " is used twice");
    }
  }
}

void model_description_checker::check_log_categories(const XMLElement* lc) {
  if (lc == nullptr) return;
  std::set<std::string, std::less<>> names;
  for (const XMLElement* c = lc->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    if (std::string_view(c->Name()) != "Category") {
      out_.error("structure.child_order",
                 at(*c) + ": unexpected element <" + c->Name() + "> in <LogCategories>");
      continue;
    }
    check_attributes(*c, {"name", "description"});
    const char* name = c->Attribute("name");
    if (name == nullptr) {
      out_.error("log_categories.name", at(*c) + ": <Category> without a name");
    } else if (!names.emplace(name).second) {
      out_.error("log_categories.unique",
                 at(*c) + ": log category " + quote(name) + " is declared twice");
    }
  }
}

void model_description_checker::check_default_experiment(const XMLElement* de) {
  if (de == nullptr) return;
  check_attributes(*de, {"startTime", "stopTime", "tolerance", "stepSize"});
  auto number = [&](const char* attribute) -> std::optional<double> {
    const char* text = de->Attribute(attribute);
    if (text == nullptr) return std::nullopt;
    const auto v = detail::parse_xs_double(text);
    if (!v || !std::isfinite(*v)) {
      out_.error("default_experiment.value", at(*de) + ": DefaultExperiment " + attribute + "=" +
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
    out_.error("default_experiment.interval",
               at(*de) + ": DefaultExperiment stopTime " + std::to_string(*stop) +
                   " is not after startTime " + std::to_string(start.value_or(0.0)));
  }
  if (step && *step <= 0.0) {
    out_.error("default_experiment.step_size", at(*de) + ": DefaultExperiment stepSize " +
                                                   std::to_string(*step) + " is not positive");
  }
  if (tolerance && *tolerance <= 0.0) {
    out_.error("default_experiment.tolerance", at(*de) + ": DefaultExperiment tolerance " +
                                                   std::to_string(*tolerance) + " is not positive");
  }
}

void model_description_checker::check_model_variables(const XMLElement* mv) {
  if (mv == nullptr) {
    out_.error("variables.empty", "there is no <ModelVariables> element");
    return;
  }
  std::map<std::string, std::size_t, std::less<>> names;
  for (const XMLElement* sv = mv->FirstChildElement(); sv != nullptr;
       sv = sv->NextSiblingElement()) {
    if (std::string_view(sv->Name()) != "ScalarVariable") {
      out_.error("structure.child_order",
                 at(*sv) + ": unexpected element <" + sv->Name() + "> in <ModelVariables>");
      continue;
    }
    variable v;
    v.index = vars_.size() + 1;
    v.line = sv->GetLineNum();
    check_variable(v, *sv);
    if (!v.name.empty()) {
      auto [it, inserted] = names.emplace(v.name, v.index);
      if (!inserted) {
        out_.error("variable.name_unique", describe(v) + ": the name is already used by index " +
                                               std::to_string(it->second));
      }
    }
    vars_.push_back(std::move(v));
  }
  if (vars_.empty()) {
    out_.error("variables.empty", at(*mv) + ": <ModelVariables> has no <ScalarVariable>");
    return;
  }
  bool seen_independent = false;
  for (const variable& v : vars_) {
    if (v.caus != causality::independent) continue;
    if (seen_independent) {
      out_.error("variable.independent",
                 describe(v) + ": more than one variable has causality independent");
    }
    seen_independent = true;
  }
  check_aliases();
  check_derivative_attributes();
  check_array_names();
}

void model_description_checker::check_variable(variable& v, const XMLElement& sv) {
  check_attributes(sv, {"name", "valueReference", "description", "causality", "variability",
                        "initial", "canHandleMultipleSetPerTimeInstant"});
  if (const char* name = sv.Attribute("name"); name == nullptr || std::string_view(name).empty()) {
    out_.error("variable.name",
               at(sv) + ": <ScalarVariable> (index " + std::to_string(v.index) + ") has no name");
  } else {
    v.name = name;
  }
  if (v.name.empty()) v.name = "#" + std::to_string(v.index);

  const char* vr = sv.Attribute("valueReference");
  if (vr == nullptr) {
    out_.error("variable.value_reference", describe(v) + ": no valueReference");
  } else if (!(v.vr = detail::parse_xs_unsigned_int(vr))) {
    out_.error("variable.value_reference",
               describe(v) + ": valueReference " + quote(vr) + " is not an unsigned int");
  }

  // type child: exactly one of the five, Annotations aside
  int type_children = 0;
  for (const XMLElement* c = sv.FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    const std::string_view name = c->Name();
    if (name == "Annotations") continue;
    if (!k_type_names.contains(name)) {
      out_.error("variable.type", describe(v) + ": unexpected child <" + std::string(name) + ">");
      continue;
    }
    ++type_children;
    if (type_children == 1) {
      v.type = name;
      v.type_element = c;
    }
  }
  if (type_children != 1) {
    out_.error("variable.type", describe(v) + ": has " + std::to_string(type_children) +
                                    " type elements, expected exactly one of Real, Integer, "
                                    "Boolean, String, Enumeration");
    v.type.clear();
    v.type_element = nullptr;
  }
  if (v.type_element != nullptr) {
    check_attributes(*v.type_element, k_type_attributes.at(v.type));
    v.has_start = v.type_element->Attribute("start") != nullptr;
    const char* declared = v.type_element->Attribute("declaredType");
    if (v.type == "Enumeration" && declared == nullptr) {
      out_.error("variable.type", describe(v) + ": an Enumeration needs a declaredType");
    }
    if (declared != nullptr) {
      const auto it = simple_types_.find(std::string_view(declared));
      if (it == simple_types_.end()) {
        out_.error("variable.declared_type", describe(v) + ": declaredType " + quote(declared) +
                                                 " is not defined in <TypeDefinitions>");
      } else if (it->second.type != v.type) {
        out_.error("variable.declared_type", describe(v) + ": declaredType " + quote(declared) +
                                                 " is a " + it->second.type + ", the variable a " +
                                                 v.type);
      }
    }
  }

  const char* causality_text = sv.Attribute("causality");
  const char* variability_text = sv.Attribute("variability");
  const char* initial_text = sv.Attribute("initial");
  v.caus = causality_text != nullptr ? parse_causality(causality_text) : causality::local;
  if (!v.caus) {
    out_.error("variable.causality", describe(v) + ": causality " + quote(causality_text) +
                                         " is not one of parameter, calculatedParameter, input, "
                                         "output, local, independent");
  }
  v.var =
      variability_text != nullptr ? parse_variability(variability_text) : variability::continuous;
  if (!v.var) {
    out_.error("variable.variability", describe(v) + ": variability " + quote(variability_text) +
                                           " is not one of constant, fixed, tunable, discrete, "
                                           "continuous");
  }
  std::optional<initial_kind> given_initial;
  if (initial_text != nullptr) {
    given_initial = parse_initial(initial_text);
    if (!given_initial) {
      out_.error("variable.initial", describe(v) + ": initial " + quote(initial_text) +
                                         " is not one of exact, approx, calculated");
    }
  }
  v.initial = given_initial;

  if (v.caus && v.var) {
    if (!combination_allowed(*v.caus, *v.var)) {
      out_.error("variable.causality_variability",
                 describe(v) + ": causality " + std::string(name_of(*v.caus)) +
                     " with variability " + std::string(name_of(*v.var)) +
                     " is not allowed (parameter/calculatedParameter: fixed|tunable; input: "
                     "discrete|continuous; output: constant|discrete|continuous; independent: "
                     "continuous)");
    } else {
      const initial_rule rule = initial_rule_for(*v.caus, *v.var);
      if (initial_text != nullptr && rule.allowed.empty()) {
        out_.error("variable.initial", describe(v) + ": initial must not be given for causality " +
                                           std::string(name_of(*v.caus)));
      } else if (given_initial && std::find(rule.allowed.begin(), rule.allowed.end(),
                                            *given_initial) == rule.allowed.end()) {
        std::string allowed;
        for (initial_kind k : rule.allowed) {
          allowed += (allowed.empty() ? "" : "|") + std::string(name_of(k));
        }
        out_.error("variable.initial",
                   describe(v) + ": initial " + std::string(name_of(*given_initial)) +
                       " is not allowed for " + std::string(name_of(*v.caus)) + " " +
                       std::string(name_of(*v.var)) + " (allowed: " + allowed + ")");
      }
      if (initial_text == nullptr) v.initial = rule.default_value;
    }
  }

  if (v.var == variability::continuous && !v.type.empty() && v.type != "Real") {
    out_.error("variable.continuous_non_real",
               describe(v) + ": a " + v.type + " variable cannot be continuous" +
                   (variability_text == nullptr ? " (continuous is the default variability)" : ""));
  }
  if (v.caus == causality::independent && !v.type.empty() && v.type != "Real") {
    out_.error("variable.independent",
               describe(v) + ": the independent variable must be a Real, not " + v.type);
  }

  if (v.type_element != nullptr) {
    const bool required = v.initial == initial_kind::exact || v.initial == initial_kind::approx ||
                          v.caus == causality::input || v.var == variability::constant;
    const bool forbidden =
        v.initial == initial_kind::calculated || v.caus == causality::independent;
    if (required && !v.has_start) {
      std::string why;
      if (v.caus == causality::input) {
        why = "an input";
      } else if (v.var == variability::constant) {
        why = "a constant";
      } else {
        why = "initial=" + std::string(name_of(*v.initial)) +
              (initial_text == nullptr ? " (the default for " + std::string(name_of(*v.caus)) +
                                             " " + std::string(name_of(*v.var)) + ")"
                                       : "");
      }
      out_.error("variable.start_required", describe(v) + ": start is required for " + why);
    } else if (forbidden && v.has_start) {
      std::string why = v.caus == causality::independent
                            ? std::string("causality independent")
                            : "initial=calculated" +
                                  (initial_text == nullptr ? std::string(" (the default)") : "");
      out_.error("variable.start_forbidden", describe(v) + ": start must not be given with " + why);
    }
    check_values(v);
  }
}

void model_description_checker::check_values(const variable& v) {
  const XMLElement& t = *v.type_element;
  const XMLElement* declared = nullptr;
  if (const char* dt = t.Attribute("declaredType")) {
    const auto it = simple_types_.find(std::string_view(dt));
    if (it != simple_types_.end() && it->second.type == v.type) declared = it->second.element;
  }
  // min/max fall back to the declared type, as the spec inherits them
  auto attribute = [&](const char* name, bool inherit) -> const char* {
    const char* text = t.Attribute(name);
    if (text == nullptr && inherit && declared != nullptr) text = declared->Attribute(name);
    return text;
  };
  auto bad_value = [&](const char* name, const char* text, std::string_view expected) {
    out_.error("variable.value",
               describe(v) + ": " + name + "=" + quote(text) + " is not " + std::string(expected));
  };

  if (v.type == "Real") {
    std::map<std::string, double> values;
    for (const char* name : {"start", "min", "max", "nominal"}) {
      const char* text = attribute(name, std::string_view(name) != "start");
      if (text == nullptr) continue;
      const auto d = detail::parse_xs_double(text);
      if (!d) {
        bad_value(name, text, "an xs:double");
      } else {
        values[name] = *d;
      }
    }
    for (const char* name : {"unbounded", "relativeQuantity", "reinit"}) {
      if (const char* text = t.Attribute(name); text != nullptr && !detail::parse_xs_boolean(text))
        bad_value(name, text, "an xs:boolean");
    }
    if (values.contains("nominal") && !(values["nominal"] > 0.0)) {
      out_.error("variable.value", describe(v) + ": nominal must be positive");
    }
    const bool has_min = values.contains("min");
    const bool has_max = values.contains("max");
    if (has_min && has_max && values["min"] > values["max"]) {
      out_.error("variable.range", describe(v) + ": min " + std::to_string(values["min"]) +
                                       " > max " + std::to_string(values["max"]));
    }
    if (values.contains("start")) {
      const double s = values["start"];
      if (std::isnan(s)) {
        out_.error("variable.value", describe(v) + ": start is NaN");
      } else if ((has_min && s < values["min"]) || (has_max && s > values["max"])) {
        out_.error("variable.range",
                   describe(v) + ": start " + std::to_string(s) + " is outside [min, max]");
      }
    }
  } else if (v.type == "Integer" || v.type == "Enumeration") {
    std::map<std::string, std::int32_t> values;
    for (const char* name : {"start", "min", "max"}) {
      const char* text = attribute(name, std::string_view(name) != "start");
      if (text == nullptr) continue;
      const auto i = detail::parse_xs_int(text);
      if (!i) {
        bad_value(name, text, "an xs:int");
      } else {
        values[name] = *i;
      }
    }
    const bool has_min = values.contains("min");
    const bool has_max = values.contains("max");
    if (has_min && has_max && values["min"] > values["max"]) {
      out_.error("variable.range", describe(v) + ": min " + std::to_string(values["min"]) +
                                       " > max " + std::to_string(values["max"]));
    }
    if (values.contains("start")) {
      const std::int32_t s = values["start"];
      if ((has_min && s < values["min"]) || (has_max && s > values["max"])) {
        out_.error("variable.range",
                   describe(v) + ": start " + std::to_string(s) + " is outside [min, max]");
      }
    }
  } else if (v.type == "Boolean") {
    if (const char* text = t.Attribute("start"); text != nullptr && !detail::parse_xs_boolean(text))
      bad_value("start", text, "an xs:boolean (true|false)");
  }
  if (v.type == "Real") {
    if (const char* text = t.Attribute("derivative")) {
      const auto d = detail::parse_xs_unsigned_int(text);
      if (!d) bad_value("derivative", text, "an unsigned index");
    }
  }
}

void model_description_checker::check_aliases() {
  std::map<std::pair<std::string, std::uint32_t>, std::vector<const variable*>> groups;
  for (const variable& v : vars_) {
    if (v.vr && !v.type.empty()) groups[{v.type, *v.vr}].push_back(&v);
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
      out_.error("variable.alias_start",
                 describe(*with_start[1]) + ": " + key.first + " aliases with valueReference " +
                     std::to_string(key.second) + " have more than one start (" + names + ")");
    }
  }
}

void model_description_checker::check_derivative_attributes() {
  for (variable& v : vars_) {
    if (v.type != "Real") continue;
    const char* text = v.type_element->Attribute("derivative");
    if (text == nullptr) continue;
    const auto d = detail::parse_xs_unsigned_int(text);
    if (!d) continue;  // reported by check_values
    if (*d < 1 || *d > vars_.size()) {
      out_.error("variable.derivative", describe(v) + ": derivative=" + quote(text) +
                                            " is not an index in 1.." +
                                            std::to_string(vars_.size()));
    } else if (vars_[*d - 1].type != "Real") {
      out_.error("variable.derivative", describe(v) + ": derivative=" + quote(text) + " names " +
                                            quote(vars_[*d - 1].name) + ", which is not a Real");
    } else {
      v.derivative_of = *d;
    }
  }
}

void model_description_checker::check_array_names() {
  // name[k] with a single trailing index; structured names such as a[2].b are not grouped
  std::map<std::string, std::vector<std::pair<std::uint32_t, const variable*>>> groups;
  for (const variable& v : vars_) {
    const std::string& n = v.name;
    if (n.size() < 4 || n.back() != ']') continue;
    const auto open = n.rfind('[');
    if (open == std::string::npos || open == 0) continue;
    const std::string_view digits(n.data() + open + 1, n.size() - open - 2);
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos) {
      continue;
    }
    const auto k = detail::parse_xs_unsigned_int(digits);
    if (!k) continue;
    groups[n.substr(0, open)].emplace_back(*k, &v);
  }
  for (auto& [base, members] : groups) {
    std::sort(members.begin(), members.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t i = 0; i < members.size(); ++i) {
      if (members[i].first != i + 1) {
        const std::string expected = std::to_string(i + 1);
        out_.warning("variable.array_index",
                     describe(*members[i].second) + ": array " + quote(base) +
                         " should have contiguous 1-based indices; expected " + base + "[" +
                         expected + "]");
        break;
      }
    }
  }
}

void model_description_checker::check_model_structure(const XMLElement* ms) {
  if (ms == nullptr) {
    out_.error("structure.model_structure", "there is no <ModelStructure> element");
    return;
  }
  check_child_order(*ms, {"Outputs", "Derivatives", "InitialUnknowns"});
  if (vars_.empty()) return;

  // Outputs: exactly the output variables, in ModelVariables order
  std::vector<std::size_t> outputs;
  if (const XMLElement* o = ms->FirstChildElement("Outputs")) {
    outputs = check_unknowns(*o, "outputs", false);
    std::set<std::size_t> seen;
    std::size_t previous = 0;
    for (std::size_t index : outputs) {
      const variable& v = vars_[index - 1];
      if (v.caus != causality::output) {
        out_.error("outputs.not_output",
                   describe(v) + ": listed in <Outputs> but its causality is " +
                       (v.caus ? std::string(name_of(*v.caus)) : std::string("invalid")));
      }
      if (!seen.insert(index).second) {
        out_.error("outputs.order", describe(v) + ": listed twice in <Outputs>");
      } else if (index < previous) {
        out_.error("outputs.order", describe(v) + ": <Outputs> is not in ModelVariables order");
      }
      previous = std::max(previous, index);
    }
  }
  const std::set<std::size_t> listed_outputs(outputs.begin(), outputs.end());
  for (const variable& v : vars_) {
    if (v.caus == causality::output && !listed_outputs.contains(v.index)) {
      out_.error("outputs.missing", describe(v) +
                                        ": an output missing from "
                                        "<ModelStructure><Outputs>");
    }
  }

  // Derivatives: Real variables with a derivative attribute
  const XMLElement* derivatives_element = ms->FirstChildElement("Derivatives");
  std::vector<std::size_t> derivatives;
  if (derivatives_element != nullptr) {
    derivatives = check_unknowns(*derivatives_element, "derivatives", false);
    for (std::size_t index : derivatives) {
      const variable& v = vars_[index - 1];
      if (!v.derivative_of) {
        out_.error("derivatives.index",
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
  for (const variable& v : vars_) {
    if (v.caus == causality::output && approx_or_calculated(v)) required.insert(v.index);
    if (v.caus == causality::calculated_parameter) required.insert(v.index);
  }
  for (std::size_t index : derivatives) {
    const variable& d = vars_[index - 1];
    if (approx_or_calculated(d)) required.insert(index);
    if (d.derivative_of && approx_or_calculated(vars_[*d.derivative_of - 1])) {
      required.insert(*d.derivative_of);
    }
  }
  std::vector<std::size_t> initial_unknowns;
  const XMLElement* iu = ms->FirstChildElement("InitialUnknowns");
  if (iu != nullptr) {
    initial_unknowns = check_unknowns(*iu, "initial_unknowns", true);
    std::size_t previous = 0;
    std::set<std::size_t> seen;
    for (std::size_t index : initial_unknowns) {
      const variable& v = vars_[index - 1];
      if (!seen.insert(index).second) {
        out_.error("initial_unknowns.order", describe(v) + ": listed twice in <InitialUnknowns>");
      } else if (index < previous) {
        out_.error("initial_unknowns.order",
                   describe(v) + ": <InitialUnknowns> is not sorted by index");
      }
      previous = std::max(previous, index);
      if (!required.contains(index)) {
        out_.error("initial_unknowns.extra",
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
      const variable& v = vars_[index - 1];
      out_.error("initial_unknowns.missing",
                 describe(v) + ": must be listed in <ModelStructure><InitialUnknowns> (" +
                     (v.caus ? std::string(name_of(*v.caus)) : std::string("?")) +
                     " with initial " + (v.initial ? std::string(name_of(*v.initial)) : "?") + ")");
    }
  }
}

std::vector<std::size_t> model_description_checker::check_unknowns(const XMLElement& list,
                                                                   std::string_view rule_prefix,
                                                                   bool initial_unknowns) {
  const std::string index_rule = std::string(rule_prefix) + ".index";
  std::vector<std::size_t> indices;
  for (const XMLElement* u = list.FirstChildElement(); u != nullptr; u = u->NextSiblingElement()) {
    if (std::string_view(u->Name()) != "Unknown") {
      out_.error("structure.child_order",
                 at(*u) + ": unexpected element <" + u->Name() + "> in <" + list.Name() + ">");
      continue;
    }
    check_attributes(*u, {"index", "dependencies", "dependenciesKind"});
    const std::string where = at(*u) + ": <" + list.Name() + "><Unknown>";
    const char* text = u->Attribute("index");
    if (text == nullptr) {
      out_.error(index_rule, where + " has no index");
      continue;
    }
    const auto index = detail::parse_xs_unsigned_int(text);
    if (!index) {
      out_.error(index_rule, where + " index " + quote(text) + " is not an unsigned integer");
      continue;
    }
    if (*index == 0) {
      out_.error(index_rule, where +
                                 " index 0 is invalid: indices are 1-based positions in "
                                 "<ModelVariables>");
      continue;
    }
    if (*index > vars_.size()) {
      std::string hint;
      for (const variable& v : vars_) {
        if (v.vr == *index) {
          hint = " (is it the valueReference of " + quote(v.name) +
                 "? indices are positions in <ModelVariables>, not valueReferences)";
          break;
        }
      }
      out_.error(index_rule, where + " index " + std::to_string(*index) + " is out of range 1.." +
                                 std::to_string(vars_.size()) + hint);
      continue;
    }
    check_dependencies(*u, where, initial_unknowns);
    indices.push_back(*index);
  }
  return indices;
}

void model_description_checker::check_dependencies(const XMLElement& unknown,
                                                   std::string_view where, bool initial_unknowns) {
  const char* deps_text = unknown.Attribute("dependencies");
  const char* kinds_text = unknown.Attribute("dependenciesKind");
  const std::string prefix(where);
  std::size_t dependency_count = 0;
  if (deps_text != nullptr) {
    const auto parts = detail::split_ws(deps_text);
    dependency_count = parts.size();
    std::uint64_t previous = 0;
    for (std::string_view p : parts) {
      const auto d = detail::parse_xs_unsigned_int(p);
      if (!d || *d == 0 || *d > vars_.size()) {
        out_.error("dependencies.index", prefix + " dependency " + quote(p) +
                                             " is not an index in 1.." +
                                             std::to_string(vars_.size()));
        continue;
      }
      if (*d <= previous) {
        out_.error("dependencies.order", prefix + " dependencies " + quote(deps_text) +
                                             " are not sorted ascending without duplicates");
        break;
      }
      previous = *d;
    }
  }
  if (kinds_text == nullptr) return;
  const auto kinds = detail::split_ws(kinds_text);
  if (deps_text == nullptr) {
    out_.error("dependencies.kind", prefix + " has dependenciesKind without dependencies");
  } else if (kinds.size() != dependency_count) {
    out_.error("dependencies.kind", prefix + " has " + std::to_string(dependency_count) +
                                        " dependencies but " + std::to_string(kinds.size()) +
                                        " dependenciesKind entries");
  }
  for (std::string_view k : kinds) {
    if (initial_unknowns) {
      if (k != "dependent" && k != "constant") {
        out_.error("initial_unknowns.kind", prefix + " dependenciesKind " + quote(k) +
                                                " is not allowed in InitialUnknowns "
                                                "(dependent|constant)");
      }
    } else if (k != "dependent" && k != "constant" && k != "fixed" && k != "tunable" &&
               k != "discrete") {
      out_.error("dependencies.kind",
                 prefix + " dependenciesKind " + quote(k) +
                     " is not one of dependent, constant, fixed, tunable, discrete");
    }
  }
}

void model_description_checker::check_archive() {
  if (archive_ == nullptr) return;
  // FMI 3 platform tuples for platforms that have an FMI 2 name are not searched by FMI 2 tools
  static const std::map<std::string_view, std::string_view> k_fmi3_tuples = {
      {"x86_64-linux", "linux64"},
      {"x86-linux", "linux32"},
      {"x86_64-windows", "win64"},
      {"x86-windows", "win32"},
      {"x86_64-darwin", "darwin64"}};
  std::set<std::string, std::less<>> reported;
  for (const std::string& entry : *archive_) {
    if (!entry.starts_with("binaries/")) continue;
    const std::string_view rest = std::string_view(entry).substr(9);
    const auto slash = rest.find('/');
    if (slash == std::string_view::npos) continue;
    const std::string_view dir = rest.substr(0, slash);
    const auto it = k_fmi3_tuples.find(dir);
    if (it != k_fmi3_tuples.end() && reported.emplace(dir).second) {
      out_.error("archive.platform_dir", "binaries/" + std::string(dir) +
                                             "/ is an FMI 3 platform tuple; FMI 2 importers "
                                             "only look in binaries/" +
                                             std::string(it->second) + "/");
    }
  }
  if (model_identifier_.empty()) return;
  const std::string binary = "binaries/linux64/" + model_identifier_ + ".so";
  if (std::find(archive_->begin(), archive_->end(), binary) == archive_->end()) {
    std::string hint;
    for (const std::string& entry : *archive_) {
      if (entry.starts_with("binaries/") && entry.ends_with(".so")) {
        hint += (hint.empty() ? " (found: " : ", ") + entry;
      }
    }
    if (!hint.empty()) hint += ")";
    out_.error("archive.binary", "the archive has no " + binary +
                                     " (named after CoSimulation@modelIdentifier)" + hint);
  }
}

}  // namespace

std::vector<finding> check_model_description(std::string_view xml, const archive_listing* archive) {
  detail::reporter out;
  model_description_checker checker(out, archive);
  checker.run(xml);
  return out.take();
}

}  // namespace stride::fmi_check
