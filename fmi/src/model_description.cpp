#include "stride/sdk/model_description.hpp"

#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include "model_description_parts.hpp"
#include "start_value.hpp"
#include "stride/common/text.hpp"

namespace stride::sdk {

std::string xml_number(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

void write_unit_definitions(std::ostringstream& xml, const std::set<std::string>& units) {
  if (units.empty()) return;
  xml << "  <UnitDefinitions>\n";
  for (const std::string& u : units) {
    xml << "    <Unit name=\"" << stride::text::xml_escape(u) << "\"/>\n";
  }
  xml << "  </UnitDefinitions>\n";
}

void write_log_categories(std::ostringstream& xml, const model_info& info) {
  xml << "  <LogCategories>\n"
      << "    <Category name=\"logStatusWarning\" description=\"Warnings\"/>\n"
      << "    <Category name=\"logStatusError\" description=\"Errors, including rejected "
         "calls\"/>\n"
      << "    <Category name=\"logStatusFatal\" description=\"Fatal errors\"/>\n"
      << "    <Category name=\"logEvents\" description=\"Lifecycle events of the instance\"/>\n"
      << "    <Category name=\"logCalls\" description=\"Every FMI function call\"/>\n";
  for (const auto& [name, description] : info.log_categories) {
    xml << "    <Category name=\"" << stride::text::xml_escape(name) << "\" description=\""
        << stride::text::xml_escape(description) << "\"/>\n";
  }
  xml << "  </LogCategories>\n";
}

void write_default_experiment(std::ostringstream& xml, const model_info& info) {
  xml << "  <DefaultExperiment startTime=\"0\"";
  if (info.default_stop_time > 0)
    xml << " stopTime=\"" << xml_number(info.default_stop_time) << '"';
  xml << " stepSize=\"" << xml_number(info.default_step_size) << "\"/>\n";
}

namespace {

using stride::text::xml_escape;  // unqualified: sdk::text is the FMI string type

void write_type_element(std::ostringstream& xml, const variable& v, const void* defaults) {
  xml << "      <" << to_string(v.type);
  if (v.has_start()) xml << " start=\"" << xml_escape(format_start_value(v, defaults)) << '"';
  if (v.type == value_type::real && !v.unit.empty()) xml << " unit=\"" << xml_escape(v.unit) << '"';
  if (v.type == value_type::real || v.type == value_type::integer) {
    if (v.has_min) xml << " min=\"" << xml_number(v.min) << '"';
    if (v.has_max) xml << " max=\"" << xml_number(v.max) << '"';
  }
  xml << "/>\n";
}

}  // namespace

std::string write_model_description(const fmu_definition& fmu, const std::string& generation_time) {
  const model_info& info = fmu.info;
  const variable_table& table = fmu.table;
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"" << xml_escape(info.model_name)
      << "\" guid=\"" << compute_guid(fmu) << "\" description=\"" << xml_escape(info.description)
      << "\" author=\"" << xml_escape(info.author) << "\" version=\"" << xml_escape(info.version)
      << "\" generationTool=\"Stride component SDK\"";
  if (!generation_time.empty()) xml << " generationDateAndTime=\"" << generation_time << '"';
  xml << " variableNamingConvention=\"structured\" numberOfEventIndicators=\"0\">\n";

  xml << "  <CoSimulation modelIdentifier=\"" << xml_escape(info.model_identifier)
      << "\" canHandleVariableCommunicationStepSize=\"true\" canGetAndSetFMUstate=\"true\""
         " canSerializeFMUstate=\"true\" canNotUseMemoryManagementFunctions=\"true\"/>\n";

  std::set<std::string> units;
  for (const variable& v : table.variables()) {
    if (v.type == value_type::real && !v.unit.empty()) units.insert(v.unit);
  }
  write_unit_definitions(xml, units);
  write_log_categories(xml, info);
  write_default_experiment(xml, info);

  xml << "  <ModelVariables>\n";
  for (const variable& v : table.variables()) {
    xml << "    <ScalarVariable name=\"" << xml_escape(v.name) << "\" valueReference=\""
        << v.value_reference << "\" causality=\"" << to_string(v.causality_kind)
        << "\" variability=\"" << to_string(v.variability_kind) << '"';
    if (v.initial != initial_kind::none) xml << " initial=\"" << to_string(v.initial) << '"';
    if (!v.description.empty()) xml << " description=\"" << xml_escape(v.description) << '"';
    xml << ">\n";
    write_type_element(xml, v, table.defaults());
    xml << "    </ScalarVariable>\n";
  }
  xml << "  </ModelVariables>\n";

  xml << "  <ModelStructure>\n";
  std::ostringstream outputs;
  std::ostringstream initial_unknowns;
  for (const variable& v : table.variables()) {
    const std::size_t index = table.index_of(v);
    if (v.causality_kind == causality::output) {
      std::set<std::size_t> dependencies;
      for (std::uint32_t vr : v.direct_dependencies) {
        dependencies.insert(table.index_of(*table.find(vr)));
      }
      std::string deps, kinds;
      for (std::size_t d : dependencies) {
        if (!deps.empty()) {
          deps += ' ';
          kinds += ' ';
        }
        deps += std::to_string(d);
        kinds += "dependent";
      }
      outputs << "      <Unknown index=\"" << index << "\" dependencies=\"" << deps << '"';
      if (!kinds.empty()) outputs << " dependenciesKind=\"" << kinds << '"';
      outputs << "/>\n";
    }
    const bool calculated_output =
        v.causality_kind == causality::output &&
        (v.initial == initial_kind::calculated || v.initial == initial_kind::approx);
    if (calculated_output || v.causality_kind == causality::calculated_parameter) {
      initial_unknowns << "      <Unknown index=\"" << index << "\"/>\n";
    }
  }
  if (!outputs.str().empty()) xml << "    <Outputs>\n" << outputs.str() << "    </Outputs>\n";
  if (!initial_unknowns.str().empty()) {
    xml << "    <InitialUnknowns>\n" << initial_unknowns.str() << "    </InitialUnknowns>\n";
  }
  xml << "  </ModelStructure>\n</fmiModelDescription>\n";
  return xml.str();
}

}  // namespace stride::sdk
