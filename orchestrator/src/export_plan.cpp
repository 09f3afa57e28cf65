// The checks and the canonical form both exporters start from (docs/ssp.md, "Export"). Every
// choice here serves two promises: the exported system runs exactly as the original, and the
// same system always exports to the same bytes (FMU names, connection and value order do not
// depend on how the system was written).
#include "export_plan.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <tuple>

#include "stride/cosim/error.hpp"
#include "stride/cosim/scalar_value.hpp"
#include "stride/cosim/system_builder.hpp"

namespace stride::cosim::detail {

namespace fs = std::filesystem;

void refuse_export(std::string_view format, const source_location& where, const std::string& what) {
  const std::string place = where.str();
  throw validation_error((place.empty() ? "" : place + ": ") + "cannot export to " +
                         std::string(format) + ": " + what);
}

export_plan::export_plan(const system_structure& system, const std::vector<fs::path>& search,
                         std::string_view format)
    : format_(format) {
  // SSP writes the copies of replica groups as components of their own: any SSP tool sees
  // every FMU instance, and Stride's importer accepts the copies' names "gait[1]"
  system_ = ssp() ? expand_replicas(system) : system;
  if (!ssp()) check_osp_system();
  for (const auto& c : system_.components) add_component(c, search);
  if (components_.empty()) refuse_export(format_, system_.where, "the system has no component");
  for (const auto& c : system_.connections) add_connection(c);
  finish_connections();
}

// what belongs to a run rather than to the system: OSP has no word for it, and its importer
// gives the defaults back (record every output at every base step into results.csv); SSP
// carries it in Stride's annotations
void export_plan::check_osp_system() const {
  const system_structure& s = system_;
  if (!s.groups.empty()) {
    const replica_group& g = s.groups.front();
    const std::string copy = g.components.empty() ? g.name : g.components.front().name;
    refuse_export(format_, g.where,
                  "replica group '" + g.name + "': the copies' names (\"" + copy +
                      "[1]\") are not valid element names");
  }
  if (s.agents.count > 0) {
    refuse_export(format_, s.agents.where,
                  "<agents>: several agents are a way of running the system (stride run "
                  "--agents)");
  }
  if (!s.failover.standby.empty()) {
    refuse_export(format_, s.failover.where,
                  "<failover>: standby workers are a way of running the system (stride run "
                  "--standby)");
  }
  const record_spec& r = s.record;
  const std::string run_option =
      " (OSP says nothing of recording; give it to stride run: --record, "
      "--record-interval)";
  if (!r.enabled) refuse_export(format_, r.where, "recording is switched off" + run_option);
  if (!r.signals.empty()) {
    const source_location at = r.signal_locations.empty() ? r.where : r.signal_locations.front();
    refuse_export(format_, at, "the recorded signals (" + r.signals.front() + ")" + run_option);
  }
  if (r.interval && (!s.base_step || *r.interval != *s.base_step)) {
    refuse_export(format_, r.where,
                  "the recording interval " + format_seconds(*r.interval) +
                      " s is not the base step" + run_option);
  }
  if (r.file != "results.csv") {
    refuse_export(
        format_, r.where,
        "the results file \"" + r.file + "\" (the OSP importer records into results.csv)");
  }
}

void export_plan::add_component(const component_spec& c, const std::vector<fs::path>& search) {
  const std::string who = "component '" + c.name + "': ";
  if (const std::string problem = component_name_problem(c.name, ssp()); !problem.empty()) {
    refuse_export(format_, c.where, who + problem);
  }
  if (!c.worker.empty() && !ssp()) {
    refuse_export(format_, c.where,
                  who + "runs on worker '" + c.worker + "' (placement is a Stride setting)");
  }
  if ((c.kind == "model-exchange" || c.model_exchange) && !ssp()) {
    refuse_export(format_, c.where,
                  who + "Model Exchange (OSP runs Co-Simulation; SSP export keeps it)");
  }
  const fs::path file = resolve_fmu(c, system_, search);
  const std::string where = c.where.str().empty() ? std::string() : c.where.str() + ": ";
  export_component out;
  out.spec = &c;
  out.description = &facts_.of(file, where + who);
  const fs::path canonical = fs::weakly_canonical(file);
  const auto known = std::find(canonical_.begin(), canonical_.end(), canonical);
  out.fmu = static_cast<std::size_t>(known - canonical_.begin());
  if (known == canonical_.end()) {
    fmus_.push_back({file, fmu_name_for(file)});
    canonical_.push_back(canonical);
  }
  add_values(out);
  components_.push_back(std::move(out));
}

// the file's own name; a second FMU of the same name gets "-2", "-3", ... (in component order)
std::string export_plan::fmu_name_for(const fs::path& file) const {
  const std::string stem = file.stem().string();
  const auto taken = [&](const std::string& name) {
    return std::any_of(fmus_.begin(), fmus_.end(),
                       [&](const export_fmu& f) { return f.name == name; });
  };
  std::string name = stem + ".fmu";
  for (int k = 2; taken(name); ++k) name = stem + "-" + std::to_string(k) + ".fmu";
  return name;
}

// each value checked against its variable's type and written canonically ("1" for a Boolean
// becomes "true"); a variable given twice keeps its first place and its last value, as the
// importers make of it. A placeholder in a value that is not a String ("${agent}" for an
// Integer) is the run's to substitute: no SSP type holds it, so SSP keeps it apart (in Stride's
// component annotation); OSP has no place for it.
void export_plan::add_values(export_component& out) {
  const component_spec& c = *out.spec;
  for (const auto& p : c.parameters) {
    const std::string name = c.name + "." + p.variable;
    const variable_description* v = out.description->find(p.variable);
    if (v == nullptr) refuse_export(format_, p.where, "parameter '" + name + "': no such variable");
    std::string text = p.value;
    const bool placeholder =
        v->type != variable_type::string && text.find("${") != std::string::npos;
    if (placeholder && !ssp()) {
      refuse_export(format_, p.where,
                    "parameter '" + name + "': the placeholder in '" + text + "' (a " +
                        std::string(to_string(v->type)) + " must be a plain value)");
    }
    if (v->type != variable_type::string && !placeholder) {
      try {
        text = format_scalar(parse_scalar(v->type, text));
      } catch (const std::invalid_argument& e) {
        refuse_export(format_, p.where, "parameter '" + name + "': " + e.what());
      }
    }
    set_value(placeholder ? out.placeholders : out.values, v, std::move(text));
    erase_value(placeholder ? out.values : out.placeholders, v);
  }
}

void export_plan::set_value(std::vector<export_value>& values, const variable_description* v,
                            std::string text) {
  const auto same = [&](const export_value& e) { return e.variable == v; };
  if (auto it = std::find_if(values.begin(), values.end(), same); it != values.end()) {
    it->text = std::move(text);
  } else {
    values.push_back({v, std::move(text)});
  }
}

void export_plan::erase_value(std::vector<export_value>& values, const variable_description* v) {
  std::erase_if(values, [&](const export_value& e) { return e.variable == v; });
}

// "comp.var", "comp.var[*]" or "comp.var[2:5]" as (component, variable) pairs, ascending; the
// component part may name a replica group's copies ("gait[*]", "gait[2:3]"), as for a run
std::vector<std::pair<std::size_t, std::size_t>> export_plan::expand_side(
    const connection_spec& c, const std::string& side) const {
  std::vector<std::string> names;
  for (const auto& component : system_.components) names.push_back(component.name);
  const std::size_t end = component_end(side, [&](std::string_view n) {
    return std::find(names.begin(), names.end(), n) != names.end();
  });
  const std::string what = "connection " + c.from + " -> " + c.to + ": ";
  std::vector<std::size_t> components;
  if (end != std::string::npos) {
    const std::string component = side.substr(0, end);
    try {
      components = expand_component_group(names, component, "'" + side + "': ");
    } catch (const validation_error& e) {
      // an unknown copy range says what is wrong with it; an unknown name is plainly unknown
      if (component.find('[') != std::string::npos)
        refuse_export(format_, c.where, what + e.what());
    }
  }
  if (components.empty())
    refuse_export(format_, c.where, what + "'" + side + "' names no component");
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (const std::size_t component : components) {
    try {
      for (std::size_t v : expand_variable_group(*components_[component].description,
                                                 side.substr(end + 1), "'" + side + "': ")) {
        out.emplace_back(component, v);
      }
    } catch (const validation_error& e) {
      refuse_export(format_, c.where, what + e.what());
    }
  }
  return out;
}

// SSP and OSP connect an output to an input or parameter; the importers read nothing else
void export_plan::add_connection(const connection_spec& c) {
  const auto from = expand_side(c, c.from);
  const auto to = expand_side(c, c.to);
  const std::string what = "connection " + c.from + " -> " + c.to + ": ";
  if (from.size() != to.size()) {
    refuse_export(format_, c.where,
                  what + std::to_string(from.size()) + " sources for " + std::to_string(to.size()) +
                      " targets");
  }
  for (std::size_t k = 0; k < from.size(); ++k) {
    const auto& source = components_[from[k].first].description->variables[from[k].second];
    const auto& target = components_[to[k].first].description->variables[to[k].second];
    if (source.causality != causality::output) {
      refuse_export(format_, c.where,
                    what + "its source " + source.name + " is " +
                        std::string(to_string(source.causality)) + ", not an output");
    }
    if (target.causality != causality::input && target.causality != causality::parameter) {
      refuse_export(format_, c.where,
                    what + "its target " + target.name + " is " +
                        std::string(to_string(target.causality)) + ", not an input or parameter");
    }
    connections_.push_back({from[k].first, to[k].first, from[k].second, to[k].second, c.delayed,
                            c.factor, c.offset, c.where});
  }
}

void export_plan::finish_connections() {
  std::stable_sort(connections_.begin(), connections_.end(), [](const auto& a, const auto& b) {
    return std::tie(a.to, a.to_variable) < std::tie(b.to, b.to_variable);
  });
  for (std::size_t k = 1; k < connections_.size(); ++k) {
    const auto& a = connections_[k - 1];
    const auto& b = connections_[k];
    if (a.to == b.to && a.to_variable == b.to_variable) {
      const auto& c = components_[b.to];
      refuse_export(format_, b.where,
                    c.spec->name + "." + c.description->variables[b.to_variable].name +
                        " is the target of two connections");
    }
  }
  for (const auto& c : connections_) {
    components_[c.from].connectors.push_back(c.from_variable);
    components_[c.to].connectors.push_back(c.to_variable);
  }
  for (auto& c : components_) {
    std::sort(c.connectors.begin(), c.connectors.end());
    c.connectors.erase(std::unique(c.connectors.begin(), c.connectors.end()), c.connectors.end());
  }
}

std::string uri_path(std::string_view text) {
  std::string out;
  for (const char ch : text) {
    const auto u = static_cast<unsigned char>(ch);
    // RFC 3986's unreserved characters, ASCII whatever the locale
    const bool plain = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
                       (ch >= '0' && ch <= '9') || ch == '-' || ch == '.' || ch == '_' ||
                       ch == '~' || ch == '/';
    if (plain) {
      out += ch;
    } else {
      char escaped[4];
      std::snprintf(escaped, sizeof escaped, "%%%02X", u);
      out += escaped;
    }
  }
  return out;
}

std::string xml_text(const tinyxml2::XMLDocument& doc) {
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

void check_export_target(const fs::path& target, bool folder, bool overwrite) {
  std::error_code error;
  if (!fs::exists(target, error)) return;
  if (folder != fs::is_directory(target, error)) {
    throw validation_error(target.string() + ": exists and is not " +
                           (folder ? "a folder" : "a file"));
  }
  if (overwrite) return;
  if (!folder) {
    throw validation_error(target.string() + ": exists (give --force to replace it)");
  }
  if (!fs::is_empty(target, error)) {
    throw validation_error(target.string() +
                           ": a folder that is not empty (give --force to write into it)");
  }
}

std::optional<duration> export_plan::base_step() const {
  std::vector<const model_description*> models;
  for (const auto& c : components_) models.push_back(c.description);
  return base_step_of(system_, models);
}

}  // namespace stride::cosim::detail
