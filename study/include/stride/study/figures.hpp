// Figures of learner runs (gnuplot PNGs): the study's Figures 1–8 from the run files.
#ifndef STRIDE_STUDY_FIGURES_HPP
#define STRIDE_STUDY_FIGURES_HPP

#include <filesystem>
#include <vector>

namespace stride::study {

/// Writes the PNGs of every learner run found in `dir` and its subfolders into `dir`/figures:
/// V heatmap (first two grid dimensions, max over the others) for the final table and each
/// snapshot, max-V profile per parameter, Σ|ΔV| per episode with a 50-episode moving average,
/// accumulated reward per episode, travelled x-y paths, and for evaluation runs the mean speed
/// and falls per point. Returns the files written. \throws std::runtime_error when gnuplot is
/// missing or fails, or nothing plottable is found.
std::vector<std::filesystem::path> write_figures(const std::filesystem::path& dir);

}  // namespace stride::study

#endif  // STRIDE_STUDY_FIGURES_HPP
