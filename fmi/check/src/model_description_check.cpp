// modelDescription.xml rules of docs/fmi-rules.md §2.1 (archive ties) and §2.2: parses the
// text, then runs the checker of each rule family in document order. A description whose
// fmiVersion starts with "3." goes to the FMI 3.0 checkers (model_description_check3.cpp).
#include "model_description_check.hpp"

#include <algorithm>
#include <map>

#include "model_description_check3.hpp"
#include "xs_values.hpp"

namespace stride::fmi_check {

namespace detail {

std::string at(const XMLElement& e) {
  return "line " + std::to_string(e.GetLineNum());
}

std::string describe(const variable& v) {
  return "line " + std::to_string(v.line) + ": variable " + quote(v.name) + " (index " +
         std::to_string(v.index) + ")";
}

void check_attributes(reporter& out, const XMLElement& e, const std::set<std::string_view>& allowed,
                      std::string_view version) {
  // the capability flags both versions have, spelt differently
  static const std::map<std::string_view, std::string_view> k_spelt_in_3 = {
      {"canGetAndSetFMUState", "canGetAndSetFMUstate"},
      {"canSerializeFMUState", "canSerializeFMUstate"},
      {"providesDirectionalDerivatives", "providesDirectionalDerivative"}};
  for (const tinyxml2::XMLAttribute* a = e.FirstAttribute(); a != nullptr; a = a->Next()) {
    const std::string_view name = a->Name();
    if (allowed.contains(name) || name.starts_with("xmlns") || name.starts_with("xsi:")) continue;
    std::string message = at(e) + ": <" + e.Name() + "> has no attribute " + quote(name) +
                          " in FMI " + std::string(version);
    for (const auto& [spelling3, spelling2] : k_spelt_in_3) {
      if (version == "2.0" && name == spelling3) {
        message += " (FMI 3.0 spelling; FMI 2.0 writes " + std::string(spelling2) + ")";
      } else if (version == "3.0" && name == spelling2) {
        message += " (FMI 2.0 spelling; FMI 3.0 writes " + std::string(spelling3) + ")";
      }
    }
    out.error("schema.attribute", std::move(message));
  }
}

void check_child_order(reporter& out, const XMLElement& parent,
                       std::initializer_list<std::string_view> sequence) {
  const std::vector<std::string_view> order(sequence);
  std::ptrdiff_t last = -1;
  std::string_view last_name;
  for (const XMLElement* c = parent.FirstChildElement(); c != nullptr;
       c = c->NextSiblingElement()) {
    const std::string_view name = c->Name();
    const auto it = std::find(order.begin(), order.end(), name);
    if (it == order.end()) {
      out.error("structure.child_order", at(*c) + ": unexpected element <" + std::string(name) +
                                             "> in <" + parent.Name() + ">");
      continue;
    }
    const std::ptrdiff_t rank = it - order.begin();
    if (rank == last) {
      out.error("structure.child_order", at(*c) + ": <" + std::string(name) +
                                             "> occurs more than once in <" + parent.Name() + ">");
    } else if (rank < last) {
      out.error("structure.child_order", at(*c) + ": <" + std::string(name) +
                                             "> must come before <" + std::string(last_name) +
                                             "> in <" + parent.Name() + ">");
    } else {
      last = rank;
      last_name = name;
    }
  }
}

std::vector<finding> check_description(std::string_view xml, const archive_listing* archive,
                                       int* major_version, std::string* model_identifier) {
  reporter out;
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
    out.error("xml.well_formed", std::string("modelDescription.xml is not well-formed XML: ") +
                                     (doc.ErrorStr() != nullptr ? doc.ErrorStr() : "parse error"));
    return out.take();
  }
  const XMLElement* root = doc.RootElement();
  if (root == nullptr) {
    out.error("xml.well_formed", "modelDescription.xml has no root element");
    return out.take();
  }
  if (std::string_view(root->Name()) != "fmiModelDescription") {
    out.error("root.element", at(*root) + ": the root element is <" + root->Name() +
                                  ">, expected <fmiModelDescription>");
    return out.take();
  }
  if (const char* version = root->Attribute("fmiVersion");
      version != nullptr && std::string_view(version).starts_with("3.")) {
    if (major_version != nullptr) *major_version = 3;
    check_model_description3(out, *root, archive, model_identifier);
    return out.take();
  }
  if (major_version != nullptr) *major_version = 2;
  md_context md(out);
  check_root_attributes(md, *root);
  check_child_order(
      out, *root,
      {"ModelExchange", "CoSimulation", "UnitDefinitions", "TypeDefinitions", "LogCategories",
       "DefaultExperiment", "VendorAnnotations", "ModelVariables", "ModelStructure"});
  check_interfaces(md, *root);
  check_type_definitions(md, root->FirstChildElement("TypeDefinitions"));
  check_log_categories(md, root->FirstChildElement("LogCategories"));
  check_default_experiment(md, root->FirstChildElement("DefaultExperiment"));
  check_model_variables(md, root->FirstChildElement("ModelVariables"));
  check_model_structure(md, root->FirstChildElement("ModelStructure"));
  if (md.model_exchange) check_model_exchange_states(md, root->FirstChildElement("ModelStructure"));
  if (archive != nullptr) {
    check_archive_ties(out, *archive, md.model_identifier, md.me_model_identifier);
  }
  if (model_identifier != nullptr) *model_identifier = md.model_identifier;
  return out.take();
}

}  // namespace detail

std::vector<finding> check_model_description(std::string_view xml, const archive_listing* archive) {
  return detail::check_description(xml, archive, nullptr, nullptr);
}

}  // namespace stride::fmi_check
