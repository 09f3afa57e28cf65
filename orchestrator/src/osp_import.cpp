// The reader of OSP system structures (OspSystemStructure.xml, libcosim's format version 0.1):
// simulators with their initial values and step sizes, variable connections, the time settings
// (docs/ssp.md). Functions, signal and group connections and the ECCO algorithm are refused.
#include <set>

#include "import_xml.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim::detail {

namespace fs = std::filesystem;
using tinyxml2::XMLElement;

namespace {

// libcosim's base step when the file gives none
constexpr std::string_view k_osp_default_step = "0.1";

class osp_reader {
 public:
  explicit osp_reader(const xml_file& file) : file_(file) {}

  system_structure read() {
    const XMLElement& root = file_.root();
    if (!file_.is(root, k_osp_ns, "OspSystemStructure")) {
      file_.fail(root, "the root element must be OspSystemStructure of namespace " +
                           std::string(k_osp_ns));
    }
    file_.allow_attributes(root, {"version"});
    if (const std::string v = file_.required(root, "version"); v != "0.1") {
      file_.fail(root, "version \"" + v + "\": Stride reads version 0.1 of the OSP format");
    }
    s_.name = default_system_name(file_.shown());
    s_.where = {file_.shown(), 0};
    s_.base_dir = file_.path().parent_path();
    s_.base_step = parse_duration(k_osp_default_step);
    bool simulators = false;
    file_.children(root,
                   {{k_osp_ns, "StartTime", 0},
                    {k_osp_ns, "EndTime", 1},
                    {k_osp_ns, "BaseStepSize", 2},
                    {k_osp_ns, "Algorithm", 3},
                    {k_osp_ns, "Simulators", 4},
                    {k_osp_ns, "Functions", 5},
                    {k_osp_ns, "Connections", 6},
                    {k_osp_ns, "EccoConfiguration", 7}},
                   [&](const XMLElement& e, std::string_view local) {
                     if (local == "Simulators") {
                       simulators = true;
                       read_simulators(e);
                     } else if (local == "Connections") {
                       read_connections(e);
                     } else if (local == "Functions" || local == "EccoConfiguration") {
                       file_.fail(e,
                                  "not supported (Stride connects simulators' variables "
                                  "directly and steps with a fixed step)");
                     } else {
                       read_setting(e, local);
                     }
                   });
    if (!simulators) file_.fail(root, "has no Simulators");
    if (s_.components.empty()) file_.fail(root, "has no Simulator");
    return std::move(s_);
  }

 private:
  std::string text(const XMLElement& e) const {
    file_.allow_attributes(e, {});
    if (e.FirstChildElement() != nullptr) file_.fail(e, "holds text only");
    const char* t = e.GetText();
    return t != nullptr ? t : "";
  }

  void read_setting(const XMLElement& e, std::string_view local) {
    const std::string value = text(e);
    if (local == "Algorithm") {
      if (value != "fixedStep") {
        file_.fail(e, "algorithm \"" + value + "\" is not supported (fixedStep is)");
      }
      return;
    }
    const duration d = file_.seconds(e, value, local);
    if (local == "StartTime") s_.start = time_point(d);
    if (local == "EndTime") s_.stop = time_point(d);
    if (local == "BaseStepSize") {
      if (d <= duration::zero()) file_.fail(e, "must be positive");
      s_.base_step = d;
    }
  }

  void read_simulators(const XMLElement& e) {
    file_.allow_attributes(e, {});
    file_.children(e, {{k_osp_ns, "Simulator", 0, true}}, [&](const XMLElement& x, auto) {
      file_.allow_attributes(x, {"name", "source", "stepSize"});
      const std::string name = file_.required(x, "name");
      if (const std::string problem = component_name_problem(name); !problem.empty()) {
        file_.fail(x, problem);
      }
      if (s_.find_component(name) != nullptr) file_.fail(x, "a second simulator so named");
      const fs::path fmu = file_.resolve(x, file_.required(x, "source"), "FMU");
      const model_description& md = facts_.of(fmu, file_.where(x));
      component_spec& c = s_.add_component(name, fmu_reference(fmu, s_.base_dir));
      c.where = file_.at(x);
      descriptions_[name] = &md;
      if (const auto step = file_.attribute(x, "stepSize")) c.step_multiple = multiple(x, *step);
      file_.children(x, {{k_osp_ns, "InitialValues", 0}}, [&](const XMLElement& values, auto) {
        file_.allow_attributes(values, {});
        file_.children(values, {{k_osp_ns, "InitialValue", 0, true}},
                       [&](const XMLElement& v, auto) { read_initial_value(v, md, c); });
      });
    });
  }

  // a simulator's stepSize as a whole number of base steps
  int multiple(const XMLElement& x, const std::string& text) const {
    const duration step = file_.seconds(x, text, "stepSize");
    if (step <= duration::zero() || step % *s_.base_step != duration::zero() ||
        step / *s_.base_step > 1'000'000) {
      file_.fail(x, "stepSize " + text + " s is not a whole multiple of the base step " +
                        format_seconds(*s_.base_step) + " s");
    }
    return static_cast<int>(step / *s_.base_step);
  }

  void read_initial_value(const XMLElement& v, const model_description& md, component_spec& c) {
    file_.allow_attributes(v, {"variable"});
    const std::string name = file_.required(v, "variable");
    const variable_description* var = md.find(name);
    if (var == nullptr) file_.fail(v, "simulator '" + c.name + "' has no variable so named");
    const XMLElement* typed = v.FirstChildElement();
    if (typed == nullptr || typed->NextSiblingElement() != nullptr) {
      file_.fail(v, "holds one of Real, Integer, Boolean or String");
    }
    static constexpr std::pair<std::string_view, variable_type> k_types[] = {
        {"Real", variable_type::real},
        {"Integer", variable_type::integer},
        {"Boolean", variable_type::boolean},
        {"String", variable_type::string}};
    const auto* type = std::find_if(std::begin(k_types), std::end(k_types), [&](const auto& t) {
      return file_.is(*typed, k_osp_ns, t.first);
    });
    if (type == std::end(k_types)) file_.fail(*typed, "not Real, Integer, Boolean or String");
    if (type->second != exchange_type(var->type)) {
      file_.fail(*typed, "a " + std::string(type->first) + " value for " + c.name + "." + name +
                             ", which is " + std::string(to_string(var->type)));
    }
    file_.allow_attributes(*typed, {"value"});
    const auto value = file_.attribute(*typed, "value");
    if (!value) file_.fail(*typed, "needs a value attribute");
    for (const auto& p : c.parameters) {
      if (p.variable == name) file_.fail(v, "a second initial value for " + name);
    }
    c.parameters.push_back({name, *value, file_.at(v)});
  }

  void read_connections(const XMLElement& e) {
    file_.allow_attributes(e, {});
    file_.children(e,
                   {{k_osp_ns, "VariableConnection", 0, true},
                    {k_osp_ns, "SignalConnection", 0, true},
                    {k_osp_ns, "VariableGroupConnection", 0, true},
                    {k_osp_ns, "SignalGroupConnection", 0, true}},
                   [&](const XMLElement& x, std::string_view local) {
                     if (local != "VariableConnection") {
                       file_.fail(x,
                                  "not supported: Stride reads VariableConnection only "
                                  "(no functions, no variable groups)");
                     }
                     read_variable_connection(x);
                   });
  }

  struct end {
    std::string name;  // "simulator.variable"
    bool source = false;
  };

  end read_end(const XMLElement& v) const {
    file_.allow_attributes(v, {"simulator", "name", "causality"});
    const std::string simulator = file_.required(v, "simulator");
    const std::string variable = file_.required(v, "name");
    const auto md = descriptions_.find(simulator);
    if (md == descriptions_.end()) file_.fail(v, "no simulator is named \"" + simulator + "\"");
    const variable_description* var = md->second->find(variable);
    if (var == nullptr) file_.fail(v, "simulator '" + simulator + "' has no variable so named");
    // as libcosim: the side whose variable is an output (or calculated parameter) is the source
    const std::string causality =
        file_.attribute(v, "causality").value_or(std::string(to_string(var->causality)));
    return {simulator + "." + variable,
            causality == "output" || causality == "calculatedParameter"};
  }

  void read_variable_connection(const XMLElement& x) {
    file_.allow_attributes(x, {"powerBond"});
    std::vector<end> ends;
    file_.children(x, {{k_osp_ns, "Variable", 0, true}},
                   [&](const XMLElement& v, auto) { ends.push_back(read_end(v)); });
    if (ends.size() != 2) file_.fail(x, "needs exactly two Variable elements");
    if (ends[0].source == ends[1].source) {
      file_.fail(x, ends[0].name + " and " + ends[1].name +
                        ": a connection joins an output and an input or parameter");
    }
    connection_spec& c = ends[0].source ? s_.connect(ends[0].name, ends[1].name)
                                        : s_.connect(ends[1].name, ends[0].name);
    c.where = file_.at(x);
  }

  const xml_file& file_;
  fmu_facts facts_;
  std::map<std::string, const model_description*> descriptions_;
  system_structure s_;
};

}  // namespace

system_structure import_osp(const xml_file& file) {
  return osp_reader(file).read();
}

}  // namespace stride::cosim::detail
