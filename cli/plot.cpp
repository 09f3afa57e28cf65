#include "plot.hpp"

#include <cstdio>

#include "stride/cosim/error.hpp"
#include "stride/cosim/run_plots.hpp"

namespace stride::cli {

namespace fs = std::filesystem;

CLI::App* add_plot_command(CLI::App& app, plot_arguments& args) {
  auto* plot = app.add_subcommand(
      "plot",
      "Write the figures (PNG, gnuplot) of a run's output folder into RUN_DIR/figures: the x-y "
      "path of every base pose (a results column P.base_x with P.base_y, any prefix P), the "
      "signals chosen with --signals over time, and for a learner run the learner's figures and "
      "summary");
  plot->add_option("run_dir", args.run_dir, "Output folder of the run")
      ->required()
      ->check(CLI::ExistingDirectory);
  plot->add_option("--signals", args.signals,
                   "Also plot these results columns over time: comma-separated comp.var patterns "
                   "with * and ? (e.g. 'robot.base_z,gait.*'); a pattern matching no column is "
                   "an error")
      ->allow_extra_args(false);
  plot->add_flag("--quiet,-q", args.quiet, "Print nothing");
  return plot;
}

int plot(const plot_arguments& args, const plot_extension& extension) {
  const std::vector<std::string> patterns = cosim::split_signal_patterns(args.signals);
  // a figures folder this call makes is removed again when it fails or draws nothing
  const fs::path figures = args.run_dir / "figures";
  const bool existed = fs::exists(figures);
  const auto drop_figures = [&] {
    std::error_code ec;
    if (!existed) fs::remove_all(figures, ec);
  };
  std::vector<fs::path> files;
  try {
    files = cosim::write_run_plots(args.run_dir, patterns);
    if (extension) {
      const auto more = extension(args.run_dir, args.quiet);
      files.insert(files.end(), more.begin(), more.end());
    }
  } catch (...) {
    drop_figures();
    throw;
  }
  if (files.empty()) {
    drop_figures();
    throw cosim::validation_error(
        args.run_dir.string() +
        ": nothing to plot: no base pose (P.base_x with P.base_y) in the run's results, no "
        "--signals chosen, no application files (stride plot --help)");
  }
  if (!args.quiet) {
    for (const auto& f : files) std::printf("figure: %s\n", f.string().c_str());
  }
  return 0;
}

}  // namespace stride::cli
