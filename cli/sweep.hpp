// `stride sweep`: every point of a parameter grid run as one `stride run` each (the library's
// run_system), on threads of this process or on workers, into one CSV (docs/sweep.md). Generic: the
// grid is comp.var parameters with ranges, the table holds what the caller asks for; an application
// adds named collectors (the study's speed map) and the heat map through sweep_extension.
#ifndef STRIDE_CLI_SWEEP_HPP
#define STRIDE_CLI_SWEEP_HPP

#include <CLI/CLI.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "stride/cosim/run.hpp"
#include "stride/cosim/system_structure.hpp"
#include "stride/remote/settings.hpp"

namespace stride::cli {

/// One axis of a grid: its name and its values, as written into overrides, folders and the CSV.
struct sweep_axis {
  std::string name;
  std::vector<std::string> labels;  ///< "%.12g" of min + i * step
  std::vector<double> values;
};

/// One `--grid comp.var=AXES` option: the variable takes the axes' values of a point joined by
/// ',' (one axis: a scalar; several: a vector such as a learner's eval_point "600,20").
struct sweep_target {
  std::string variable;   ///< comp.var
  std::string axes_text;  ///< AXES as given
  std::vector<sweep_axis> axes;
};

/// Parses "comp.var=name:min:max:step[,name:min:max:step...]" (one axis may omit its name; it
/// is then the variable's). \throws cosim::validation_error quoting `text`.
sweep_target parse_sweep_grid(std::string_view text);

/// One point: the values of every axis of every target, in order.
struct sweep_point {
  std::vector<std::string> labels;
  std::vector<double> values;
  std::vector<std::string> overrides;  ///< "comp.var=v1,v2", one per target
  std::string name;                    ///< "600,20": the values joined by ','
  std::string folder;                  ///< "600_20": its folder below DIR/points/
};

/// The grid's points, the last axis varying fastest. \throws cosim::validation_error when there
/// are more than a million.
std::vector<sweep_point> sweep_points(const std::vector<sweep_target>& targets);

/// The sweep's table: per point (grid order, failed points left out) the axis values, then the
/// collected columns.
struct sweep_table {
  std::vector<std::string> axes;
  std::vector<std::string> columns;
  struct row {
    std::vector<std::string> labels;
    std::vector<double> axis_values;
    std::vector<double> values;  ///< one per column (NaN allowed where the collector says so)
  };
  std::vector<row> rows;
};

/// What an application's named collector (`--collect NAME`) puts in the table, and what it adds
/// to the sweep.
struct sweep_profile {
  std::string name;         ///< as given to --collect
  std::string description;  ///< one line for --help
  std::string table_name;   ///< CSV and figure base name (DIR/<table_name>.csv)
  std::vector<std::string> columns;
  /// The column values of a finished point's folder. \throws naming the file at fault.
  std::function<std::vector<double>(const std::filesystem::path& point_dir)> collect;
  /// Overrides every point needs besides the grid's (before them); may throw to refuse a grid.
  std::function<std::vector<std::string>(const std::vector<sweep_target>&)> overrides;
  /// Text printed after the table is written (e.g. the best points); may be empty.
  std::function<std::string(const sweep_table&)> summary;
  /// The figure of a 2-D table; null: the extension's generic heat map.
  std::function<void(const sweep_table&, const std::filesystem::path& png)> figure;
};

/// What an application adds to `stride sweep` (the CLI itself knows no component).
struct sweep_extension {
  std::vector<sweep_profile> profiles;
  /// Checks each point's system before its run, as `stride run` does.
  std::function<void(const cosim::system_structure&)> check;
  /// After each point's successful run, as `stride run --quiet --no-plots` does.
  std::function<void(const cosim::run_report&)> report;
  /// A heat map of a 2-D table, one panel per column. Null: no figure.
  std::function<void(const sweep_table&, const std::filesystem::path& png)> heat_map;
};

struct sweep_arguments {
  std::filesystem::path system;
  std::vector<std::string> grids;
  std::vector<std::string> sets;
  std::vector<std::string> collect;
  std::filesystem::path output;          ///< empty: ./stride-out/<system>-sweep-<stamp>
  std::string stop_time;                 ///< empty: the system's
  std::optional<std::string> step;       ///< --step: the base step in seconds
  std::optional<std::string> algorithm;  ///< --algorithm: gauss-seidel or jacobi
  int jobs = 1;
  bool quiet = false;
  /// point k (in the order they are started) runs on workers[k % size] (`stride worker`); empty:
  /// in this process
  std::vector<std::string> workers;
  remote::dds_settings dds;
  double worker_timeout = 10;  ///< seconds to wait for a worker to appear
};

/// Runs the sweep; 0 when every point ran and was collected, 1 when one failed, 130/143 when
/// interrupted by SIGINT/SIGTERM. \throws cosim::validation_error for bad arguments.
int sweep(const sweep_arguments& args, const sweep_extension& extension);

/// Adds `stride sweep` to `app`; its callback runs the sweep and ends the parse with the exit
/// code (CLI::RuntimeError when non-zero), printing errors as `stride: error: ...`.
CLI::App* add_sweep_command(CLI::App& app, sweep_extension extension);

/// The study's collectors, checks and figures (cli/sweep_study.cpp): what main.cpp registers.
sweep_extension study_sweep_extension();

}  // namespace stride::cli

#endif  // STRIDE_CLI_SWEEP_HPP
