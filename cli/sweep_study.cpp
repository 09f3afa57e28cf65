// The study's part of `stride sweep`: like main.cpp for `stride run`, the one place of the CLI
// that knows the DARwIn study; the collectors, checks and figures themselves live in study/.
#include <stdexcept>

#include "stride/study/run_hooks.hpp"
#include "stride/study/sweep.hpp"
#include "sweep.hpp"

namespace stride::cli {

namespace {

study::grid_table to_grid_table(const sweep_table& t) {
  study::grid_table g;
  g.axes = t.axes;
  g.columns = t.columns;
  for (const auto& r : t.rows) {
    g.axis_values.push_back(r.axis_values);
    g.values.push_back(r.values);
  }
  return g;
}

}  // namespace

sweep_extension study_sweep_extension() {
  sweep_extension e;
  sweep_profile speed_map;
  speed_map.name = "speed-map";
  speed_map.description =
      "with --grid LEARNER.eval_point=name:min:max:step,... over evaluate-point.xml: windows "
      "walked, falls, mean speed and mean reward per state into speed_map.csv (EXPERIMENTS.md)";
  speed_map.table_name = "speed_map";
  speed_map.columns = study::speed_map_columns();
  speed_map.collect = [](const std::filesystem::path& dir) {
    return study::read_speed_map_point(dir);
  };
  speed_map.overrides = [](const std::vector<sweep_target>& targets) {
    if (targets.size() != 1) {
      throw std::runtime_error("--collect speed-map: give one --grid, the learner's eval_point");
    }
    return study::speed_map_overrides(targets[0].variable, targets[0].axes_text);
  };
  speed_map.summary = [](const sweep_table& t) {
    return study::summarize_speed_map(to_grid_table(t));
  };
  speed_map.figure = [](const sweep_table& t, const std::filesystem::path& png) {
    study::write_speed_map_figure(to_grid_table(t), png);
  };
  e.profiles.push_back(std::move(speed_map));
  e.check = study::check_before_run;
  // what `stride run --quiet --no-plots` does after a run: config.ini of each learn run
  e.report = [](const cosim::run_report& report) {
    study::report_after_run(report, /*quiet=*/true, /*figures=*/false);
  };
  e.heat_map = [](const sweep_table& t, const std::filesystem::path& png) {
    study::write_grid_heat_map(to_grid_table(t), png);
  };
  return e;
}

}  // namespace stride::cli
