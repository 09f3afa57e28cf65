// stride: run a co-simulation from a system XML, inspect or validate FMUs and systems.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>

#include "calibrate.hpp"
#include "commands.hpp"
#include "stride/cosim/algorithm.hpp"
#include "stride/cosim/run.hpp"
#include "stride/study/run_hooks.hpp"

int main(int argc, char** argv) {
  CLI::App app{"stride: FMI 2.0 co-simulation of FMUs wired by a system XML"};
  app.set_version_flag("--version", std::string(stride::cosim::version()));
  app.require_subcommand(1);

  stride::cli::run_arguments run_args;
  std::string system_file;
  std::string stop_time;
  auto* run = app.add_subcommand(
      "run",
      "Run a system (no SYSTEM.xml: the built-in demo, Experiment 1 of the gait-parameter "
      "learner at demo scale, models/experiments/demo.xml)");
  run->add_option("system", system_file, "System XML file")->check(CLI::ExistingFile);
  run->add_option("--stop-time", stop_time, "Stop time in seconds (replaces the XML's)");
  run->add_option("--output,-o", run_args.output,
                  "Output folder (default ./stride-out/<system>-<YYYYmmdd-HHMMSS>)");
  run->add_option("--set", run_args.sets, "Parameter or input start value: comp.var=value")
      ->allow_extra_args(false);
  run->add_flag("--quiet,-q", run_args.quiet, "No progress display, only warnings and errors");
  run->add_flag("--fmu-debug-log", run_args.fmu_debug_log,
                "Instantiate FMUs with debug logging on");
  run->add_option("--resume", run_args.resume,
                  "Continue the run in this output folder from its checkpoint (system: the "
                  "folder's system.xml unless SYSTEM.xml is given; ${resume} = the folder)")
      ->check(CLI::ExistingDirectory);
  run_args.threads = stride::cosim::default_thread_count();
  run->add_option("--threads", run_args.threads,
                  "Threads for stepping independent components concurrently (results are "
                  "identical for any count)")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  run->add_flag("--no-plots", run_args.no_plots,
                "Do not write figures after a learner run (see `stride plot`)");

  std::string inspect_file;
  auto* inspect = app.add_subcommand("inspect", "Show an FMU's model description");
  inspect->add_option("fmu", inspect_file, "FMU file")->required()->check(CLI::ExistingFile);

  stride::cli::validate_arguments validate_args;
  std::string validate_file;
  std::string validate_stop;
  auto* validate = app.add_subcommand(
      "validate",
      "Check an FMU (static checks, import, instantiate) or a system XML (parse, "
      "build, validate; nothing is run)");
  validate->add_option("file", validate_file, "FMU or system XML file")
      ->required()
      ->check(CLI::ExistingFile);
  validate->add_option("--stop-time", validate_stop, "Stop time in seconds for a system");
  validate->add_option("--set", validate_args.sets, "comp.var=value, as for run")
      ->allow_extra_args(false);
  validate->add_flag("--quiet,-q", validate_args.quiet, "Print only problems");

  std::string plot_dir;
  bool plot_quiet = false;
  auto* plot = app.add_subcommand(
      "plot", "Write the figures (PNG, gnuplot) and summary of a learner run's output folder");
  plot->add_option("run_dir", plot_dir, "Output folder of the run")
      ->required()
      ->check(CLI::ExistingDirectory);
  plot->add_flag("--quiet,-q", plot_quiet, "Print nothing");

  stride::cli::calibrate_arguments calibrate_args;
  auto* calibrate = stride::cli::add_calibrate_command(app, calibrate_args);

  CLI11_PARSE(app, argc, argv);

  try {
    if (*run) {
      if (!system_file.empty()) run_args.system = system_file;
      if (!stop_time.empty()) run_args.stop_time = stop_time;
      // the DARwIn study: its demo as the default system, its checks and reports
      stride::cli::run_extension study;
      study.default_system_xml = stride::study::demo_scenario_xml();
      study.default_system_name = stride::study::demo_scenario_name();
      study.check = stride::study::check_before_run;
      study.report = [](const stride::cosim::run_report& report,
                        const stride::cli::run_arguments& a) {
        stride::study::report_after_run(report, a.quiet, !a.no_plots);
      };
      return stride::cli::run(run_args, study);
    }
    if (*inspect) return stride::cli::inspect(inspect_file);
    if (*calibrate) return stride::cli::calibrate(calibrate_args);
    if (*plot) return stride::study::plot(plot_dir, plot_quiet);
    if (*validate) {
      validate_args.file = validate_file;
      if (!validate_stop.empty()) validate_args.stop_time = validate_stop;
      return stride::cli::validate(validate_args);
    }
  } catch (const std::exception& e) {
    std::string message = e.what();
    for (char& c : message) {
      if (c == '\n') c = ' ';
    }
    std::fprintf(stderr, "stride: error: %s\n", message.c_str());
    return 1;
  }
  return 0;
}
