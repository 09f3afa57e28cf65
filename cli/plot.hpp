// `stride plot RUN_DIR`: the figures of any run (stride/cosim/run_plots.hpp) and what the
// application adds for its own runs.
#ifndef STRIDE_CLI_PLOT_HPP
#define STRIDE_CLI_PLOT_HPP

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace stride::cli {

struct plot_arguments {
  std::filesystem::path run_dir;
  std::vector<std::string> signals;  ///< --signals values (comma-separated patterns)
  bool quiet = false;
};

/// The application's figures for a run folder (run folder, quiet) → the PNGs it wrote (none when
/// the folder is not one of its runs).
using plot_extension =
    std::function<std::vector<std::filesystem::path>(const std::filesystem::path&, bool)>;

/// Adds the `plot` subcommand filling `args`.
CLI::App* add_plot_command(CLI::App& app, plot_arguments& args);

/// Writes the generic figures, then the application's. Returns the exit code; \throws
/// validation_error when nothing at all could be plotted, for bad patterns and gnuplot failures.
int plot(const plot_arguments& args, const plot_extension& extension);

}  // namespace stride::cli

#endif  // STRIDE_CLI_PLOT_HPP
