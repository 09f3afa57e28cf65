// `stride plot RUN_DIR`: figures of a learner run (learner.fmu artefacts) with gnuplot.
#ifndef STRIDE_CLI_PLOT_HPP
#define STRIDE_CLI_PLOT_HPP

#include <filesystem>
#include <string>
#include <vector>

namespace stride::cli {

/// Whether `dir` (or a folder right below it) holds learner artefacts (v_table.csv or
/// evaluation.csv).
bool has_learner_artefacts(const std::filesystem::path& dir);

/// Writes the PNGs of every learner run found in `dir` and its subfolders into `dir`/figures:
/// V heatmap (first two grid dimensions, max over the others) for the final table and each
/// snapshot, max-V profile per parameter, Σ|ΔV| per episode with a 50-episode moving average,
/// accumulated reward per episode, travelled x-y paths, and for evaluation runs the mean speed
/// and falls per point. Returns the files written. \throws std::runtime_error when gnuplot is
/// missing or fails, or nothing plottable is found.
std::vector<std::filesystem::path> write_figures(const std::filesystem::path& dir);

/// Text summary of the run for the terminal: best.txt of each learner, the evaluation table.
std::string summarize_run(const std::filesystem::path& dir);

struct plot_arguments {
  std::filesystem::path run_dir;
  bool quiet = false;
};

int plot(const plot_arguments& args);

}  // namespace stride::cli

#endif  // STRIDE_CLI_PLOT_HPP
