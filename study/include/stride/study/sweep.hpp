// The study's part of `stride sweep` (docs/sweep.md): the speed map, i.e. every state of a
// learner's grid walked with models/experiments/evaluate-point.xml and measured as the learner
// would see it (EXPERIMENTS.md), and the heat maps of 2-D sweeps.
#ifndef STRIDE_STUDY_SWEEP_HPP
#define STRIDE_STUDY_SWEEP_HPP

#include <filesystem>
#include <string>
#include <vector>

namespace stride::study {

/// A table of grid points: per row the values of the axes, then of the columns.
struct grid_table {
  std::vector<std::string> axes;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> axis_values;  ///< per row
  std::vector<std::vector<double>> values;       ///< per row, one per column
};

/// The speed map's columns: W-footstep windows walked without a fall, falls, mean speed over
/// those windows (cm/s), mean reward per RL step as the learner sees it (falls included).
std::vector<std::string> speed_map_columns();

/// The speed map's columns for one evaluation run's folder, from evaluation.csv and steps.csv.
/// The evaluator counts a fall as a window, so windows = windows - falls; the mean speed is NaN
/// when no window was walked, the mean reward NaN when no RL step was logged.
/// \throws std::runtime_error naming the file that is missing or malformed.
std::vector<double> read_speed_map_point(const std::filesystem::path& dir);

/// What the evaluator needs besides its point: `comp.eval_point` swept over `grid_text`
/// (name:min:max:step,...) takes `comp.grid=grid_text`, so that every point is a state of its
/// grid. \throws std::runtime_error unless `variable` is a `comp.eval_point`.
std::vector<std::string> speed_map_overrides(const std::string& variable,
                                             const std::string& grid_text);

/// "N states, K fell at least once", then the five fastest states without a fall and the five
/// of highest mean reward.
std::string summarize_speed_map(const grid_table& table);

/// Two heat maps side by side (first axis x, second y): mean speed, with the states that fell
/// crossed and the fastest without a fall circled, and mean reward. \throws std::runtime_error
/// when gnuplot is missing or fails.
void write_speed_map_figure(const grid_table& table, const std::filesystem::path& png);

/// A heat map per column of a 2-D table (first axis x, second y), side by side.
/// \throws std::runtime_error when gnuplot is missing or fails.
void write_grid_heat_map(const grid_table& table, const std::filesystem::path& png);

}  // namespace stride::study

#endif  // STRIDE_STUDY_SWEEP_HPP
