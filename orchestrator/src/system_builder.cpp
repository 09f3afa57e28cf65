#include "stride/cosim/system_builder.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <map>
#include <set>

#include "stride/cosim/error.hpp"

#ifndef STRIDE_FMU_OUTPUT_DIR
#define STRIDE_FMU_OUTPUT_DIR ""
#endif

namespace stride::cosim {

namespace fs = std::filesystem;

fs::path installed_data_dir() {
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (error) return {};
  const fs::path data = program.parent_path().parent_path() / "share" / "stride";
  return fs::is_directory(data, error) ? data : fs::path();
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
  if (const fs::path installed = installed_data_dir(); !installed.empty()) {
    paths.push_back(installed / "fmus");
  } else if (std::string_view(STRIDE_FMU_OUTPUT_DIR).size() > 0) {
    paths.emplace_back(STRIDE_FMU_OUTPUT_DIR);
  }
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
                         "' not found (searched $STRIDE_FMU_PATH and the bundled FMU folder: " +
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

std::vector<std::size_t> expand_component_group(const std::vector<std::string>& names,
                                                const std::string& comp,
                                                const std::string& context) {
  if (const auto it = std::find(names.begin(), names.end(), comp); it != names.end()) {
    return {static_cast<std::size_t>(it - names.begin())};
  }
  const auto open = comp.rfind('[');
  if (open != std::string::npos && comp.ends_with("]")) {
    const std::string base = comp.substr(0, open);
    const std::string inside = comp.substr(open + 1, comp.size() - open - 2);
    std::vector<std::pair<long, std::size_t>> found;
    for (std::size_t c = 0; c < names.size(); ++c) {
      const std::string& name = names[c];
      if (!name.starts_with(base + "[") || !name.ends_with("]")) continue;
      found.emplace_back(std::stol(name.substr(base.size() + 1)), c);
    }
    std::sort(found.begin(), found.end());
    std::vector<std::size_t> result;
    if (inside == "*") {
      for (const auto& f : found) result.push_back(f.second);
    } else if (const auto colon = inside.find(':'); colon != std::string::npos) {
      long first = 0, last = 0;
      const auto parse = [](std::string_view t, long& v) {
        auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
        return ec == std::errc() && end == t.data() + t.size();
      };
      if (!parse(std::string_view(inside).substr(0, colon), first) ||
          !parse(std::string_view(inside).substr(colon + 1), last) || first > last) {
        throw validation_error(context + "malformed copy range '" + comp +
                               "' (expected [first:last], first <= last)");
      }
      for (const auto& f : found) {
        if (f.first >= first && f.first <= last) result.push_back(f.second);
      }
      if (result.size() != static_cast<std::size_t>(last - first + 1)) {
        throw validation_error(context + "'" + comp + "': only " + std::to_string(found.size()) +
                               " copies of '" + base + "' exist");
      }
    }
    if (!result.empty()) return result;
    if (inside == "*") {
      throw validation_error(context + "no copies '" + base + "[<k>]' for '" + comp + "'");
    }
    if (!found.empty()) {
      throw validation_error(context + "unknown component '" + comp + "' (the copies are " + base +
                             "[1].." + base + "[" + std::to_string(found.size()) + "])");
    }
  }
  throw validation_error(context + "unknown component '" + comp + "'");
}

namespace {

std::string prefix(const source_location& where) {
  const std::string s = where.str();
  return s.empty() ? s : s + ": ";
}

// the components a connection side names: "comp", or the copies "comp[*]" / "comp[2:3]"
std::vector<std::size_t> expand_components(const execution& ex, const std::string& comp,
                                           const std::string& context) {
  if (const auto index = ex.find_component(comp)) return {*index};
  std::vector<std::string> names;
  for (std::size_t c = 0; c < ex.component_count(); ++c) names.push_back(ex.component_at(c).name());
  return expand_component_group(names, comp, context);
}

// one side of a connection, "comp.var" with groups on either part → variables in pairing order
std::vector<variable_id> expand_side(const execution& ex, const std::string& full,
                                     const std::string& context) {
  const auto dot = component_end(
      full, [&](std::string_view name) { return ex.find_component(name).has_value(); });
  if (dot == std::string::npos || dot == 0 || dot + 1 == full.size()) {
    throw validation_error(context + "'" + full + "' is not of the form component.variable");
  }
  std::vector<variable_id> result;
  for (std::size_t c : expand_components(ex, full.substr(0, dot), context)) {
    const auto& comp = ex.component_at(c);
    for (std::size_t v : expand_variable_group(comp.model_description(), full.substr(dot + 1),
                                               context + comp.name() + ": ")) {
      result.push_back({c, v});
    }
  }
  return result;
}

}  // namespace

std::vector<std::vector<std::size_t>> worker_groups(const execution& ex,
                                                    const std::vector<std::string>& workers,
                                                    algorithm_kind kind) {
  // connected sets per worker (union-find over connections within one worker)
  const std::size_t n = ex.component_count();
  std::vector<std::size_t> root(n);
  for (std::size_t i = 0; i < n; ++i) root[i] = i;
  const auto find = [&](std::size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  for (const auto& c : ex.connections()) {
    const std::size_t a = c.from.component, b = c.to.component;
    if (a != b && !workers.at(a).empty() && workers.at(a) == workers.at(b)) {
      root[std::max(find(a), find(b))] = std::min(find(a), find(b));
    }
  }
  std::map<std::size_t, std::vector<std::size_t>> sets;
  for (std::size_t i = 0; i < n; ++i) sets[find(i)].push_back(i);
  // a group carries values between its members as they are (its links know no factor or
  // offset): members joined by a transforming connection step one by one
  std::set<std::size_t> transformed;
  for (const auto& c : ex.connections()) {
    if (c.options.transforms() && find(c.from.component) == find(c.to.component)) {
      transformed.insert(find(c.from.component));
    }
  }
  std::vector<std::vector<std::size_t>> groups;
  for (auto& [first, members] : sets) {
    if (members.size() > 1 && !transformed.contains(first)) groups.push_back(std::move(members));
  }
  if (kind == algorithm_kind::gauss_seidel) {
    const auto kept = steppable_groups(n, ex.connections(), groups);
    std::vector<std::vector<std::size_t>> steppable;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      if (kept[g]) steppable.push_back(std::move(groups[g]));
    }
    groups = std::move(steppable);
  }
  return groups;
}

std::optional<duration> base_step_of(const system_structure& system,
                                     const std::vector<const model_description*>& models) {
  if (system.base_step) return system.base_step;
  std::optional<double> smallest;
  for (const model_description* md : models) {
    if (const auto s = md->default_experiment.step_size; s && *s > 0) {
      smallest = smallest ? std::min(*smallest, *s) : *s;
    }
  }
  if (!smallest) return std::nullopt;
  return duration_from_seconds(*smallest);
}

built_system build_system(const system_structure& structure, const build_options& options) {
  const system_structure system = expand_replicas(structure);
  const log_sink log = options.log ? options.log : stderr_log_sink();
  built_system built;
  built.start = system.start;

  // components, each created where its spec places it
  placement_context context{&system, options.fmu_search_path, options.import, log,
                            options.fmu_debug_logging};
  in_process_placement in_process;
  std::vector<std::unique_ptr<component>> components;
  std::vector<placement_resolver*> made_by;  // per component
  for (const auto& resolver : options.placements) resolver->prepare(system);
  for (const auto& spec : system.components) {
    component_info info;
    info.name = spec.name;
    info.step_multiple = spec.step_multiple;
    info.worker = spec.worker;
    std::unique_ptr<component> c;
    placement_resolver* maker = nullptr;
    for (const auto& resolver : options.placements) {
      c = resolver->create(spec, context);
      if (c) {
        info.fmu = resolver->source_of(spec);
        maker = resolver.get();
        break;
      }
    }
    if (!c) {
      c = in_process.create(spec, context);
      info.fmu = in_process.source_of(spec);
      maker = &in_process;
    }
    made_by.push_back(maker);
    if (!c) {
      throw validation_error(prefix(spec.where) + "component '" + spec.name + "': worker \"" +
                             spec.worker +
                             "\" placement needs a resolver for worker processes, which this "
                             "build does not have");
    }
    const auto& md = c->model_description();
    info.guid = md.guid;
    info.model_name = md.model_name;
    info.generation_tool = md.generation_tool;
    built.components.push_back(std::move(info));
    components.push_back(std::move(c));
  }

  std::vector<const model_description*> models;
  for (const auto& c : components) models.push_back(&c->model_description());
  const std::optional<duration> base_step = base_step_of(system, models);
  if (!base_step) {
    throw validation_error(prefix(system.where) +
                           "no base step: give <simulation step=\"...\"> (no FMU declares a "
                           "DefaultExperiment stepSize)");
  }
  const duration step = *base_step;
  built.base_step = step;

  auto ex = std::make_unique<execution>(
      std::make_unique<fixed_step_algorithm>(step, system.algorithm, options.threads), system.start,
      log);
  for (std::size_t i = 0; i < components.size(); ++i) {
    const auto& spec = system.components[i];
    try {
      ex->add_component(std::move(components[i]), spec.step_multiple);
    } catch (const validation_error& e) {
      throw validation_error(prefix(spec.where) + e.what());
    }
  }

  // parameters and start values
  for (std::size_t i = 0; i < system.components.size(); ++i) {
    const auto& spec = system.components[i];
    const auto& md = ex->component_at(i).model_description();
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
      ex->set_start_value({i, *index}, std::move(value), p.where.str());
    }
  }

  // connections, groups expanded and paired in order
  for (const auto& c : system.connections) {
    const std::string context = prefix(c.where) + "connection " + c.from + " -> " + c.to + ": ";
    const auto sources = expand_side(*ex, c.from, context);
    const auto targets = expand_side(*ex, c.to, context);
    if (sources.size() != targets.size()) {
      throw validation_error(context + "the source group has " + std::to_string(sources.size()) +
                             " variables, the target group " + std::to_string(targets.size()));
    }
    for (std::size_t k = 0; k < sources.size(); ++k) {
      ex->connect(sources[k], targets[k],
                  connection_options{c.delayed, c.where.str(), c.factor, c.offset});
    }
  }

  // connected components on one worker step there together, when their placement can
  std::vector<std::string> workers;
  for (const auto& spec : system.components) workers.push_back(spec.worker);
  for (const auto& members : worker_groups(*ex, workers, system.algorithm)) {
    std::vector<component*> parts;
    std::string names;
    bool one_maker = true;
    for (std::size_t i : members) {
      parts.push_back(&ex->component_at(i));
      names += (names.empty() ? "" : ", ") + ex->component_at(i).name();
      one_maker = one_maker && made_by[i] == made_by[members.front()];
    }
    auto group = one_maker ? made_by[members.front()]->create_group(parts) : nullptr;
    if (!group) continue;
    log(log_level::info, "stride", "",
        names + " step together on worker '" + workers[members.front()] + "'");
    ex->add_group(members, std::move(group));
    built.groups.push_back(members);
  }

  ex->freeze();

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
  built.execution = std::move(ex);
  return built;
}

}  // namespace stride::cosim
