// The OSP writer (docs/ssp.md, "Export"): OspSystemStructure.xml (version 0.1) and the FMUs
// beside it, as osp_import.cpp reads them. OSP has step multiples (a simulator's stepSize) but
// no delayed connections, no linear transformations Stride reads and one algorithm, so those
// are refused.
#include <algorithm>
#include <fstream>

#include "export_plan.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/system_builder.hpp"
#include "stride/cosim/system_export.hpp"

namespace stride::cosim {

namespace fs = std::filesystem;
using tinyxml2::XMLElement;

namespace {

constexpr const char* k_osp_file = "OspSystemStructure.xml";
constexpr std::string_view k_format = "OSP";

// what OSP cannot say and the OSP importer would not give back
void check_osp(const detail::export_plan& plan) {
  const system_structure& s = plan.system();
  if (s.algorithm == algorithm_kind::jacobi) {
    detail::refuse_export(k_format, s.where,
                          "the jacobi algorithm (the OSP importer steps Gauss-Seidel; its "
                          "Algorithm fixedStep names no order)");
  }
  const auto& components = plan.components();
  for (const auto& c : plan.connections()) {
    const std::string name = components[c.from].spec->name + "." +
                             components[c.from].description->variables[c.from_variable].name +
                             " -> " + components[c.to].spec->name + "." +
                             components[c.to].description->variables[c.to_variable].name;
    if (c.delayed) {
      detail::refuse_export(
          k_format, c.where,
          "the delayed connection " + name + " (OSP has no delay; SSP export keeps it)");
    }
    if (c.factor != 1.0 || c.offset != 0.0) {
      detail::refuse_export(k_format, c.where,
                            "the factor or offset of " + name +
                                " (OSP's Functions are not read by Stride; SSP export keeps it)");
    }
  }
}

// the system's base step as the build takes it
duration base_step(const detail::export_plan& plan) {
  const std::optional<duration> step = plan.base_step();
  if (!step) {
    detail::refuse_export(k_format, plan.system().where,
                          "no base step (give <simulation step>; no FMU declares a "
                          "DefaultExperiment stepSize)");
  }
  return *step;
}

void add_text(XMLElement* parent, const char* name, const std::string& text) {
  parent->InsertNewChildElement(name)->SetText(text.c_str());
}

// Real, Integer, Boolean or String: enumerations are Integer values in OSP as in Stride
const char* value_element(variable_type t) {
  switch (exchange_type(t)) {
    case variable_type::real:
      return "Real";
    case variable_type::boolean:
      return "Boolean";
    case variable_type::string:
      return "String";
    default:
      return "Integer";
  }
}

void write_simulators(XMLElement* simulators, const detail::export_plan& plan, duration step) {
  for (const auto& c : plan.components()) {
    XMLElement* x = simulators->InsertNewChildElement("Simulator");
    x->SetAttribute("name", c.spec->name.c_str());
    x->SetAttribute("source", detail::uri_path(plan.fmus()[c.fmu].name).c_str());
    if (c.spec->step_multiple != 1) {
      x->SetAttribute("stepSize", format_seconds(step * c.spec->step_multiple).c_str());
    }
    if (c.values.empty()) continue;
    XMLElement* values = x->InsertNewChildElement("InitialValues");
    for (const auto& v : c.values) {
      XMLElement* e = values->InsertNewChildElement("InitialValue");
      e->SetAttribute("variable", v.variable->name.c_str());
      e->InsertNewChildElement(value_element(v.variable->type))
          ->SetAttribute("value", v.text.c_str());
    }
  }
}

void write_connections(XMLElement* connections, const detail::export_plan& plan) {
  const auto& components = plan.components();
  for (const auto& c : plan.connections()) {
    XMLElement* x = connections->InsertNewChildElement("VariableConnection");
    for (const auto& [component, variable] :
         {std::pair{c.from, c.from_variable}, std::pair{c.to, c.to_variable}}) {
      XMLElement* v = x->InsertNewChildElement("Variable");
      v->SetAttribute("simulator", components[component].spec->name.c_str());
      v->SetAttribute("name", components[component].description->variables[variable].name.c_str());
    }
  }
}

std::string osp_text(const detail::export_plan& plan) {
  const system_structure& s = plan.system();
  const duration step = base_step(plan);
  tinyxml2::XMLDocument doc;
  doc.InsertEndChild(doc.NewDeclaration());
  XMLElement* root = doc.NewElement("OspSystemStructure");
  doc.InsertEndChild(root);
  root->SetAttribute("xmlns", "http://opensimulationplatform.com/MSMI/OSPSystemStructure");
  root->SetAttribute("version", "0.1");
  add_text(root, "StartTime", format_seconds(s.start));
  if (s.stop) add_text(root, "EndTime", format_seconds(*s.stop));
  add_text(root, "BaseStepSize", format_seconds(step));
  add_text(root, "Algorithm", "fixedStep");
  write_simulators(root->InsertNewChildElement("Simulators"), plan, step);
  if (!plan.connections().empty()) {
    write_connections(root->InsertNewChildElement("Connections"), plan);
  }
  return detail::xml_text(doc);
}

void write_file(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw validation_error(file.string() + ": cannot write the file");
}

}  // namespace

export_report export_osp(const system_structure& system, const fs::path& folder,
                         const export_options& options) {
  detail::check_export_target(folder, true, options.overwrite);
  const detail::export_plan plan(system, options.fmu_search_path, k_format);
  check_osp(plan);
  const std::string text = osp_text(plan);
  std::error_code error;
  fs::create_directories(folder, error);
  if (error)
    throw validation_error(folder.string() + ": cannot create the folder: " + error.message());
  export_report report{folder, {k_osp_file}};
  write_file(folder / k_osp_file, text);
  for (const auto& f : plan.fmus()) {
    report.files.push_back(f.name);
    if (fs::equivalent(f.file, folder / f.name, error)) continue;  // re-exported in place
    fs::copy_file(f.file, folder / f.name, fs::copy_options::overwrite_existing, error);
    if (error) {
      throw validation_error((folder / f.name).string() + ": cannot copy " + f.file.string() +
                             ": " + error.message());
    }
  }
  return report;
}

}  // namespace stride::cosim
