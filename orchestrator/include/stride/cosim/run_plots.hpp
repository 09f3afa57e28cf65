// Figures of any run (`stride plot RUN_DIR`): the x-y path of every base pose in the results
// CSV and chosen signals over time, as gnuplot PNGs in RUN_DIR/figures. Applications add their
// own figures on top (the study's learner figures).
//
// Naming rule for poses: a results column `P.base_x` together with a column `P.base_y` (the same
// prefix P, e.g. a component name) is the planar position of one base; its path is drawn as
// figures/path_P.png. No component is known here: any prefix that follows the rule is drawn.
#ifndef STRIDE_COSIM_RUN_PLOTS_HPP
#define STRIDE_COSIM_RUN_PLOTS_HPP

#include <filesystem>
#include <string>
#include <vector>

namespace stride::cosim {

/// The results CSV of the run in `dir`: the file manifest.json names ("results"), else
/// `results.csv`; empty when there is none.
std::filesystem::path run_results_file(const std::filesystem::path& dir);

/// The prefixes P of the pose columns (`P.base_x` with `P.base_y`) among `columns`, in column
/// order.
std::vector<std::string> pose_prefixes(const std::vector<std::string>& columns);

/// Signal patterns from `--signals` values: each value split at commas, blanks trimmed.
/// \throws validation_error for an empty pattern (naming the value it came from).
std::vector<std::string> split_signal_patterns(const std::vector<std::string>& values);

/// Writes into `dir`/figures, for `dir` and each folder right below it holding a run (agents):
/// `path_P.png` for every pose P of its results and `signal_NAME.png` for every column matching
/// one of `signal_patterns` (`*`, `?`), each with the `.dat` (a `# ...` header naming the columns,
/// then one row per results row) and `.gp` files it was drawn from; files of a folder below are
/// prefixed `FOLDER_`. Returns the PNGs written (none: nothing to plot; figures/ is then not
/// created). \throws validation_error when a pattern matches no column of a results file (naming
/// the pattern) or patterns are given and there are no results, std::runtime_error when a results
/// value is not a number (naming file, line and column) or gnuplot fails.
std::vector<std::filesystem::path> write_run_plots(const std::filesystem::path& dir,
                                                   const std::vector<std::string>& signal_patterns);

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_RUN_PLOTS_HPP
