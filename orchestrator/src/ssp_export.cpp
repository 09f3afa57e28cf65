// The SSP 1.0 writer (docs/ssp.md, "Export"): SystemStructure.ssd, the parameter set
// resources/parameters.ssv and the FMUs under resources/, zipped with fixed times and modes so
// that the same system gives the same archive. It writes exactly what ssp_import.cpp reads back:
// elements in the schema's order, Stride's settings as its two annotations.
#include <sys/stat.h>
#include <zip.h>

#include <algorithm>
#include <ctime>
#include <memory>

#include "export_plan.hpp"
#include "integrator_attributes.hpp"
#include "stride/common/text.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/system_export.hpp"

namespace stride::cosim {

namespace fs = std::filesystem;
using tinyxml2::XMLElement;

namespace {

constexpr const char* k_ssd_file = "SystemStructure.ssd";
constexpr const char* k_ssv_file = "resources/parameters.ssv";
constexpr const char* k_system_annotation = "org.stride-sim.system";
constexpr const char* k_connection_annotation = "org.stride-sim.connection";
constexpr const char* k_component_annotation = "org.stride-sim.component";

// ssc:Real, ssc:Integer, ... of a variable; enumerations have none (an ssc:Enumeration must
// name an ssd:Enumerations entry, which Stride does not write)
const char* connector_type(variable_type t) {
  switch (t) {
    case variable_type::real:
      return "ssc:Real";
    case variable_type::integer:
      return "ssc:Integer";
    case variable_type::boolean:
      return "ssc:Boolean";
    case variable_type::string:
      return "ssc:String";
    case variable_type::enumeration:
      break;
  }
  return nullptr;
}

// ssv:Real, ...: enumerations as ssv:Integer (the importer refuses ssv:Enumeration)
const char* value_type(variable_type t) {
  switch (exchange_type(t)) {
    case variable_type::real:
      return "ssv:Real";
    case variable_type::boolean:
      return "ssv:Boolean";
    case variable_type::string:
      return "ssv:String";
    default:
      return "ssv:Integer";
  }
}

// <ssd:Annotations><ssc:Annotation type=TYPE><LOCAL/></ssc:Annotation></ssd:Annotations>, the
// parent's one ssd:Annotations made on first use
XMLElement* add_annotation(XMLElement* parent, const char* type, const char* local) {
  XMLElement* annotations = parent->FirstChildElement("ssd:Annotations");
  if (annotations == nullptr) annotations = parent->InsertNewChildElement("ssd:Annotations");
  XMLElement* a = annotations->InsertNewChildElement("ssc:Annotation");
  a->SetAttribute("type", type);
  return a->InsertNewChildElement(local);
}

class ssd_writer {
 public:
  explicit ssd_writer(const detail::export_plan& plan) : plan_(plan) {}

  std::string ssd() {
    const system_structure& s = plan_.system();
    doc_.InsertEndChild(doc_.NewDeclaration());
    XMLElement* root = doc_.NewElement("ssd:SystemStructureDescription");
    doc_.InsertEndChild(root);
    root->SetAttribute("xmlns:ssd", "http://ssp-standard.org/SSP1/SystemStructureDescription");
    root->SetAttribute("xmlns:ssc", "http://ssp-standard.org/SSP1/SystemStructureCommon");
    root->SetAttribute("xmlns:stride", "https://stride-sim.org/ssp/1");
    root->SetAttribute("xmlns:osp", std::string(detail::k_osp_annotations_ns).c_str());
    root->SetAttribute("xmlns:oms", std::string(detail::k_oms_ns).c_str());
    root->SetAttribute("version", "1.0");
    root->SetAttribute("name", (s.description.empty() ? s.name : s.description).c_str());
    root->SetAttribute("generationTool", "Stride");
    XMLElement* system = root->InsertNewChildElement("ssd:System");
    system->SetAttribute("name", s.name.c_str());
    if (has_values()) {
      system->InsertNewChildElement("ssd:ParameterBindings")
          ->InsertNewChildElement("ssd:ParameterBinding")
          ->SetAttribute("source", k_ssv_file);
    }
    write_elements(system->InsertNewChildElement("ssd:Elements"));
    if (!plan_.connections().empty()) {
      write_connections(system->InsertNewChildElement("ssd:Connections"));
    }
    const std::optional<duration> step = plan_.base_step();
    if (step) {
      // OMSimulator's fixed-step master at Stride's step
      XMLElement* master = add_annotation(system, "org.openmodelica", "oms:Annotations")
                               ->InsertNewChildElement("oms:SimulationInformation")
                               ->InsertNewChildElement("oms:FixedStepMaster");
      master->SetAttribute("description", "oms-ma");
      master->SetAttribute("stepSize", format_seconds(*step).c_str());
    }
    write_experiment(root->InsertNewChildElement("ssd:DefaultExperiment"), step);
    return detail::xml_text(doc_);
  }

  bool has_values() const {
    return std::any_of(plan_.components().begin(), plan_.components().end(),
                       [](const auto& c) { return !c.values.empty(); });
  }

 private:
  void write_elements(XMLElement* elements) const {
    for (const auto& c : plan_.components()) {
      XMLElement* e = elements->InsertNewChildElement("ssd:Component");
      e->SetAttribute("name", c.spec->name.c_str());
      e->SetAttribute("source", detail::uri_path("resources/" + plan_.fmus()[c.fmu].name).c_str());
      if (c.spec->kind == "model-exchange") e->SetAttribute("implementation", "ModelExchange");
      if (c.spec->kind == "co-simulation") e->SetAttribute("implementation", "CoSimulation");
      if (!c.connectors.empty()) write_connectors(e->InsertNewChildElement("ssd:Connectors"), c);
      if (!c.spec->worker.empty() || !c.placeholders.empty() || c.spec->model_exchange ||
          c.spec->step_multiple != 1) {
        write_component_annotation(e, c);
      }
    }
  }

  // what is Stride's alone: the worker the component runs on, its step multiple, the integrator
  // of a Model Exchange component, and values the run fills in
  static void write_component_annotation(XMLElement* e, const detail::export_component& c) {
    XMLElement* a = add_annotation(e, k_component_annotation, "stride:Component");
    if (!c.spec->worker.empty()) a->SetAttribute("worker", c.spec->worker.c_str());
    if (c.spec->step_multiple != 1) a->SetAttribute("step_multiple", c.spec->step_multiple);
    if (c.spec->model_exchange) detail::write_integrator(*a, *c.spec->model_exchange);
    for (const auto& v : c.placeholders) {
      XMLElement* value = a->InsertNewChildElement("stride:Value");
      value->SetAttribute("name", v.variable->name.c_str());
      value->SetAttribute("value", v.text.c_str());
    }
  }

  static void write_connectors(XMLElement* connectors, const detail::export_component& c) {
    for (std::size_t index : c.connectors) {
      const variable_description& v = c.description->variables[index];
      XMLElement* x = connectors->InsertNewChildElement("ssd:Connector");
      x->SetAttribute("name", v.name.c_str());
      x->SetAttribute("kind", std::string(to_string(v.causality)).c_str());
      if (const char* type = connector_type(v.type)) x->InsertNewChildElement(type);
    }
  }

  void write_connections(XMLElement* connections) const {
    const auto& components = plan_.components();
    for (const auto& c : plan_.connections()) {
      const auto& from = components[c.from];
      const auto& to = components[c.to];
      XMLElement* x = connections->InsertNewChildElement("ssd:Connection");
      x->SetAttribute("startElement", from.spec->name.c_str());
      x->SetAttribute("startConnector", from.description->variables[c.from_variable].name.c_str());
      x->SetAttribute("endElement", to.spec->name.c_str());
      x->SetAttribute("endConnector", to.description->variables[c.to_variable].name.c_str());
      if (c.factor != 1.0 || c.offset != 0.0) {
        XMLElement* t = x->InsertNewChildElement("ssc:LinearTransformation");
        t->SetAttribute("factor", text::format_double(c.factor).c_str());
        t->SetAttribute("offset", text::format_double(c.offset).c_str());
      }
      if (c.delayed) {
        add_annotation(x, k_connection_annotation, "stride:Connection")
            ->SetAttribute("delay", "true");
      }
    }
  }

  // times exactly as Stride holds them; step and algorithm in Stride's system annotation, the
  // step also as libcosim reads it (docs/ssp.md)
  void write_experiment(XMLElement* e, std::optional<duration> step) const {
    const system_structure& s = plan_.system();
    e->SetAttribute("startTime", format_seconds(s.start).c_str());
    if (s.stop) e->SetAttribute("stopTime", format_seconds(*s.stop).c_str());
    XMLElement* simulation = add_annotation(e, k_system_annotation, "stride:Simulation");
    if (s.base_step) simulation->SetAttribute("step", format_seconds(*s.base_step).c_str());
    simulation->SetAttribute("algorithm", std::string(to_string(s.algorithm)).c_str());
    write_record(simulation, s.record);
    write_agents(simulation, s.agents);
    write_failover(simulation, s.failover);
    if (step) {
      add_annotation(e, "com.opensimulationplatform", "osp:Algorithm")
          ->InsertNewChildElement("osp:FixedStepAlgorithm")
          ->SetAttribute("baseStepSize", format_seconds(*step).c_str());
    }
  }

  // recording as <record> of the system XML says it, written when it is not the default (every
  // output at every base step into results.csv), so that it reads back exactly
  static void write_record(XMLElement* simulation, const record_spec& r) {
    const record_spec defaults;
    if (r.enabled && r.signals.empty() && !r.interval && r.file == defaults.file) return;
    XMLElement* record = simulation->InsertNewChildElement("stride:Record");
    if (!r.enabled) record->SetAttribute("enabled", "false");
    if (r.interval) record->SetAttribute("interval", format_seconds(*r.interval).c_str());
    if (r.file != defaults.file) record->SetAttribute("file", r.file.c_str());
    for (const auto& signal : r.signals) {
      record->InsertNewChildElement("stride:Signal")->SetAttribute("name", signal.c_str());
    }
  }

  // several agents as <agents> of the system XML says it
  static void write_agents(XMLElement* simulation, const agents_spec& a) {
    if (a.count == 0) return;
    XMLElement* agents = simulation->InsertNewChildElement("stride:Agents");
    agents->SetAttribute("count", a.count);
    agents->SetAttribute("mode", a.synchronous ? "synchronous" : "asynchronous");
    if (!a.workers.empty()) agents->SetAttribute("workers", text::join(a.workers, " ").c_str());
  }

  // standby workers as <failover> of the system XML says them
  static void write_failover(XMLElement* simulation, const failover_spec& f) {
    if (f.standby.empty()) return;
    XMLElement* failover = simulation->InsertNewChildElement("stride:Failover");
    failover->SetAttribute("standby", text::join(f.standby, " ").c_str());
    if (f.snapshot_every) failover->SetAttribute("snapshot-every", *f.snapshot_every);
  }

  const detail::export_plan& plan_;
  tinyxml2::XMLDocument doc_;
};

// every component's values as "component.variable", in component order
std::string ssv_text(const detail::export_plan& plan) {
  tinyxml2::XMLDocument doc;
  doc.InsertEndChild(doc.NewDeclaration());
  XMLElement* set = doc.NewElement("ssv:ParameterSet");
  doc.InsertEndChild(set);
  set->SetAttribute("xmlns:ssv", "http://ssp-standard.org/SSP1/SystemStructureParameterValues");
  set->SetAttribute("version", "1.0");
  set->SetAttribute("name", plan.system().name.c_str());
  set->SetAttribute("generationTool", "Stride");
  XMLElement* parameters = set->InsertNewChildElement("ssv:Parameters");
  for (const auto& c : plan.components()) {
    for (const auto& v : c.values) {
      XMLElement* p = parameters->InsertNewChildElement("ssv:Parameter");
      p->SetAttribute("name", (c.spec->name + "." + v.variable->name).c_str());
      p->InsertNewChildElement(value_type(v.variable->type))->SetAttribute("value", v.text.c_str());
    }
  }
  return detail::xml_text(doc);
}

struct zip_discarder {
  void operator()(zip_t* z) const noexcept { zip_discard(z); }
};

// 2000-01-01 12:00 local time: a fixed time for every entry (zip keeps local DOS times)
std::time_t fixed_mtime() {
  std::tm t{};
  t.tm_year = 100;
  t.tm_mday = 1;
  t.tm_hour = 12;
  t.tm_isdst = -1;
  return std::mktime(&t);
}

// one entry added to `za`: text (kept alive by the caller) or a file; always the same mode
// and time, FMUs stored as they are (they are zip archives already)
void add_entry(zip_t* za, const fs::path& archive, const std::string& name, zip_source_t* source,
               bool store) {
  const auto fail = [&](const std::string& what) {
    throw validation_error(archive.string() + ": cannot add " + name + ": " + what);
  };
  if (source == nullptr) fail(zip_strerror(za));
  const zip_int64_t index = zip_file_add(za, name.c_str(), source, ZIP_FL_ENC_UTF_8);
  if (index < 0) {
    zip_source_free(source);
    fail(zip_strerror(za));
  }
  const auto i = static_cast<zip_uint64_t>(index);
  if (zip_file_set_mtime(za, i, fixed_mtime(), 0) != 0 ||
      zip_file_set_external_attributes(za, i, 0, ZIP_OPSYS_UNIX,
                                       static_cast<zip_uint32_t>(S_IFREG | 0644) << 16) != 0 ||
      zip_set_file_compression(za, i, store ? ZIP_CM_STORE : ZIP_CM_DEFLATE, 0) != 0) {
    fail(zip_strerror(za));
  }
}

}  // namespace

export_report export_ssp(const system_structure& system, const fs::path& archive,
                         const export_options& options) {
  if (text::lower(archive.extension().string()) != ".ssp") {
    throw validation_error(archive.string() +
                           ": an SSP archive's name ends in .ssp (how Stride recognizes it)");
  }
  detail::check_export_target(archive, false, options.overwrite);
  const detail::export_plan plan(system, options.fmu_search_path, "SSP");
  ssd_writer writer(plan);
  const std::string ssd = writer.ssd();
  const std::string ssv = writer.has_values() ? ssv_text(plan) : std::string();

  std::vector<std::pair<std::string, const fs::path*>> resources;  // name → FMU (nullptr: .ssv)
  for (const auto& f : plan.fmus()) resources.emplace_back("resources/" + f.name, &f.file);
  if (!ssv.empty()) resources.emplace_back(k_ssv_file, nullptr);
  std::sort(resources.begin(), resources.end());

  int error = 0;
  std::unique_ptr<zip_t, zip_discarder> za(
      zip_open(archive.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error));
  if (!za) throw validation_error(archive.string() + ": cannot create the archive");
  export_report report{archive, {k_ssd_file}};
  add_entry(za.get(), archive, k_ssd_file, zip_source_buffer(za.get(), ssd.data(), ssd.size(), 0),
            false);
  for (const auto& [name, fmu] : resources) {
    zip_source_t* source = fmu == nullptr ? zip_source_buffer(za.get(), ssv.data(), ssv.size(), 0)
                                          : zip_source_file(za.get(), fmu->c_str(), 0, -1);
    add_entry(za.get(), archive, name, source, fmu != nullptr);
    report.files.push_back(name);
  }
  // libzip writes a temporary file and renames it: no half-written archive under the name
  if (zip_close(za.get()) != 0) {
    throw validation_error(archive.string() +
                           ": cannot write the archive: " + zip_strerror(za.get()));
  }
  za.release();
  return report;
}

}  // namespace stride::cosim
