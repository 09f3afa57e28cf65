#include "stride/cosim/system_builder.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <map>

#include "stride/cosim/error.hpp"

#ifndef STRIDE_FMU_OUTPUT_DIR
#define STRIDE_FMU_OUTPUT_DIR ""
#endif

namespace stride::cosim {

namespace fs = std::filesystem;

bool is_bundled_fmu_name(std::string_view fmu) noexcept {
  return !fmu.empty() && fmu.find('/') == std::string_view::npos && !fmu.ends_with(".fmu");
}

std::vector<fs::path> default_fmu_search_path() {
  std::vector<fs::path> paths;
  if (const char* env = std::getenv("STRIDE_FMU_PATH")) {
    std::string_view rest(env);
    while (!rest.empty()) {
      const auto colon = rest.find(':');
      const auto part = rest.substr(0, colon);
      if (!part.empty()) paths.emplace_back(part);
      if (colon == std::string_view::npos) break;
      rest.remove_prefix(colon + 1);
    }
  }
  if (std::string_view(STRIDE_FMU_OUTPUT_DIR).size() > 0) paths.emplace_back(STRIDE_FMU_OUTPUT_DIR);
  return paths;
}

fs::path resolve_fmu(const component_spec& c, const system_structure& system,
                     const std::vector<fs::path>& search_path) {
  const std::string where = c.where.str().empty() ? std::string() : c.where.str() + ": ";
  if (c.fmu.empty()) throw validation_error(where + "component '" + c.name + "' has no FMU");
  if (!is_bundled_fmu_name(c.fmu)) {
    fs::path p(c.fmu);
    if (p.is_relative()) p = system.base_dir / p;
    if (!fs::is_regular_file(p)) {
      throw validation_error(where + "component '" + c.name + "': FMU file " + p.string() +
                             " not found");
    }
    return p;
  }
  std::string searched;
  for (const auto& dir : search_path) {
    const fs::path p = dir / (c.fmu + ".fmu");
    if (fs::is_regular_file(p)) return p;
    searched += (searched.empty() ? "" : ", ") + dir.string();
  }
  throw validation_error(where + "component '" + c.name + "': bundled FMU '" + c.fmu +
                         "' not found (searched $STRIDE_FMU_PATH and the build's FMU folder: " +
                         (searched.empty() ? "nothing" : searched) + ")");
}

std::vector<std::size_t> expand_variable_group(const model_description& md,
                                               std::string_view pattern,
                                               const std::string& context) {
  auto fail = [&](const std::string& message) -> void {
    throw validation_error(context + message);
  };
  auto parse_int = [](std::string_view s, long& out) {
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size();
  };
  std::vector<std::size_t> result;
  const auto open = pattern.rfind('[');
  const bool group =
      pattern.ends_with("]") && open != std::string_view::npos &&
      (pattern.substr(open) == "[*]" || pattern.substr(open).find(':') != std::string_view::npos);
  if (!group) {
    const auto index = md.index_of(pattern);
    if (!index) fail("no variable '" + std::string(pattern) + "'");
    result.push_back(*index);
    return result;
  }
  const std::string_view base = pattern.substr(0, open);
  const std::string_view inside = pattern.substr(open + 1, pattern.size() - open - 2);
  if (inside == "*") {
    // every "base[i]" with an integer i, in ascending i
    std::vector<std::pair<long, std::size_t>> found;
    for (std::size_t v = 0; v < md.variables.size(); ++v) {
      const std::string_view name = md.variables[v].name;
      if (name.size() <= base.size() + 2 || !name.starts_with(base) || name[base.size()] != '[' ||
          name.back() != ']') {
        continue;
      }
      long i = 0;
      if (parse_int(name.substr(base.size() + 1, name.size() - base.size() - 2), i)) {
        found.emplace_back(i, v);
      }
    }
    if (found.empty())
      fail("no variables '" + std::string(base) + "[<i>]' for '" + std::string(pattern) + "'");
    std::sort(found.begin(), found.end());
    for (const auto& f : found) result.push_back(f.second);
    return result;
  }
  const auto colon = inside.find(':');
  long first = 0, last = 0;
  if (!parse_int(inside.substr(0, colon), first) || !parse_int(inside.substr(colon + 1), last)) {
    fail("malformed range '" + std::string(pattern) + "' (expected [first:last])");
  }
  const long dir = first <= last ? 1 : -1;
  for (long i = first;; i += dir) {
    const std::string name = std::string(base) + "[" + std::to_string(i) + "]";
    const auto index = md.index_of(name);
    if (!index) fail("no variable '" + name + "' (from range '" + std::string(pattern) + "')");
    result.push_back(*index);
    if (i == last) break;
  }
  return result;
}

namespace {

std::string prefix(const source_location& where) {
  const std::string s = where.str();
  return s.empty() ? s : s + ": ";
}

// "comp.var" → component index and the variable part
std::pair<std::size_t, std::string> split_name(const fixed_step_algorithm& algo,
                                               const std::string& full,
                                               const std::string& context) {
  const auto dot = full.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == full.size()) {
    throw validation_error(context + "'" + full + "' is not of the form component.variable");
  }
  const std::string comp = full.substr(0, dot);
  const auto index = algo.find_component(comp);
  if (!index) throw validation_error(context + "unknown component '" + comp + "'");
  return {*index, full.substr(dot + 1)};
}

}  // namespace

built_system build_system(const system_structure& system, const build_options& options) {
  const log_sink log = options.log ? options.log : stderr_log_sink();
  built_system built;
  built.start = system.start;

  // components: each FMU file is imported once, however many instances use it
  std::map<fs::path, std::shared_ptr<fmu>> imported;
  std::vector<std::unique_ptr<component>> components;
  for (const auto& spec : system.components) {
    component_info info;
    info.name = spec.name;
    info.step_multiple = spec.step_multiple;
    std::unique_ptr<component> c;
    if (options.factory) {
      c = options.factory(spec);
      if (!c) throw validation_error(prefix(spec.where) + "no component for '" + spec.name + "'");
    } else {
      const fs::path file = resolve_fmu(spec, system, options.fmu_search_path);
      const fs::path key = fs::weakly_canonical(file);
      auto& f = imported[key];
      try {
        if (!f) f = fmu::load(file, options.import);
        instance_options io;
        io.log = log;
        io.logging_on = options.fmu_debug_logging;
        c = f->instantiate(spec.name, io);
      } catch (const error& e) {
        throw fmu_import_error(prefix(spec.where) + "component '" + spec.name + "': " + e.what());
      }
      info.fmu = fs::absolute(file);
    }
    const auto& md = c->model_description();
    info.guid = md.guid;
    info.model_name = md.model_name;
    info.generation_tool = md.generation_tool;
    built.components.push_back(std::move(info));
    components.push_back(std::move(c));
  }

  // base step: given, or the smallest default step of the components
  duration step{};
  if (system.base_step) {
    step = *system.base_step;
  } else {
    std::optional<double> smallest;
    for (const auto& c : components) {
      if (const auto s = c->model_description().default_experiment.step_size; s && *s > 0) {
        smallest = smallest ? std::min(*smallest, *s) : *s;
      }
    }
    if (!smallest) {
      throw validation_error(prefix(system.where) +
                             "no base step: give <simulation step=\"...\"> (no FMU declares a "
                             "DefaultExperiment stepSize)");
    }
    step = duration_from_seconds(*smallest);
  }
  built.base_step = step;

  auto algo = std::make_unique<fixed_step_algorithm>(step, system.algorithm, log);
  for (std::size_t i = 0; i < components.size(); ++i) {
    const auto& spec = system.components[i];
    try {
      algo->add_component(std::move(components[i]), spec.step_multiple);
    } catch (const validation_error& e) {
      throw validation_error(prefix(spec.where) + e.what());
    }
  }

  // parameters and start values
  for (std::size_t i = 0; i < system.components.size(); ++i) {
    const auto& spec = system.components[i];
    const auto& md = algo->component_at(i).model_description();
    for (const auto& p : spec.parameters) {
      const std::string where = prefix(p.where);
      const auto index = md.index_of(p.variable);
      if (!index) {
        throw validation_error(where + "component '" + spec.name + "' has no variable '" +
                               p.variable + "'");
      }
      scalar_value value;
      try {
        value = parse_scalar(md.variables[*index].type, p.value);
      } catch (const std::invalid_argument& e) {
        throw validation_error(where + spec.name + "." + p.variable + ": " + e.what());
      }
      algo->set_start_value({i, *index}, std::move(value), p.where.str());
    }
  }

  // connections, groups expanded and paired in index order
  for (const auto& c : system.connections) {
    const std::string where = prefix(c.where);
    const std::string context = where + "connection " + c.from + " -> " + c.to + ": ";
    const auto [from_comp, from_var] = split_name(*algo, c.from, context);
    const auto [to_comp, to_var] = split_name(*algo, c.to, context);
    const auto sources =
        expand_variable_group(algo->component_at(from_comp).model_description(), from_var,
                              context + algo->component_at(from_comp).name() + ": ");
    const auto targets =
        expand_variable_group(algo->component_at(to_comp).model_description(), to_var,
                              context + algo->component_at(to_comp).name() + ": ");
    if (sources.size() != targets.size()) {
      throw validation_error(context + "the source group has " + std::to_string(sources.size()) +
                             " variables, the target group " + std::to_string(targets.size()));
    }
    for (std::size_t k = 0; k < sources.size(); ++k) {
      algo->connect({from_comp, sources[k]}, {to_comp, targets[k]},
                    connection_options{c.delayed, c.where.str()});
    }
  }

  algo->freeze();

  // run time
  if (!system.stop) {
    throw validation_error(prefix(system.where) +
                           "no stop time: give <simulation stop=\"...\"> or --stop-time");
  }
  if (*system.stop <= system.start) {
    throw validation_error(prefix(system.where) + "stop time " + format_seconds(*system.stop) +
                           " s is not after the start time " + format_seconds(system.start) + " s");
  }
  if ((*system.stop - system.start) % step != duration::zero()) {
    throw validation_error(
        prefix(system.where) + "the run length " + format_seconds(*system.stop - system.start) +
        " s is not a whole number of base steps of " + format_seconds(step) + " s");
  }
  built.stop = *system.stop;
  built.execution = std::make_unique<execution>(std::move(algo), system.start);
  return built;
}

}  // namespace stride::cosim
