#include "stride/study/gait_link.hpp"

#include <fstream>
#include <stdexcept>

#include "stride/common/files.hpp"
#include "stride/cosim/error.hpp"
#include "stride/gait/config_ini.hpp"
#include "stride/gait/walking_params.hpp"
#include "stride/learner/artefacts.hpp"

namespace stride::study {

namespace fs = std::filesystem;

namespace {

const cosim::parameter_setting* find_parameter(const cosim::component_spec& c,
                                               const std::string& name) {
  for (const auto& p : c.parameters) {
    if (p.variable == name) return &p;
  }
  return nullptr;
}

std::string where(const cosim::parameter_setting& p) {
  const std::string s = p.where.str();
  return s.empty() ? s : s + ": ";
}

// the grid of a learner: its parameter, or the learner's default
learner::state_grid grid_of(const cosim::component_spec& c) {
  const auto* p = find_parameter(c, "grid");
  return p ? learner::state_grid::parse(p->value, "grid") : learner::learner_config{}.grid;
}

}  // namespace

bool is_learner(const cosim::component_spec& c) {
  return c.fmu == "learner" || fs::path(c.fmu).filename() == "learner.fmu";
}

void check_grid_against_gait(const learner::state_grid& grid, const std::string& what) {
  for (const auto& d : grid.dimensions()) {
    const gait::param_info* p = gait::find_param(d.name);
    if (p == nullptr) continue;
    for (double v : {d.value(0), d.value(d.count - 1)}) {
      try {
        gait::check_param_value(*p, v);
      } catch (const std::invalid_argument& e) {
        throw learner::learner_error(what + " dimension " + d.name + ": " + e.what());
      }
    }
  }
}

void check_learner_grids(const cosim::system_structure& system) {
  for (const auto& c : system.components) {
    if (!is_learner(c)) continue;
    const auto* grid = find_parameter(c, "grid");
    const auto* point = find_parameter(c, "eval_point");
    const cosim::parameter_setting* at = grid;
    try {
      const learner::state_grid g = grid_of(c);
      if (grid) check_grid_against_gait(g, c.name + ".grid");
      if (point) {
        // an evaluation point need not lie on the grid, but within the gait's ranges
        at = point;
        const auto values = learner::parse_number_list(point->value, c.name + ".eval_point");
        std::string as_grid;
        for (std::size_t i = 0; i < values.size() && i < g.dimension_count(); ++i) {
          const std::string v = learner::format_number(values[i]);
          as_grid +=
              (as_grid.empty() ? "" : ",") + g.dimensions()[i].name + ":" + v + ":" + v + ":1";
        }
        if (!as_grid.empty()) {
          check_grid_against_gait(learner::state_grid::parse(as_grid), c.name + ".eval_point");
        }
      }
    } catch (const learner::learner_error& e) {
      throw cosim::validation_error((at ? where(*at) : std::string()) + e.what());
    }
  }
}

void write_best_config(const fs::path& out,
                       const std::vector<std::pair<std::string, double>>& settings,
                       const learner::state_grid& grid, const std::vector<double>& values) {
  gait::walking_params params{};
  for (const auto& [key, v] : settings) gait::set_param(params, *gait::find_param(key), v);
  for (std::size_t d = 0; d < grid.dimension_count() && d < values.size(); ++d) {
    const gait::param_info* p = gait::find_param(grid.dimensions()[d].name);
    if (p != nullptr) gait::set_param(params, *p, values[d]);
  }
  common::write_file_atomically(out, gait::make_walking_config_text(params));
}

std::vector<fs::path> write_best_configs(const cosim::system_structure& system) {
  std::vector<fs::path> written;
  for (const auto& c : system.components) {
    if (!is_learner(c)) continue;
    const auto* mode = find_parameter(c, "mode");
    const auto* out = find_parameter(c, "output_dir");
    if ((mode && mode->value != "0") || !out || out->value.empty()) continue;
    const fs::path dir = out->value;
    if (!fs::exists(dir / learner::run_files::value_table)) continue;
    // the best state: the largest V, the lowest index among equals (rows are in index order)
    const learner::csv_columns v = learner::read_csv_log(dir / learner::run_files::value_table);
    const learner::state_grid grid = grid_of(c);
    if (v.rows.size() != grid.size()) continue;
    std::size_t best = 0;
    for (std::size_t s = 1; s < v.rows.size(); ++s) {
      if (v.rows[s].back() > v.rows[best].back()) best = s;
    }
    // the settings of the gait the learner drives: the target of its value[i] outputs
    std::vector<std::pair<std::string, double>> settings;
    for (const auto& conn : system.connections) {
      if (!conn.from.starts_with(c.name + ".value[")) continue;
      const std::string gait_name = conn.to.substr(0, conn.to.find('.'));
      for (const auto& g : system.components) {
        if (g.name != gait_name) continue;
        for (const auto& p : g.parameters) {
          if (gait::find_param(p.variable) != nullptr) {
            settings.emplace_back(p.variable,
                                  learner::parse_number(p.value, g.name + "." + p.variable));
          }
        }
      }
      break;
    }
    write_best_config(dir / "config.ini", settings, grid, grid.values(best));
    written.push_back(dir / "config.ini");
  }
  return written;
}

}  // namespace stride::study
