// A structural comparison of two systems, field by field, for round trips through an exchange
// format: what an importer reads back must be what was exported. Written forms that mean the
// same are made equal first: connection groups ("x[*]") become pairs of scalar variables in the
// order of their targets, values canonical text of their variables' types ("1" for a Boolean is
// "true") by variable name, FMUs their files' bytes. Source locations are not compared (the
// files differ).
#ifndef STRIDE_TESTS_ORCHESTRATOR_SYSTEM_COMPARE_HPP
#define STRIDE_TESTS_ORCHESTRATOR_SYSTEM_COMPARE_HPP

#include <algorithm>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "import_xml.hpp"
#include "stride/cosim/scalar_value.hpp"
#include "stride/cosim/system_builder.hpp"
#include "stride/cosim/system_structure.hpp"

namespace stride::cosim::test {

/// One system in the comparable form: one line per fact, each naming its field.
class system_facts {
 public:
  system_facts(const system_structure& s, const std::vector<std::filesystem::path>& search) {
    add("name", s.name);
    add("description", s.description);
    add("start", format_seconds(s.start));
    add("stop", s.stop ? format_seconds(*s.stop) : "-");
    add("base_step", s.base_step ? format_seconds(*s.base_step) : "-");
    add("algorithm", std::string(to_string(s.algorithm)));
    add("groups", std::to_string(s.groups.size()));
    add_record(s.record);
    add_agents(s.agents);
    for (const auto& c : s.components) add_component(s, c, search);
    add_connections(s);
  }

  const std::vector<std::string>& lines() const noexcept { return lines_; }

 private:
  void add(const std::string& field, const std::string& value) {
    lines_.push_back(field + " = " + value);
  }

  void add_record(const record_spec& r) {
    add("record.enabled", r.enabled ? "true" : "false");
    add("record.interval", r.interval ? format_seconds(*r.interval) : "-");
    add("record.file", r.file);
    for (const auto& signal : r.signals) add("record.signal", signal);
  }

  void add_agents(const agents_spec& a) {
    add("agents.count", std::to_string(a.count));
    add("agents.synchronous", a.synchronous ? "true" : "false");
    for (const auto& w : a.workers) add("agents.worker", w);
  }

  static std::string file_bytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
  }

  void add_component(const system_structure& s, const component_spec& c,
                     const std::vector<std::filesystem::path>& search) {
    const std::string at = "component " + c.name + ".";
    const std::filesystem::path file = resolve_fmu(c, s, search);
    const model_description& md = facts_.of(file, c.name + ": ");
    descriptions_.emplace_back(c.name, &md);
    // the FMU by its content: a bundled name and a copy in an archive are the same FMU
    add(at + "fmu",
        md.model_name + " " + std::to_string(std::hash<std::string>{}(file_bytes(file))));
    add(at + "step_multiple", std::to_string(c.step_multiple));
    add(at + "worker", c.worker);
    add(at + "kind", c.kind);
    add(at + "model_exchange", c.model_exchange ? "yes" : "no");
    // a variable's last value counts; values of different variables in any order mean the same
    // (SSP keeps placeholders apart from the parameter set)
    std::map<std::string, std::string> values;
    for (const auto& p : c.parameters) {
      const variable_description* v = md.find(p.variable);
      const bool typed = v != nullptr && v->type != variable_type::string &&
                         p.value.find("${") == std::string::npos;
      values[p.variable] = typed ? format_scalar(parse_scalar(v->type, p.value)) : p.value;
    }
    for (const auto& [variable, value] : values) add(at + "parameter " + variable, value);
  }

  // every connection as scalar pairs "a.y -> b.u", ordered by target
  void add_connections(const system_structure& s) {
    std::vector<std::string> pairs;
    for (const auto& c : s.connections) {
      const auto from = scalars(c.from);
      const auto to = scalars(c.to);
      const std::string how = std::string(c.delayed ? " delayed" : "") + " factor " +
                              format_scalar(c.factor) + " offset " + format_scalar(c.offset);
      for (std::size_t k = 0; k < std::max(from.size(), to.size()); ++k) {
        pairs.push_back((k < to.size() ? to[k] : "?") + " <- " + (k < from.size() ? from[k] : "?") +
                        how);
      }
    }
    std::sort(pairs.begin(), pairs.end());
    for (const auto& p : pairs) add("connection", p);
  }

  // "comp.var[*]" or "comp[*].var" as the names of its scalar variables, in pairing order
  std::vector<std::string> scalars(const std::string& side) const {
    std::vector<std::string> names;
    for (const auto& d : descriptions_) names.push_back(d.first);
    const std::size_t end = component_end(side, [&](std::string_view n) {
      return std::find(names.begin(), names.end(), n) != names.end();
    });
    if (end == std::string::npos) return {side + " (no component)"};
    std::vector<std::string> out;
    for (std::size_t c : expand_component_group(names, side.substr(0, end), side)) {
      const model_description& md = *descriptions_[c].second;
      for (std::size_t v : expand_variable_group(md, side.substr(end + 1), side)) {
        out.push_back(names[c] + "." + md.variables[v].name);
      }
    }
    return out;
  }

  detail::fmu_facts facts_;
  std::vector<std::pair<std::string, const model_description*>> descriptions_;
  std::vector<std::string> lines_;
};

}  // namespace stride::cosim::test

#endif  // STRIDE_TESTS_ORCHESTRATOR_SYSTEM_COMPARE_HPP
