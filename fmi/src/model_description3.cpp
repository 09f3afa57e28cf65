// modelDescription.xml for FMI 3.0 (docs/fmi3-rules.md §5), from the same table as 2.0.
#include <set>
#include <sstream>

#include "fmi3_variables.hpp"
#include "model_description_parts.hpp"
#include "start_value.hpp"
#include "stride/common/text.hpp"
#include "stride/sdk/model_description.hpp"

namespace stride::sdk {
namespace {

using stride::text::xml_escape;  // unqualified: sdk::text is the FMI string type

const char* fmi3_type_name(value_type t) {
  switch (t) {
    case value_type::real:
      return "Float64";
    case value_type::integer:
    case value_type::enumeration:
      return "Int32";
    case value_type::boolean:
      return "Boolean";
    case value_type::string:
      return "String";
  }
  return "?";
}

// Every element's start value, space-separated in element order (String uses <Start> children).
std::string start_list(const fmi3_variable& v, const void* defaults) {
  std::string out;
  for (std::size_t k = 0; k < v.count; ++k) {
    if (k > 0) out += ' ';
    out += format_start_value(v.element(k), defaults);
  }
  return out;
}

void write_variable(std::ostringstream& xml, const fmi3_variable& v, const void* defaults) {
  const variable& e = v.element(0);
  const char* type = fmi3_type_name(e.type);
  xml << "    <" << type << " name=\"" << xml_escape(v.name) << "\" valueReference=\""
      << v.value_reference << "\" causality=\"" << to_string(e.causality_kind)
      << "\" variability=\"" << to_string(e.variability_kind) << '"';
  if (e.initial != initial_kind::none) xml << " initial=\"" << to_string(e.initial) << '"';
  if (!e.description.empty()) xml << " description=\"" << xml_escape(e.description) << '"';
  if (e.type == value_type::real && !e.unit.empty()) xml << " unit=\"" << xml_escape(e.unit) << '"';
  if (e.type == value_type::real || e.type == value_type::integer) {
    if (e.has_min) xml << " min=\"" << xml_number(e.min) << '"';
    if (e.has_max) xml << " max=\"" << xml_number(e.max) << '"';
  }
  const bool string_starts = e.has_start() && e.type == value_type::string;
  if (e.has_start() && !string_starts) {
    xml << " start=\"" << xml_escape(start_list(v, defaults)) << '"';
  }
  if (!v.is_array && !string_starts) {
    xml << "/>\n";
    return;
  }
  xml << ">\n";
  if (v.is_array) xml << "      <Dimension start=\"" << v.count << "\"/>\n";
  for (std::size_t k = 0; string_starts && k < v.count; ++k) {
    xml << "      <Start value=\"" << xml_escape(format_start_value(v.element(k), defaults))
        << "\"/>\n";
  }
  xml << "    </" << type << ">\n";
}

// <Output> entries list the inputs they depend on by the FMI 3.0 value reference of the input
// (an array's, for an element), each dependency once.
void write_model_structure(std::ostringstream& xml, const fmi3_variables& vars,
                           const variable_table& table) {
  xml << "  <ModelStructure>\n";
  for (const fmi3_variable& v : vars.all()) {
    if (v.is_time() || v.element(0).causality_kind != causality::output) continue;
    std::set<std::uint32_t> dependencies;
    for (std::size_t k = 0; k < v.count; ++k) {
      for (std::uint32_t vr : v.element(k).direct_dependencies) {
        dependencies.insert(vars.owner(*table.find(vr)).value_reference);
      }
    }
    std::string deps, kinds;
    for (std::uint32_t d : dependencies) {
      if (!deps.empty()) {
        deps += ' ';
        kinds += ' ';
      }
      deps += std::to_string(d);
      kinds += "dependent";
    }
    xml << "    <Output valueReference=\"" << v.value_reference << "\" dependencies=\"" << deps
        << '"';
    if (!kinds.empty()) xml << " dependenciesKind=\"" << kinds << '"';
    xml << "/>\n";
  }
  for (const fmi3_variable& v : vars.all()) {
    if (v.is_time()) continue;
    const variable& e = v.element(0);
    const bool calculated_output =
        e.causality_kind == causality::output &&
        (e.initial == initial_kind::calculated || e.initial == initial_kind::approx);
    if (calculated_output || e.causality_kind == causality::calculated_parameter) {
      xml << "    <InitialUnknown valueReference=\"" << v.value_reference << "\"/>\n";
    }
  }
  xml << "  </ModelStructure>\n";
}

}  // namespace

std::string write_model_description3(const fmu_definition& fmu,
                                     const std::string& generation_time) {
  const model_info& info = fmu.info;
  const variable_table& table = fmu.table;
  const fmi3_variables vars(table);
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<fmiModelDescription fmiVersion=\"3.0\" modelName=\"" << xml_escape(info.model_name)
      << "\" instantiationToken=\"" << compute_guid(fmu) << "\" description=\""
      << xml_escape(info.description) << "\" author=\"" << xml_escape(info.author)
      << "\" version=\"" << xml_escape(info.version)
      << "\" generationTool=\"Stride component SDK\"";
  if (!generation_time.empty()) xml << " generationDateAndTime=\"" << generation_time << '"';
  xml << " variableNamingConvention=\"structured\">\n";

  // what is not offered is declared so, although false is the default
  xml << "  <CoSimulation modelIdentifier=\"" << xml_escape(info.model_identifier)
      << "\" canHandleVariableCommunicationStepSize=\"true\" canGetAndSetFMUState=\"true\""
         " canSerializeFMUState=\"true\" hasEventMode=\"false\""
         " providesIntermediateUpdate=\"false\" mightReturnEarlyFromDoStep=\"false\""
         " canReturnEarlyAfterIntermediateUpdate=\"false\"/>\n";

  std::set<std::string> units = {"s"};
  for (const variable& v : table.variables()) {
    if (v.type == value_type::real && !v.unit.empty()) units.insert(v.unit);
  }
  write_unit_definitions(xml, units);
  write_log_categories(xml, info);
  write_default_experiment(xml, info);

  xml << "  <ModelVariables>\n";
  xml << "    <Float64 name=\"time\" valueReference=\"" << vars.time().value_reference
      << "\" causality=\"independent\" variability=\"continuous\""
         " description=\"Simulation time\" unit=\"s\"/>\n";
  for (const fmi3_variable& v : vars.all()) {
    if (!v.is_time()) write_variable(xml, v, table.defaults());
  }
  xml << "  </ModelVariables>\n";
  write_model_structure(xml, vars, table);
  xml << "</fmiModelDescription>\n";
  return xml.str();
}

}  // namespace stride::sdk
