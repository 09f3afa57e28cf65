#include "stride/cosim/model_description.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <unordered_set>

#include "fmi3_model_description.hpp"
#include "md_reader_base.hpp"
#include "stride/common/files.hpp"
#include "stride/common/text.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "xml_util.hpp"

namespace stride::cosim {

const variable_description* model_description::find(std::string_view name) const noexcept {
  for (const auto& v : variables) {
    if (v.name == name) return &v;
  }
  return nullptr;
}

std::optional<std::size_t> model_description::index_of(std::string_view name) const noexcept {
  for (std::size_t i = 0; i < variables.size(); ++i) {
    if (variables[i].name == name) return i;
  }
  return std::nullopt;
}

bool model_description::has_feedthrough(std::size_t output_index,
                                        std::size_t input_index) const noexcept {
  for (const auto& o : outputs) {
    if (o.output != output_index) continue;
    if (!o.dependencies) return true;
    return std::find(o.dependencies->begin(), o.dependencies->end(), input_index) !=
           o.dependencies->end();
  }
  return true;
}

namespace {

using detail::attribute;
using detail::attribute_or;

struct md_reader : detail::md_reader_base {
  // An absent attribute takes `fallback`; a misspelt one is an error.
  template <class Enum>
  Enum parse_enum(const tinyxml2::XMLElement* e, const char* name, Enum fallback,
                  std::optional<Enum> (*parse)(std::string_view) noexcept) const {
    const char* v = e->Attribute(name);
    if (v == nullptr) return fallback;
    if (const auto value = parse(v)) return *value;
    fail(e->GetLineNum(), std::string("unknown ") + name + " \"" + v + "\"");
  }

  model_description read(const tinyxml2::XMLDocument& doc) const {
    const auto* root = doc.RootElement();
    if (root == nullptr || std::string_view(root->Name()) != "fmiModelDescription") {
      fail(root ? root->GetLineNum() : 0, "root element is not <fmiModelDescription>");
    }
    model_description md;
    md.fmi_version = attribute_or(root, "fmiVersion");
    if (md.fmi_version != "2.0") {
      fail(root->GetLineNum(), "fmiVersion is \"" + md.fmi_version +
                                   "\"; only FMI 2.0 Co-Simulation FMUs are supported");
    }
    md.model_name = attribute_or(root, "modelName");
    md.guid = attribute_or(root, "guid");
    if (md.guid.empty()) fail(root->GetLineNum(), "missing or empty guid");
    md.description = attribute_or(root, "description");
    md.author = attribute_or(root, "author");
    md.version = attribute_or(root, "version");
    md.generation_tool = attribute_or(root, "generationTool");
    md.generation_date_and_time = attribute_or(root, "generationDateAndTime");

    md.has_model_exchange = root->FirstChildElement("ModelExchange") != nullptr;
    if (const auto* me = root->FirstChildElement("ModelExchange")) {
      md.model_exchange = read_model_exchange(me);
    }
    if (root->Attribute("numberOfEventIndicators") != nullptr) {
      const auto n = text::parse_integer(attribute_or(root, "numberOfEventIndicators"));
      if (!n || *n < 0) {
        fail(root->GetLineNum(), "numberOfEventIndicators=\"" +
                                     attribute_or(root, "numberOfEventIndicators") +
                                     "\" is not a non-negative integer");
      }
      md.number_of_event_indicators = static_cast<std::size_t>(*n);
    }
    if (const auto* cs = root->FirstChildElement("CoSimulation")) {
      cosim_capabilities cap;
      cap.model_identifier = attribute_or(cs, "modelIdentifier");
      if (cap.model_identifier.empty()) {
        fail(cs->GetLineNum(), "<CoSimulation> has no modelIdentifier");
      }
      cap.needs_execution_tool = parse_bool(cs, "needsExecutionTool", false);
      cap.can_handle_variable_communication_step_size =
          parse_bool(cs, "canHandleVariableCommunicationStepSize", false);
      cap.can_interpolate_inputs = parse_bool(cs, "canInterpolateInputs", false);
      cap.max_output_derivative_order = cs->IntAttribute("maxOutputDerivativeOrder", 0);
      cap.can_run_asynchronuously = parse_bool(cs, "canRunAsynchronuously", false);
      cap.can_be_instantiated_only_once_per_process =
          parse_bool(cs, "canBeInstantiatedOnlyOncePerProcess", false);
      cap.can_not_use_memory_management_functions =
          parse_bool(cs, "canNotUseMemoryManagementFunctions", false);
      cap.can_get_and_set_fmu_state = parse_bool(cs, "canGetAndSetFMUstate", false);
      cap.can_serialize_fmu_state = parse_bool(cs, "canSerializeFMUstate", false);
      cap.provides_directional_derivative = parse_bool(cs, "providesDirectionalDerivative", false);
      md.co_simulation = cap;
    }

    // units of declared types, so a Real without its own unit can inherit one
    std::map<std::string, std::string> type_units;
    if (const auto* types = root->FirstChildElement("TypeDefinitions")) {
      for (auto* st = types->FirstChildElement("SimpleType"); st != nullptr;
           st = st->NextSiblingElement("SimpleType")) {
        if (const auto* real = st->FirstChildElement("Real")) {
          type_units[attribute_or(st, "name")] = attribute_or(real, "unit");
        }
      }
    }

    if (const auto* de = root->FirstChildElement("DefaultExperiment")) {
      md.default_experiment.start_time = parse_double(de, "startTime");
      md.default_experiment.stop_time = parse_double(de, "stopTime");
      md.default_experiment.tolerance = parse_double(de, "tolerance");
      md.default_experiment.step_size = parse_double(de, "stepSize");
    }

    const auto* mv = root->FirstChildElement("ModelVariables");
    if (mv == nullptr) fail(root->GetLineNum(), "missing <ModelVariables>");
    std::unordered_set<std::string> names;
    for (auto* sv = mv->FirstChildElement("ScalarVariable"); sv != nullptr;
         sv = sv->NextSiblingElement("ScalarVariable")) {
      md.variables.push_back(read_variable(sv, type_units));
      if (!names.insert(md.variables.back().name).second) {
        fail(sv->GetLineNum(), "duplicate variable name \"" + md.variables.back().name + "\"");
      }
    }

    if (const auto* ms = root->FirstChildElement("ModelStructure")) {
      if (const auto* outs = ms->FirstChildElement("Outputs")) {
        for (auto* u = outs->FirstChildElement("Unknown"); u != nullptr;
             u = u->NextSiblingElement("Unknown")) {
          md.outputs.push_back(read_unknown(u, md.variables.size()));
        }
      }
      if (const auto* ders = ms->FirstChildElement("Derivatives")) read_derivatives(ders, md);
    }
    return md;
  }

  model_exchange_capabilities read_model_exchange(const tinyxml2::XMLElement* me) const {
    model_exchange_capabilities cap;
    cap.model_identifier = attribute_or(me, "modelIdentifier");
    if (cap.model_identifier.empty())
      fail(me->GetLineNum(), "<ModelExchange> has no modelIdentifier");
    cap.needs_execution_tool = parse_bool(me, "needsExecutionTool", false);
    cap.completed_integrator_step_not_needed =
        parse_bool(me, "completedIntegratorStepNotNeeded", false);
    cap.can_be_instantiated_only_once_per_process =
        parse_bool(me, "canBeInstantiatedOnlyOncePerProcess", false);
    cap.can_not_use_memory_management_functions =
        parse_bool(me, "canNotUseMemoryManagementFunctions", false);
    cap.can_get_and_set_fmu_state = parse_bool(me, "canGetAndSetFMUstate", false);
    cap.can_serialize_fmu_state = parse_bool(me, "canSerializeFMUstate", false);
    cap.provides_directional_derivative = parse_bool(me, "providesDirectionalDerivative", false);
    return cap;
  }

  // Each listed derivative must be a Real whose derivative attribute names a Real state.
  void read_derivatives(const tinyxml2::XMLElement* ders, model_description& md) const {
    for (auto* u = ders->FirstChildElement("Unknown"); u != nullptr;
         u = u->NextSiblingElement("Unknown")) {
      const std::size_t d = read_unknown(u, md.variables.size()).output;
      const auto& v = md.variables[d];
      if (v.type != variable_type::real || !v.derivative_of) {
        fail(u->GetLineNum(), "Derivatives lists \"" + v.name +
                                  "\", which is not a Real with a derivative attribute");
      }
      md.derivatives.push_back(d);
    }
    for (const auto& v : md.variables) {
      if (v.derivative_of && *v.derivative_of >= md.variables.size()) {
        fail(v.line, "variable \"" + v.name + "\": derivative=\"" +
                         std::to_string(*v.derivative_of + 1) +
                         "\" is not a variable position 1.." + std::to_string(md.variables.size()));
      }
    }
  }

  std::size_t parse_index(const std::string& token, int line, std::size_t count) const {
    std::size_t value = 0;
    auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size() || value < 1 || value > count) {
      fail(line, "ModelStructure index \"" + token + "\" is not a variable position 1.." +
                     std::to_string(count));
    }
    return value - 1;
  }

  output_dependency read_unknown(const tinyxml2::XMLElement* u, std::size_t count) const {
    output_dependency dep;
    const auto index = attribute(u, "index");
    if (!index) fail(u->GetLineNum(), "<Unknown> without index");
    dep.output = parse_index(*index, u->GetLineNum(), count);
    if (const auto deps = attribute(u, "dependencies")) {
      dep.dependencies.emplace();
      std::istringstream in(*deps);
      std::string token;
      while (in >> token) dep.dependencies->push_back(parse_index(token, u->GetLineNum(), count));
    }
    return dep;
  }

  variable_description read_variable(const tinyxml2::XMLElement* sv,
                                     const std::map<std::string, std::string>& type_units) const {
    variable_description v;
    v.line = sv->GetLineNum();
    v.name = attribute_or(sv, "name");
    if (v.name.empty()) fail(v.line, "<ScalarVariable> without name");
    const auto vr = attribute(sv, "valueReference");
    if (!vr) fail(v.line, "variable \"" + v.name + "\" has no valueReference");
    auto [end, ec] = std::from_chars(vr->data(), vr->data() + vr->size(), v.reference);
    if (ec != std::errc() || end != vr->data() + vr->size()) {
      fail(v.line, "variable \"" + v.name + "\": valueReference \"" + *vr +
                       "\" is not an unsigned integer");
    }
    v.description = attribute_or(sv, "description");
    v.causality = parse_enum(sv, "causality", causality::local, fmi2::parse_causality);
    v.variability = parse_enum(sv, "variability", variability::continuous, fmi2::parse_variability);
    v.initial = parse_enum(sv, "initial", initial_kind::none, fmi2::parse_initial_kind);

    const tinyxml2::XMLElement* type_element = nullptr;
    for (auto* child = sv->FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement()) {
      const std::string_view tag = child->Name();
      const std::optional<variable_type> t = fmi2::parse_value_type(tag);
      if (!t) continue;
      if (type_element != nullptr) fail(v.line, "variable \"" + v.name + "\" has two types");
      type_element = child;
      v.type = *t;
    }
    if (type_element == nullptr) {
      fail(v.line, "variable \"" + v.name + "\" has no type element (Real, Integer, ...)");
    }
    v.start = attribute(type_element, "start");
    v.min = attribute(type_element, "min");
    v.max = attribute(type_element, "max");
    v.declared_type = attribute_or(type_element, "declaredType");
    v.unit = attribute_or(type_element, "unit");
    if (const auto d = attribute(type_element, "derivative")) {
      const auto n = text::parse_integer(*d);
      if (!n || *n < 1)
        fail(v.line,
             "variable \"" + v.name + "\": derivative=\"" + *d + "\" is not a variable position");
      v.derivative_of = static_cast<std::size_t>(*n - 1);
    }
    if (v.unit.empty() && !v.declared_type.empty()) {
      if (auto it = type_units.find(v.declared_type); it != type_units.end()) v.unit = it->second;
    }
    return v;
  }
};

model_description parse(const tinyxml2::XMLDocument& doc, const std::string& origin) {
  md_reader reader{{origin}};
  if (doc.Error()) {
    reader.fail(doc.ErrorLineNum(), "malformed XML: " + detail::describe_error(doc));
  }
  return reader.read(doc);
}

}  // namespace

model_description parse_model_description(const std::filesystem::path& file) {
  tinyxml2::XMLDocument doc;
  if (!std::filesystem::exists(file)) {
    throw fmu_import_error(file.string() + ": file not found");
  }
  // an FMI 3.0 model description has its own reader; this is its view as scalar ports
  if (const std::string xml = common::read_file(file);
      fmi3::declared_fmi_version(xml).starts_with("3")) {
    return fmi3::parse_description(xml, file.string()).scalar;
  }
  doc.LoadFile(file.c_str());
  return parse(doc, file.string());
}

model_description parse_model_description_text(std::string_view xml, const std::string& origin) {
  if (fmi3::declared_fmi_version(xml).starts_with("3")) {
    return fmi3::parse_description(xml, origin).scalar;
  }
  tinyxml2::XMLDocument doc;
  doc.Parse(xml.data(), xml.size());
  return parse(doc, origin);
}

model_description read_archive_description(const std::filesystem::path& fmu) {
  const std::optional<std::string> text = read_archive_entry(fmu, "modelDescription.xml");
  if (!text) throw fmu_import_error(fmu.string() + ": no modelDescription.xml at the archive root");
  return parse_model_description_text(*text, (fmu / "modelDescription.xml").string());
}

}  // namespace stride::cosim
