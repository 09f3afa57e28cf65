#include "stride/cosim/system_structure.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <sstream>

#include "integrator_attributes.hpp"
#include "stride/common/text.hpp"
#include "stride/cosim/error.hpp"
#include "xml_util.hpp"

namespace stride::cosim {

namespace fs = std::filesystem;

std::string source_location::str() const {
  if (file.empty()) return {};
  return line > 0 ? file + ":" + std::to_string(line) : file;
}

bool is_bundled_fmu_name(std::string_view fmu) noexcept {
  return !fmu.empty() && fmu.find('/') == std::string_view::npos && !fmu.ends_with(".fmu");
}

component_spec& system_structure::add_component(std::string component_name, std::string fmu_ref,
                                                int step_multiple) {
  component_spec c;
  c.name = std::move(component_name);
  c.fmu = std::move(fmu_ref);
  c.step_multiple = step_multiple;
  components.push_back(std::move(c));
  return components.back();
}

connection_spec& system_structure::connect(std::string from, std::string to, bool delayed) {
  connection_spec c;
  c.from = std::move(from);
  c.to = std::move(to);
  c.delayed = delayed;
  connections.push_back(std::move(c));
  return connections.back();
}

component_spec* system_structure::find_component(std::string_view component_name) noexcept {
  for (auto& c : components) {
    if (c.name == component_name) return &c;
  }
  return nullptr;
}

std::size_t component_end(std::string_view full_name,
                          const std::function<bool(std::string_view)>& is_component) {
  // component names may hold dots: the longest one that prefixes the name wins
  for (auto dot = full_name.rfind('.'); dot != std::string_view::npos && dot > 0;
       dot = full_name.rfind('.', dot - 1)) {
    if (is_component(full_name.substr(0, dot))) return dot;
  }
  return full_name.find('.');
}

void system_structure::set(const std::string& full_name, std::string value, source_location at) {
  const auto dot = component_end(full_name, [&](std::string_view name) {
    if (find_component(name) != nullptr) return true;
    for (const auto& g : groups) {
      for (const auto& m : g.components) {
        if (m.name == name) return true;
      }
    }
    return false;
  });
  if (dot == std::string::npos || dot == 0 || dot + 1 == full_name.size()) {
    throw validation_error("'" + full_name + "' is not of the form component.variable");
  }
  const std::string comp = full_name.substr(0, dot);
  const std::string var = full_name.substr(dot + 1);
  std::vector<component_spec*> targets;
  if (component_spec* c = find_component(comp)) targets.push_back(c);
  for (auto& g : groups) {
    for (auto& m : g.components) {
      if (m.name == comp) targets.push_back(&m);  // the member of every copy
      if (comp.starts_with(m.name + "[")) {
        throw validation_error("'" + full_name + "': a parameter of one copy of group '" + g.name +
                               "' cannot be set; '" + m.name + "." + var +
                               "' sets it in every copy");
      }
    }
  }
  if (targets.empty()) {
    throw validation_error("'" + full_name + "': the system has no component '" + comp + "'");
  }
  for (component_spec* c : targets) {
    bool replaced = false;
    for (auto& p : c->parameters) {
      if (p.variable == var) {
        p.value = value;
        p.where = at;
        replaced = true;
      }
    }
    if (!replaced) c->parameters.push_back({var, value, at});
  }
}

void apply_override(system_structure& system, const std::string& assignment) {
  // the value goes into system.xml and manifest.json, which are UTF-8
  if (detail::first_line_not_utf8(assignment) > 0 || assignment.find('\n') != std::string::npos) {
    throw validation_error("--set: \"" + detail::printable(assignment) +
                           "\" is not one line of UTF-8 text");
  }
  const auto eq = assignment.find('=');
  if (eq == std::string::npos) {
    throw validation_error("--set '" + assignment + "': expected component.variable=value");
  }
  try {
    system.set(std::string(text::trim(assignment.substr(0, eq))), assignment.substr(eq + 1),
               {"--set " + assignment, 0});
  } catch (const validation_error& e) {
    throw validation_error(std::string("--set: ") + e.what());
  }
}

namespace {

using detail::attribute;

class system_reader {
 public:
  explicit system_reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw validation_error(source_location{file_, line}.str() + ": " + message);
  }

  source_location at(const tinyxml2::XMLElement* e) const { return {file_, e->GetLineNum()}; }

  // The children of an element come in a fixed order (as the XSD says): each known tag has a
  // rank, and a child may not follow one of a higher rank. Unknown tags are left to the caller.
  class child_order {
   public:
    child_order(std::string parent, std::initializer_list<std::pair<std::string_view, int>> ranks,
                std::string expected)
        : parent_(std::move(parent)), ranks_(ranks), expected_(std::move(expected)) {}

    void check(const tinyxml2::XMLElement* e, const system_reader& reader) {
      const std::string_view tag = e->Name();
      const auto known =
          std::find_if(ranks_.begin(), ranks_.end(), [&](const auto& r) { return r.first == tag; });
      if (known == ranks_.end()) return;
      if (known->second < highest_) {
        reader.fail(e->GetLineNum(), "<" + std::string(tag) + "> after <" + highest_tag_ +
                                         "> (line " + std::to_string(highest_line_) +
                                         "): the children of " + parent_ + " come in the order " +
                                         expected_);
      }
      if (known->second > highest_) {
        highest_ = known->second;
        highest_tag_ = std::string(tag);
        highest_line_ = e->GetLineNum();
      }
    }

   private:
    std::string parent_;
    std::vector<std::pair<std::string_view, int>> ranks_;
    std::string expected_;
    int highest_ = -1;
    std::string highest_tag_;
    int highest_line_ = 0;
  };

  // rejects attributes that are not in `allowed` (typos should not pass silently)
  void check_attributes(const tinyxml2::XMLElement* e,
                        std::initializer_list<std::string_view> allowed) const {
    for (auto* a = e->FirstAttribute(); a != nullptr; a = a->Next()) {
      bool ok = false;
      for (auto name : allowed) ok = ok || name == a->Name();
      if (!ok) {
        fail(e->GetLineNum(),
             std::string("unknown attribute '") + a->Name() + "' on <" + e->Name() + ">");
      }
    }
  }

  std::string required(const tinyxml2::XMLElement* e, const char* name) const {
    const char* v = e->Attribute(name);
    if (v == nullptr || *v == '\0') {
      fail(e->GetLineNum(), std::string("<") + e->Name() + "> needs a " + name + " attribute");
    }
    return v;
  }

  duration seconds(const tinyxml2::XMLElement* e, const char* name) const {
    const std::string text = required(e, name);
    try {
      return parse_duration(text);
    } catch (const std::exception& ex) {
      fail(e->GetLineNum(), std::string(name) + ": " + ex.what());
    }
  }

  bool boolean(const tinyxml2::XMLElement* e, const char* name, bool fallback) const {
    const char* v = e->Attribute(name);
    if (v == nullptr) return fallback;
    const std::string_view s(v);
    if (s == "true" || s == "1") return true;
    if (s == "false" || s == "0") return false;
    fail(e->GetLineNum(), std::string(name) + "=\"" + v + "\" is not true or false");
  }

  system_structure read(const tinyxml2::XMLDocument& doc, const fs::path& path) const {
    if (doc.Error()) {
      fail(doc.ErrorLineNum(), "malformed XML: " + detail::describe_error(doc));
    }
    const auto* root = doc.RootElement();
    if (root == nullptr || std::string_view(root->Name()) != "system") {
      fail(root ? root->GetLineNum() : 0, "the root element must be <system>");
    }
    check_attributes(root, {"name", "description", "version"});
    system_structure s;
    s.where = {file_, 0};
    s.base_dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
    s.name = attribute(root, "name").value_or(path.stem().string());
    // the name becomes a folder name (the default output folder): it must stay one
    const bool control = std::any_of(s.name.begin(), s.name.end(), [](char c) {
      return static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
    });
    if (s.name.empty() || s.name == "." || s.name == ".." ||
        s.name.find_first_of("/\\") != std::string::npos || control) {
      fail(root->GetLineNum(), "system name \"" + s.name +
                                   "\" must be a folder name: not empty, '.' or '..', and "
                                   "without '/', '\\' or control characters");
    }
    s.description = attribute(root, "description").value_or("");
    if (const auto v = attribute(root, "version"); v && *v != "1") {
      fail(root->GetLineNum(), "unsupported system format version \"" + *v + "\" (expected 1)");
    }
    bool seen_simulation = false;
    bool seen_record = false;
    bool seen_agents = false;
    bool seen_failover = false;
    child_order order("<system>",
                      {{"simulation", 0},
                       {"agents", 1},
                       {"failover", 2},
                       {"component", 3},
                       {"replicate", 3},
                       {"connection", 4},
                       {"record", 5}},
                      "simulation, agents, failover, component and replicate, connection, record");
    for (auto* e = root->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
      const std::string_view tag = e->Name();
      order.check(e, *this);
      if (tag == "simulation") {
        if (seen_simulation) fail(e->GetLineNum(), "more than one <simulation>");
        seen_simulation = true;
        read_simulation(e, s);
      } else if (tag == "component") {
        read_component(e, s.components);
      } else if (tag == "connection") {
        s.connections.push_back(read_connection(e));
      } else if (tag == "replicate") {
        read_group(e, s);
      } else if (tag == "record") {
        if (seen_record) fail(e->GetLineNum(), "more than one <record>");
        seen_record = true;
        read_record(e, s.record);
      } else if (tag == "agents") {
        if (seen_agents) fail(e->GetLineNum(), "more than one <agents>");
        seen_agents = true;
        read_agents(e, s.agents);
      } else if (tag == "failover") {
        if (seen_failover) fail(e->GetLineNum(), "more than one <failover>");
        seen_failover = true;
        read_failover(e, s.failover);
      } else {
        fail(e->GetLineNum(), "unknown element <" + std::string(tag) +
                                  "> (expected simulation, component, connection, replicate, "
                                  "record, agents or failover)");
      }
    }
    if (s.components.empty() && s.groups.empty()) {
      fail(root->GetLineNum(), "the system has no <component>");
    }
    return s;
  }

  void read_simulation(const tinyxml2::XMLElement* e, system_structure& s) const {
    check_attributes(e, {"start", "stop", "step", "algorithm"});
    if (e->Attribute("start")) s.start = time_point(seconds(e, "start"));
    if (e->Attribute("stop")) s.stop = time_point(seconds(e, "stop"));
    if (e->Attribute("step")) {
      s.base_step = seconds(e, "step");
      if (*s.base_step <= duration::zero()) fail(e->GetLineNum(), "step must be positive");
    }
    if (const auto a = attribute(e, "algorithm")) {
      if (*a == "gauss-seidel") {
        s.algorithm = algorithm_kind::gauss_seidel;
      } else if (*a == "jacobi") {
        s.algorithm = algorithm_kind::jacobi;
      } else {
        fail(e->GetLineNum(), "algorithm \"" + *a + "\" is not gauss-seidel or jacobi");
      }
    }
  }

  void read_agents(const tinyxml2::XMLElement* e, agents_spec& a) const {
    check_attributes(e, {"count", "mode", "workers"});
    a.count = positive_integer(e, "count");
    if (const auto w = attribute(e, "workers")) {
      std::istringstream names(*w);
      for (std::string name; names >> name;) a.workers.push_back(name);
      if (a.workers.empty()) fail(e->GetLineNum(), "workers=\"\" names no worker");
    }
    if (const auto m = attribute(e, "mode")) {
      if (*m != "synchronous" && *m != "asynchronous") {
        fail(e->GetLineNum(), "mode \"" + *m + "\" is not synchronous or asynchronous");
      }
      a.synchronous = *m == "synchronous";
    }
    a.where = at(e);
  }

  void read_failover(const tinyxml2::XMLElement* e, failover_spec& f) const {
    check_attributes(e, {"standby", "snapshot-every"});
    std::istringstream names(required(e, "standby"));
    for (std::string name; names >> name;) f.standby.push_back(name);
    if (f.standby.empty()) fail(e->GetLineNum(), "standby=\"\" names no worker");
    if (e->Attribute("snapshot-every")) f.snapshot_every = positive_integer(e, "snapshot-every");
    f.where = at(e);
  }

  connection_spec read_connection(const tinyxml2::XMLElement* e) const {
    check_attributes(e, {"from", "to", "delay", "factor", "offset"});
    connection_spec c;
    c.from = required(e, "from");
    c.to = required(e, "to");
    c.delayed = boolean(e, "delay", false);
    c.factor = finite(e, "factor", 1.0);
    c.offset = finite(e, "offset", 0.0);
    c.where = at(e);
    return c;
  }

  // kind="model-exchange" and its integrator (docs/model-exchange.md)
  void read_kind(const tinyxml2::XMLElement* e, component_spec& c) const {
    const int line = e->GetLineNum();
    if (e->Attribute("kind")) {
      c.kind = required(e, "kind");
      if (c.kind != "co-simulation" && c.kind != "model-exchange") {
        fail(line, "kind=\"" + c.kind + "\" is not co-simulation or model-exchange");
      }
    }
    detail::read_integrator(*e, c, [&](const std::string& message) { fail(line, message); });
  }

  double finite(const tinyxml2::XMLElement* e, const char* name, double fallback) const {
    const char* v = e->Attribute(name);
    if (v == nullptr) return fallback;
    const auto value = text::parse_double(v);
    if (!value || !std::isfinite(*value)) {
      fail(e->GetLineNum(), std::string(name) + "=\"" + v + "\" is not a finite number");
    }
    return *value;
  }

  int positive_integer(const tinyxml2::XMLElement* e, const char* name) const {
    const std::string text = required(e, name);
    int value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || value < 1) {
      fail(e->GetLineNum(), std::string(name) + "=\"" + text + "\" is not a positive integer");
    }
    return value;
  }

  void read_group(const tinyxml2::XMLElement* e, system_structure& s) const {
    check_attributes(e, {"name", "count"});
    replica_group g;
    g.name = required(e, "name");
    g.count = positive_integer(e, "count");
    g.where = at(e);
    for (const auto& other : s.groups) {
      if (other.name == g.name) {
        fail(e->GetLineNum(),
             "duplicate group name \"" + g.name + "\" (first at " + other.where.str() + ")");
      }
    }
    child_order order("<replicate>", {{"component", 0}, {"connection", 1}},
                      "component, connection");
    for (auto* c = e->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
      const std::string_view tag = c->Name();
      order.check(c, *this);
      if (tag == "component") {
        read_component(c, g.components, true);
      } else if (tag == "connection") {
        g.connections.push_back(read_connection(c));
      } else {
        fail(c->GetLineNum(), "unknown element <" + std::string(tag) +
                                  "> in <replicate> (expected component or connection)");
      }
    }
    if (g.components.empty()) fail(e->GetLineNum(), "<replicate> has no <component>");
    s.groups.push_back(std::move(g));
  }

  // a replica group's members take no dots: "gait.x" inside a group means member gait
  void read_component(const tinyxml2::XMLElement* e, std::vector<component_spec>& components,
                      bool member = false) const {
    check_attributes(e, {"name", "fmu", "step_multiple", "worker", "kind", "solver", "method",
                         "rtol", "atol", "max_step"});
    component_spec c;
    c.name = required(e, "name");
    const bool bad_dots = member ? c.name.find('.') != std::string::npos
                                 : c.name.front() == '.' || c.name.back() == '.' ||
                                       c.name.find("..") != std::string::npos;
    if (bad_dots || c.name.find_first_of(" \t*?[]") != std::string::npos) {
      fail(e->GetLineNum(), "component name \"" + c.name + "\" must not contain " +
                                (member ? "'.', " : "") + "blanks, '*', '?' or brackets" +
                                (member ? "" : ", nor begin or end with '.' or hold '..'"));
    }
    for (const auto& other : components) {
      if (other.name == c.name) {
        fail(e->GetLineNum(),
             "duplicate component name \"" + c.name + "\" (first at " + other.where.str() + ")");
      }
    }
    c.fmu = required(e, "fmu");
    if (e->Attribute("step_multiple")) c.step_multiple = positive_integer(e, "step_multiple");
    if (e->Attribute("worker")) c.worker = required(e, "worker");
    read_kind(e, c);
    c.where = at(e);
    for (auto* p = e->FirstChildElement(); p != nullptr; p = p->NextSiblingElement()) {
      if (std::string_view(p->Name()) != "parameter") {
        fail(p->GetLineNum(), "unknown element <" + std::string(p->Name()) +
                                  "> in <component> (expected parameter)");
      }
      check_attributes(p, {"name", "value"});
      parameter_setting setting;
      setting.variable = required(p, "name");
      const char* value = p->Attribute("value");
      if (value == nullptr) fail(p->GetLineNum(), "<parameter> needs a value attribute");
      setting.value = value;
      setting.where = at(p);
      for (const auto& other : c.parameters) {
        if (other.variable == setting.variable) {
          fail(p->GetLineNum(), "parameter \"" + setting.variable + "\" set twice (first at " +
                                    other.where.str() + ")");
        }
      }
      c.parameters.push_back(std::move(setting));
    }
    components.push_back(std::move(c));
  }

  void read_record(const tinyxml2::XMLElement* e, record_spec& r) const {
    check_attributes(e, {"enabled", "interval", "file"});
    r.where = at(e);
    r.enabled = boolean(e, "enabled", true);
    if (e->Attribute("interval")) r.interval = seconds(e, "interval");
    if (const auto f = attribute(e, "file")) {
      if (const std::string problem = detail::record_file_problem(*f); !problem.empty()) {
        fail(e->GetLineNum(), problem);
      }
      r.file = *f;
    }
    for (auto* sig = e->FirstChildElement(); sig != nullptr; sig = sig->NextSiblingElement()) {
      if (std::string_view(sig->Name()) != "signal") {
        fail(sig->GetLineNum(),
             "unknown element <" + std::string(sig->Name()) + "> in <record> (expected signal)");
      }
      check_attributes(sig, {"name"});
      r.signals.push_back(required(sig, "name"));
      r.signal_locations.push_back(at(sig));
    }
  }

 private:
  std::string file_;
};

}  // namespace

system_structure parse_system_text(std::string_view xml, const fs::path& file) {
  // names and values go on into result files (manifest.json, system.xml): text only
  if (const int line = detail::first_line_not_utf8(xml); line > 0) {
    throw validation_error(file.string() + ":" + std::to_string(line) +
                           ": not UTF-8 text (XML's encoding); save the file as UTF-8");
  }
  tinyxml2::XMLDocument doc;
  doc.Parse(xml.data(), xml.size());
  return system_reader(file.string()).read(doc, file);
}

system_structure parse_system_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw validation_error(file.string() + ": cannot open the system file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_system_text(text.str(), file);
}

namespace {

void write_kind(tinyxml2::XMLElement* e, const component_spec& c) {
  if (!c.kind.empty()) e->SetAttribute("kind", c.kind.c_str());
  if (c.model_exchange) detail::write_integrator(*e, *c.model_exchange);
}

}  // namespace

std::string to_xml(const system_structure& s, bool absolute_fmu_paths) {
  tinyxml2::XMLDocument doc;
  doc.InsertEndChild(doc.NewDeclaration());
  auto* root = doc.NewElement("system");
  doc.InsertEndChild(root);
  root->SetAttribute("name", s.name.c_str());
  if (!s.description.empty()) root->SetAttribute("description", s.description.c_str());
  auto* sim = root->InsertNewChildElement("simulation");
  sim->SetAttribute("start", format_seconds(s.start).c_str());
  if (s.stop) sim->SetAttribute("stop", format_seconds(*s.stop).c_str());
  if (s.base_step) sim->SetAttribute("step", format_seconds(*s.base_step).c_str());
  sim->SetAttribute("algorithm", std::string(to_string(s.algorithm)).c_str());
  if (s.agents.count > 0) {
    auto* a = root->InsertNewChildElement("agents");
    a->SetAttribute("count", s.agents.count);
    a->SetAttribute("mode", s.agents.synchronous ? "synchronous" : "asynchronous");
    if (!s.agents.workers.empty())
      a->SetAttribute("workers", text::join(s.agents.workers, " ").c_str());
  }
  if (!s.failover.standby.empty()) {
    auto* f = root->InsertNewChildElement("failover");
    f->SetAttribute("standby", text::join(s.failover.standby, " ").c_str());
    if (s.failover.snapshot_every) f->SetAttribute("snapshot-every", *s.failover.snapshot_every);
  }
  const auto write_component = [&](tinyxml2::XMLElement* parent, const component_spec& c) {
    auto* e = parent->InsertNewChildElement("component");
    e->SetAttribute("name", c.name.c_str());
    std::string fmu_ref = c.fmu;
    if (absolute_fmu_paths && !is_bundled_fmu_name(fmu_ref) && fs::path(fmu_ref).is_relative()) {
      fmu_ref = fs::absolute(s.base_dir / fmu_ref).lexically_normal().string();
    }
    e->SetAttribute("fmu", fmu_ref.c_str());
    if (c.step_multiple != 1) e->SetAttribute("step_multiple", c.step_multiple);
    if (!c.worker.empty()) e->SetAttribute("worker", c.worker.c_str());
    write_kind(e, c);
    for (const auto& p : c.parameters) {
      auto* pe = e->InsertNewChildElement("parameter");
      pe->SetAttribute("name", p.variable.c_str());
      pe->SetAttribute("value", p.value.c_str());
    }
  };
  const auto write_connection = [](tinyxml2::XMLElement* parent, const connection_spec& c) {
    auto* e = parent->InsertNewChildElement("connection");
    e->SetAttribute("from", c.from.c_str());
    e->SetAttribute("to", c.to.c_str());
    if (c.delayed) e->SetAttribute("delay", "true");
    if (c.factor != 1.0) e->SetAttribute("factor", text::format_double(c.factor).c_str());
    if (c.offset != 0.0) e->SetAttribute("offset", text::format_double(c.offset).c_str());
  };
  for (const auto& c : s.components) write_component(root, c);
  for (const auto& g : s.groups) {
    auto* e = root->InsertNewChildElement("replicate");
    e->SetAttribute("name", g.name.c_str());
    e->SetAttribute("count", g.count);
    for (const auto& c : g.components) write_component(e, c);
    for (const auto& c : g.connections) write_connection(e, c);
  }
  for (const auto& c : s.connections) write_connection(root, c);
  auto* rec = root->InsertNewChildElement("record");
  if (!s.record.enabled) rec->SetAttribute("enabled", "false");
  if (s.record.interval) rec->SetAttribute("interval", format_seconds(*s.record.interval).c_str());
  rec->SetAttribute("file", s.record.file.c_str());
  for (const auto& sig : s.record.signals) {
    rec->InsertNewChildElement("signal")->SetAttribute("name", sig.c_str());
  }
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

}  // namespace stride::cosim
