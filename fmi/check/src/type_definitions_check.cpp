// TypeDefinitions and the type element of each variable: SimpleType names, the attributes each
// base type may carry, declaredType (docs/fmi-rules.md §2.2).
#include "model_description_check.hpp"
#include "xs_values.hpp"

namespace stride::fmi_check::detail {

namespace {

const std::set<std::string_view>& type_attributes(fmi2::value_type t) {
  static const std::set<std::string_view> real = {
      "declaredType", "quantity", "unit",      "displayUnit", "relativeQuantity", "min",
      "max",          "nominal",  "unbounded", "start",       "derivative",       "reinit"};
  static const std::set<std::string_view> integer = {"declaredType", "quantity", "min", "max",
                                                     "start"};
  static const std::set<std::string_view> other = {"declaredType", "start"};
  switch (t) {
    case fmi2::value_type::real:
      return real;
    case fmi2::value_type::integer:
    case fmi2::value_type::enumeration:
      return integer;
    case fmi2::value_type::boolean:
    case fmi2::value_type::string:
      return other;
  }
  return other;
}

}  // namespace

void check_type_definitions(md_context& md, const XMLElement* td) {
  if (td == nullptr) return;
  for (const XMLElement* st = td->FirstChildElement(); st != nullptr;
       st = st->NextSiblingElement()) {
    if (std::string_view(st->Name()) != "SimpleType") {
      md.out.error("structure.child_order",
                   at(*st) + ": unexpected element <" + st->Name() + "> in <TypeDefinitions>");
      continue;
    }
    const char* name = st->Attribute("name");
    if (name == nullptr || trim(name).empty()) {
      md.out.error("type_definitions.name", at(*st) + ": <SimpleType> without a name");
      continue;
    }
    const XMLElement* base = st->FirstChildElement();
    while (base != nullptr && std::string_view(base->Name()) == "Annotations") {
      base = base->NextSiblingElement();
    }
    simple_type t{base != nullptr ? base->Name() : "", base};
    if (!md.simple_types.emplace(name, t).second) {
      md.out.error("type_definitions.name",
                   at(*st) + ": SimpleType name " + quote(name) + " is used twice");
    }
  }
}

void check_type_element(md_context& md, variable& v) {
  const std::string type(fmi2::to_string(*v.type));
  check_attributes(md.out, *v.type_element, type_attributes(*v.type));
  v.has_start = v.type_element->Attribute("start") != nullptr;
  const char* declared = v.type_element->Attribute("declaredType");
  if (v.type == fmi2::value_type::enumeration && declared == nullptr) {
    md.out.error("variable.type", describe(v) + ": an Enumeration needs a declaredType");
  }
  if (declared != nullptr) {
    const auto it = md.simple_types.find(std::string_view(declared));
    if (it == md.simple_types.end()) {
      md.out.error("variable.declared_type", describe(v) + ": declaredType " + quote(declared) +
                                                 " is not defined in <TypeDefinitions>");
    } else if (it->second.type != type) {
      md.out.error("variable.declared_type", describe(v) + ": declaredType " + quote(declared) +
                                                 " is a " + it->second.type + ", the variable a " +
                                                 type);
    }
  }
}

}  // namespace stride::fmi_check::detail
