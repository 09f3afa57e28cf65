// The study's part of the `stride` command line: what `stride run` checks before and reports
// after a run of a learner system, `stride plot`, and the default scenario.
#ifndef STRIDE_STUDY_RUN_HOOKS_HPP
#define STRIDE_STUDY_RUN_HOOKS_HPP

#include <filesystem>
#include <string_view>
#include <vector>

#include "stride/cosim/run.hpp"
#include "stride/cosim/system_structure.hpp"

namespace stride::study {

/// Before a run: the learners' grids against the gait's ranges (gait_link.hpp).
void check_before_run(const cosim::system_structure& system);

/// After a run: config.ini of each learn run, then (unless `quiet`) the summary and (with
/// `figures`) the PNGs of the learner runs in the output folder. Nothing for other systems.
void report_after_run(const cosim::run_report& report, bool quiet, bool figures);

/// The study's part of `stride plot RUN_DIR`: when the folder (or one right below it) holds
/// learner files, their figures (figures.hpp) and, unless `quiet`, the summary. Returns the PNGs
/// written (none for other runs).
std::vector<std::filesystem::path> plot_learner_runs(const std::filesystem::path& run_dir,
                                                     bool quiet);

/// The default scenario of `stride run`: Experiment 1 at demo scale
/// (models/experiments/demo.xml, embedded at build time), and its name for messages.
std::string_view demo_scenario_xml();
std::string_view demo_scenario_name();

}  // namespace stride::study

#endif  // STRIDE_STUDY_RUN_HOOKS_HPP
