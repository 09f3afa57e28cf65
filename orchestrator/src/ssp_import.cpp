// The reader of SSP 1.0 system structure descriptions (.ssd): the system tree with its
// components, connectors, connections, parameter bindings, units, default experiment and
// Stride's annotation, checked element by element against the SSP's schema (docs/ssp.md).
#include <algorithm>
#include <functional>
#include <set>

#include "ssp_model.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim::detail {

namespace fs = std::filesystem;
using tinyxml2::XMLElement;

namespace ssp {
namespace {

constexpr std::string_view k_system_annotation = "org.stride-sim.system";
constexpr std::string_view k_connection_annotation = "org.stride-sim.connection";
constexpr std::string_view k_component_annotation = "org.stride-sim.component";

// where an Annotations element stands: which of Stride's annotations it may hold
enum class annotated { other, system, connection, component };

// where another tool's step, algorithm or integrator may stand: libcosim's in the
// ssd:DefaultExperiment, OMSimulator's on an ssd:System (its master on the top one)
enum class tool_place { none, experiment, top_system, nested_system };

constexpr std::string_view k_osp_annotation = "com.opensimulationplatform";
constexpr std::string_view k_oms_annotation = "org.openmodelica";

// which of Stride's annotations a type names (other: another tool's)
annotated annotation_kind(std::string_view type) {
  if (type == k_system_annotation) return annotated::system;
  if (type == k_connection_annotation) return annotated::connection;
  if (type == k_component_annotation) return annotated::component;
  return annotated::other;
}

// the element of Stride's namespace an annotation of `kind` holds
std::string_view stride_local(annotated kind) {
  return kind == annotated::system       ? "Simulation"
         : kind == annotated::connection ? "Connection"
                                         : "Component";
}

std::string misplaced(annotated kind) {
  switch (kind) {
    case annotated::system:
      return "Stride's system annotation belongs to the ssd:SystemStructureDescription, its top "
             "ssd:System or its ssd:DefaultExperiment";
    case annotated::connection:
      return "Stride's connection annotation belongs to an ssd:Connection";
    default:
      return "Stride's component annotation belongs to an ssd:Component";
  }
}

class ssd_reader {
 public:
  ssd_reader(const xml_file& file, fmu_facts& facts, std::vector<std::unique_ptr<unit_table>>& keep)
      : file_(file), facts_(facts), keep_(keep) {}

  ssd_content read() {
    const XMLElement& root = file_.root();
    if (!file_.is(root, k_ssd_ns, "SystemStructureDescription")) {
      file_.fail(root, "the root element must be ssd:SystemStructureDescription (namespace " +
                           std::string(k_ssd_ns) + ")");
    }
    file_.allow_attributes(
        root, {"version", "name", "id", "description", "author", "fileversion", "copyright",
               "license", "generationTool", "generationDateAndTime"});
    if (const std::string v = file_.required(root, "version"); !v.starts_with("1.")) {
      file_.fail(root, "version \"" + v + "\": Stride reads SSP 1.0 (version 1.x)");
    }
    bool has_system = false;
    content_.description = file_.required(root, "name");
    file_.children(root,
                   {{k_ssd_ns, "System", 0},
                    {k_ssd_ns, "Enumerations", 1},
                    {k_ssd_ns, "Units", 2},
                    {k_ssd_ns, "DefaultExperiment", 3},
                    {k_ssd_ns, "Annotations", 4}},
                   [&](const XMLElement& e, std::string_view local) {
                     if (local == "System") {
                       content_.top = read_system(e, "", true);
                       has_system = true;
                     } else if (local == "Units") {
                       read_units(file_, e, content_.units);
                     } else if (local == "DefaultExperiment") {
                       read_default_experiment(e);
                     } else if (local == "Annotations") {
                       read_annotations(e, annotated::system);
                     }
                   });
    if (!has_system) file_.fail(root, "has no ssd:System");
    check_units(content_.top);
    return std::move(content_);
  }

 private:
  element read_system(const XMLElement& e, const std::string& path, bool top) {
    file_.allow_attributes(e, {"id", "description", "name"});
    element s = begin(e, path, true);
    file_.children(e,
                   {{k_ssd_ns, "Connectors", 0},
                    {k_ssd_ns, "ElementGeometry", 1},
                    {k_ssd_ns, "ParameterBindings", 2},
                    {k_ssd_ns, "Elements", 3},
                    {k_ssd_ns, "Connections", 4},
                    {k_ssd_ns, "SignalDictionaries", 5},
                    {k_ssd_ns, "SystemGeometry", 6},
                    {k_ssd_ns, "GraphicalElements", 7},
                    {k_ssd_ns, "Annotations", 8}},
                   [&](const XMLElement& c, std::string_view local) {
                     if (read_element_child(c, local, s)) return;
                     if (local == "Elements") read_elements(c, s);
                     if (local == "Connections") read_connections(c, s);
                     if (local == "SignalDictionaries") {
                       file_.fail(c, "signal dictionaries are not supported (SSP 1.0 part 'ssb')");
                     }
                     if (local == "Annotations") {
                       system_ = &s;
                       read_annotations(c, top ? annotated::system : annotated::other, {},
                                        top ? tool_place::top_system : tool_place::nested_system);
                     }
                   });
    return s;
  }

  // the children all elements have (TElement): connectors, geometry, parameter bindings
  bool read_element_child(const XMLElement& x, std::string_view local, element& into) {
    if (local == "Connectors") {
      read_connectors(x, into);
    } else if (local == "ParameterBindings") {
      read_bindings(file_, x, into.bindings, keep_);
    } else {
      return local == "ElementGeometry";
    }
    return true;
  }

  // what systems and components have in common: name, path, place
  element begin(const XMLElement& e, const std::string& path, bool system) {
    element x;
    x.system = system;
    x.name = file_.required(e, "name");
    if (!path.empty() || !system) {
      // a component may be a replica group's copy, "gait[1]", as Stride's export writes them
      if (const std::string problem = component_name_problem(x.name, !system); !problem.empty()) {
        file_.fail(e, problem);
      }
    }
    x.path = path;
    x.where = file_.at(e);
    x.origin = file_.where(e);
    return x;
  }

  void read_elements(const XMLElement& e, element& system) {
    file_.allow_attributes(e, {});
    std::set<std::string> names;
    file_.children(e,
                   {{k_ssd_ns, "Component", 0, true},
                    {k_ssd_ns, "System", 0, true},
                    {k_ssd_ns, "SignalDictionaryReference", 0, true}},
                   [&](const XMLElement& c, std::string_view local) {
                     if (local == "SignalDictionaryReference") {
                       file_.fail(c, "signal dictionary references are not supported");
                     }
                     const std::string name = file_.required(c, "name");
                     if (!names.insert(name).second) {
                       file_.fail(c, "a second element named \"" + name + "\" in this system");
                     }
                     const std::string path = system.path.empty() ? name : system.path + "." + name;
                     if (local == "System") {
                       system.children.push_back(read_system(c, path, false));
                     } else {
                       system.children.push_back(read_component(c, path));
                     }
                   });
  }

  element read_component(const XMLElement& e, const std::string& path) {
    file_.allow_attributes(e, {"id", "description", "name", "type", "source", "implementation"});
    element c = begin(e, path, false);
    if (const auto type = file_.attribute(e, "type");
        type && *type != "application/x-fmu-sharedlibrary") {
      file_.fail(e, "type \"" + *type +
                        "\" is not supported: Stride's components are FMUs "
                        "(application/x-fmu-sharedlibrary), not nested SSPs");
    }
    const std::string implementation = file_.attribute(e, "implementation").value_or("any");
    if (implementation == "ModelExchange") c.kind = "model-exchange";
    if (implementation == "CoSimulation") c.kind = "co-simulation";
    if (implementation != "any" && c.kind.empty()) {
      file_.fail(
          e, "implementation=\"" + implementation + "\" is not any, CoSimulation or ModelExchange");
    }
    const fs::path fmu = file_.resolve(e, file_.required(e, "source"), "FMU");
    c.fmu = fmu_reference(fmu, file_.path().parent_path());
    c.description = &facts_.of(fmu, file_.where(e));
    file_.children(e,
                   {{k_ssd_ns, "Connectors", 0},
                    {k_ssd_ns, "ElementGeometry", 1},
                    {k_ssd_ns, "ParameterBindings", 2},
                    {k_ssd_ns, "Annotations", 3}},
                   [&](const XMLElement& x, std::string_view local) {
                     if (read_element_child(x, local, c)) return;
                     read_annotations(x, annotated::component, [&](const XMLElement& s) {
                       read_component_annotation(file_, s, c);
                     });
                   });
    return c;
  }

  void read_connectors(const XMLElement& e, element& owner) {
    file_.allow_attributes(e, {});
    file_.children(e, {{k_ssd_ns, "Connector", 0, true}}, [&](const XMLElement& x, auto) {
      file_.allow_attributes(x, {"id", "description", "name", "kind"});
      connector c;
      c.name = file_.required(x, "name");
      // files in the wild leave kind out: a component's connector then takes its FMU's
      // causality (check_against_fmu); a system's needs none
      c.kind = file_.attribute(x, "kind").value_or("");
      c.where = file_.at(x);
      if (owner.find_connector(c.name) != nullptr) file_.fail(x, "a second connector so named");
      if (c.kind == "inout") {
        file_.fail(x, "kind=\"inout\" (signal dictionary references) is not supported");
      }
      if (!c.kind.empty() && c.kind != "input" && c.kind != "output" && c.kind != "parameter" &&
          c.kind != "calculatedParameter") {
        file_.fail(x, "kind=\"" + c.kind +
                          "\" is not input, output, parameter or "
                          "calculatedParameter");
      }
      file_.children(x,
                     {{k_ssc_ns, "Real"},
                      {k_ssc_ns, "Integer"},
                      {k_ssc_ns, "Boolean"},
                      {k_ssc_ns, "String"},
                      {k_ssc_ns, "Enumeration"},
                      {k_ssc_ns, "Binary"},
                      {k_ssd_ns, "ConnectorGeometry", 1},
                      {k_ssd_ns, "Annotations", 2}},
                     [&](const XMLElement& t, std::string_view local) {
                       if (local == "Annotations") read_annotations(t, annotated::other);
                       if (local == "ConnectorGeometry" || local == "Annotations") return;
                       if (c.type) file_.fail(t, "a connector has one type");
                       c.type = connector_type(t, local, c.unit);
                     });
      if (!owner.system) check_against_fmu(x, c, owner);
      owner.connectors.push_back(std::move(c));
    });
  }

  variable_type connector_type(const XMLElement& t, std::string_view local, std::string& unit) {
    if (local == "Binary") file_.fail(t, "Binary connectors are not supported (no FMI 2.0 type)");
    if (local == "Real") {
      file_.allow_attributes(t, {"unit"});
      unit = file_.attribute(t, "unit").value_or("");
      return variable_type::real;
    }
    if (local == "Enumeration") {
      file_.allow_attributes(t, {"name"});
      file_.required(t, "name");
      return variable_type::enumeration;
    }
    file_.allow_attributes(t, {});
    return local == "Integer"   ? variable_type::integer
           : local == "Boolean" ? variable_type::boolean
                                : variable_type::string;
  }

  // a component's connector is its FMU's variable of the same name, causality and type
  void check_against_fmu(const XMLElement& x, connector& c, const element& owner) const {
    const variable_description* v = owner.description->find(c.name);
    if (v == nullptr) file_.fail(x, "the FMU of '" + owner.path + "' has no variable so named");
    if (c.kind.empty()) c.kind = to_string(v->causality);
    if (c.kind != to_string(v->causality)) {
      file_.fail(x, "kind=\"" + c.kind + "\", but the FMU's variable is " +
                        std::string(to_string(v->causality)));
    }
    if (c.type && *c.type != v->type) {
      file_.fail(x, "type " + std::string(to_string(*c.type)) + ", but the FMU's variable is " +
                        std::string(to_string(v->type)));
    }
  }

  void read_connections(const XMLElement& e, element& system) {
    file_.allow_attributes(e, {});
    file_.children(e, {{k_ssd_ns, "Connection", 0, true}}, [&](const XMLElement& x, auto) {
      file_.allow_attributes(x, {"id", "description", "startElement", "startConnector",
                                 "endElement", "endConnector", "suppressUnitConversion"});
      element::connection c;
      c.start_element = file_.attribute(x, "startElement").value_or("");
      c.start_connector = file_.required(x, "startConnector");
      c.end_element = file_.attribute(x, "endElement").value_or("");
      c.end_connector = file_.required(x, "endConnector");
      c.suppress_unit_conversion = file_.boolean(x, "suppressUnitConversion", false);
      c.where = file_.at(x);
      c.origin = file_.where(x);
      check_end(x, system, c.start_element, c.start_connector);
      check_end(x, system, c.end_element, c.end_connector);
      const auto t = read_transformed(
          file_, x, false, {{k_ssd_ns, "ConnectionGeometry", 1}, {k_ssd_ns, "Annotations", 2}},
          [&](const XMLElement& a, std::string_view local) {
            if (local != "Annotations") return;
            read_annotations(a, annotated::connection, [&](const XMLElement& s) {
              file_.allow_attributes(s, {"delay"});
              c.delayed = file_.boolean(s, "delay", false);
            });
          });
      if (t) c.transform = t->linear;
      system.connections.push_back(std::move(c));
    });
  }

  // A component's connector that its ssd:Connectors do not list is its FMU's variable of that
  // name, as tools that leave the list empty (or short) mean it.
  void check_end(const XMLElement& x, element& system, const std::string& element_name,
                 const std::string& connector_name) const {
    element* owner = &system;
    if (!element_name.empty()) {
      const auto it = std::find_if(system.children.begin(), system.children.end(),
                                   [&](const element& c) { return c.name == element_name; });
      owner = it == system.children.end() ? nullptr : &*it;
    }
    if (owner == nullptr) {
      file_.fail(
          x, "connection to a missing element: the system has no element \"" + element_name + "\"");
    }
    if (owner->find_connector(connector_name) != nullptr) return;
    if (!owner->system) {
      if (const variable_description* v = owner->description->find(connector_name)) {
        owner->connectors.push_back(
            {connector_name, std::string(to_string(v->causality)), v->type, "", file_.at(x)});
        return;
      }
    }
    file_.fail(x, "connection to a missing connector: " +
                      (element_name.empty() ? "the system" : "element \"" + element_name + "\"") +
                      " has no connector \"" + connector_name + "\"" +
                      (owner->system ? "" : " and its FMU no variable so named"));
  }

  void read_default_experiment(const XMLElement& e) {
    file_.allow_attributes(e, {"startTime", "stopTime"});
    if (const auto t = file_.attribute(e, "startTime")) {
      content_.start = time_point(file_.seconds(e, *t, "startTime"));
    }
    if (const auto t = file_.attribute(e, "stopTime")) {
      content_.stop = time_point(file_.seconds(e, *t, "stopTime"));
    }
    file_.children(e, {{k_ssd_ns, "Annotations", 0}}, [&](const XMLElement& a, auto) {
      read_annotations(a, annotated::system, {}, tool_place::experiment);
    });
  }

  // Stride's own annotations are read where they belong: the system's here, a connection's or
  // component's content (the one element of Stride's namespace) by `read`. Of other tools'
  // annotations the step and algorithm of libcosim and OMSimulator are read at `place`; the
  // rest are listed as ignored. (ssd:Annotation is OMSimulator's older spelling.)
  void read_annotations(const XMLElement& e, annotated where,
                        const std::function<void(const XMLElement&)>& read = {},
                        tool_place place = tool_place::none) {
    file_.allow_attributes(e, {});
    file_.children(e, {{k_ssc_ns, "Annotation", 0, true}, {k_ssd_ns, "Annotation", 0, true}},
                   [&](const XMLElement& a, auto) {
                     file_.allow_attributes(a, {"type"});
                     const std::string type = file_.required(a, "type");
                     const annotated kind = annotation_kind(type);
                     if (kind == annotated::other) {
                       read_tool_annotation(a, type, place);
                       return;
                     }
                     if (where != kind) file_.fail(a, misplaced(kind));
                     const XMLElement& content = stride_element(a, stride_local(kind));
                     if (kind != annotated::system) {
                       read(content);
                       return;
                     }
                     if (content_.stride_annotation) {
                       file_.fail(a, "a second Stride annotation (the first at " +
                                         content_.stride_annotation->str() + ")");
                     }
                     content_.stride_annotation = file_.at(a);
                     read_simulation(content);
                   });
  }

  void read_tool_annotation(const XMLElement& a, const std::string& type, tool_place place) {
    bool read = false;
    if (place == tool_place::experiment && type == k_osp_annotation) {
      if (auto found = read_osp_stepping(file_, a)) {
        content_.tool_steppings.push_back(std::move(*found));
        read = true;
      }
    } else if (type == k_oms_annotation &&
               (place == tool_place::top_system || place == tool_place::nested_system)) {
      oms_simulation found = read_oms_simulation(file_, a);
      // a nested system's master would step inside Stride's one: it is not read
      if (found.master && place == tool_place::top_system) {
        content_.tool_steppings.push_back(std::move(*found.master));
        read = true;
      }
      if (found.solver) {
        system_->model_exchange = found.solver;
        read = true;
      }
    }
    if (!read) content_.ignored_annotations.push_back(type + " at " + file_.at(a).str());
  }

  // the one element of Stride's namespace inside a Stride annotation
  const XMLElement& stride_element(const XMLElement& a, std::string_view local) const {
    const XMLElement* s = a.FirstChildElement();
    if (s == nullptr || s->NextSiblingElement() != nullptr || !file_.is(*s, k_stride_ns, local)) {
      file_.fail(a, "must hold one <" + std::string(local) + "> element of namespace " +
                        std::string(k_stride_ns));
    }
    return *s;
  }

  void read_simulation(const XMLElement& s) {
    file_.allow_attributes(s, {"step", "algorithm"});
    if (const auto step = file_.attribute(s, "step")) {
      content_.step = file_.seconds(s, *step, "step");
      if (*content_.step <= duration::zero()) file_.fail(s, "step must be positive");
    }
    if (const auto a = file_.attribute(s, "algorithm")) {
      if (*a != "gauss-seidel" && *a != "jacobi") {
        file_.fail(s, "algorithm \"" + *a + "\" is not gauss-seidel or jacobi");
      }
      content_.algorithm = *a == "jacobi" ? algorithm_kind::jacobi : algorithm_kind::gauss_seidel;
    }
    file_.children(
        s, {{k_stride_ns, "Record", 0}, {k_stride_ns, "Agents", 1}, {k_stride_ns, "Failover", 2}},
        [&](const XMLElement& x, std::string_view local) {
          if (local == "Record") {
            content_.record = read_record_annotation(file_, x);
          } else if (local == "Agents") {
            content_.agents = read_agents_annotation(file_, x);
          } else {
            content_.failover = read_failover_annotation(file_, x);
          }
        });
  }

  // a unit a connector declares must be one of the SSD's
  void check_units(const element& e) const {
    for (const auto& c : e.connectors) {
      if (!c.unit.empty() && !content_.units.contains(c.unit)) {
        throw validation_error(c.where.str() + ": <ssd:Connector name=\"" + c.name +
                               "\">: unit \"" + c.unit + "\" is not defined in the ssd:Units");
      }
    }
    for (const auto& child : e.children) check_units(child);
  }

  const xml_file& file_;
  fmu_facts& facts_;  // outlives the content: its elements point at the descriptions
  std::vector<std::unique_ptr<unit_table>>& keep_;
  ssd_content content_;
  element* system_ = nullptr;  // the system whose annotations are being read
};

}  // namespace
}  // namespace ssp

system_structure import_ssd(const fs::path& ssd, const std::string& shown, const fs::path& root,
                            const log_sink& log) {
  const xml_file file(ssd, shown, root);
  fmu_facts facts;
  std::vector<std::unique_ptr<ssp::unit_table>> keep;
  const ssp::ssd_content content = ssp::ssd_reader(file, facts, keep).read();
  system_structure s;
  s.name = default_system_name(shown);
  s.description = content.description;
  s.where = {shown, 0};
  s.base_dir = ssd.parent_path();
  s.start = content.start.value_or(time_point{});
  s.stop = content.stop;
  ssp::take_stepping(content, s);
  s.notes.ignored_annotations = content.ignored_annotations;
  if (content.record) s.record = *content.record;
  s.agents = content.agents;
  s.failover = content.failover;
  ssp::flatten(content, s, sink_or_stderr(log));
  if (s.components.empty()) {
    throw validation_error(content.top.origin + "the system has no component (an FMU)");
  }
  return s;
}

}  // namespace stride::cosim::detail
