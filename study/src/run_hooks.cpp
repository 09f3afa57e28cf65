#include "stride/study/run_hooks.hpp"

#include <cstdio>

#include "stride/study/figures.hpp"
#include "stride/study/gait_link.hpp"
#include "stride/study/run_folder.hpp"

// models/experiments/demo.xml, embedded at build time
std::string_view stride_demo_scenario_xml();

namespace stride::study {

void check_before_run(const cosim::system_structure& system) {
  check_learner_grids(cosim::expand_replicas(system));
}

void report_after_run(const cosim::run_report& report, bool quiet, bool figures) {
  write_best_configs(report.system);
  if (!has_learner_artefacts(report.output_dir)) return;
  if (!quiet) std::fputs(summarize_run(report.output_dir).c_str(), stdout);
  if (!figures) return;
  try {
    const auto written = write_figures(report.output_dir);
    if (!quiet) {
      std::printf("figures: %s (%zu PNG)\n", (report.output_dir / "figures").string().c_str(),
                  written.size());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stride: warning: no figures: %s\n", e.what());
  }
}

std::vector<std::filesystem::path> plot_learner_runs(const std::filesystem::path& run_dir,
                                                     bool quiet) {
  if (!has_learner_artefacts(run_dir)) return {};
  const auto files = write_figures(run_dir);
  if (!quiet) std::fputs(summarize_run(run_dir).c_str(), stdout);
  return files;
}

std::string_view demo_scenario_xml() {
  return stride_demo_scenario_xml();
}

std::string_view demo_scenario_name() {
  return "models/experiments/demo.xml";
}

}  // namespace stride::study
