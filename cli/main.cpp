// stride: run a co-simulation from a system XML, inspect or validate FMUs and systems.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "calibrate.hpp"
#include "commands.hpp"
#include "export.hpp"
#include "installed_files.hpp"
#include "plot.hpp"
#include "robot_fmu.hpp"
#include "security.hpp"
#include "stride/cosim/algorithm.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/run.hpp"
#include "stride/remote/keystore.hpp"
#include "stride/remote/refused_peers.hpp"
#include "stride/remote/remote_placement.hpp"
#include "stride/remote/settings.hpp"
#include "stride/study/run_hooks.hpp"
#include "stride/study/suite_assertions.hpp"
#include "stride/suite/assertions.hpp"
#include "sweep.hpp"
#include "view.hpp"
#include "workers.hpp"

namespace {

constexpr const char* k_ssd_help =
    "System structure description (.ssd) to read inside an SSP archive or folder instead of "
    "SystemStructure.ssd (`stride inspect` lists them)";

// SYSTEM/NAME.ssd: the description NAME.ssd inside the SSP SYSTEM (docs/ssp.md)
std::string inside(const std::string& system, const std::string& ssd) {
  return ssd.empty() ? system : (std::filesystem::path(system) / ssd).string();
}

}  // namespace

int main(int argc, char** argv) {
  // DDS's threads end before exit's clean-up handlers run (OpenSSL's among them)
  struct close_dds_on_return {
    ~close_dds_on_return() { stride::remote::close_dds(); }
  } dds_guard;
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
  run->add_option("system", system_file,
                  "System XML file, or an SSP (.ssp, a folder with SystemStructure.ssd, .ssd) or "
                  "OspSystemStructure.xml (docs/ssp.md); a relative name not found here is looked "
                  "up in the installed models, share/stride/models")
      ->transform(stride::cli::existing_or_installed_model());
  std::string run_ssd;
  run->add_option("--ssd", run_ssd, k_ssd_help);
  run->add_option("--stop-time", stop_time, "Stop time in seconds (replaces the XML's)");
  std::string step, algorithm;
  run->add_option("--step", step, "Base step in seconds (replaces the system's)");
  run->add_option("--algorithm", algorithm, "gauss-seidel or jacobi (replaces the system's)");
  run->add_option("--output,-o", run_args.output,
                  "Output folder (default ./stride-out/<system>-<YYYYmmdd-HHMMSS>); an existing "
                  "one must be empty, unless --force");
  run->add_flag("--force", run_args.force,
                "Write into an existing non-empty output folder (files of the same name are "
                "replaced)");
  run->add_option("--set", run_args.sets,
                  "Parameter or input start value: comp.var=value (not for a variable that a "
                  "connection drives)")
      ->allow_extra_args(false);
  run->add_flag("--quiet,-q", run_args.quiet, "No progress display, only warnings and errors");
  run->add_flag("--fmu-debug-log", run_args.fmu_debug_log,
                "Instantiate FMUs with debug logging on");
  run->add_option("--resume", run_args.resume,
                  "Continue the interrupted run in this output folder: from the state of every "
                  "component when it was interrupted (its checkpoint.stride), simulated time and "
                  "the results file going on; without that file the run starts over and "
                  "components continue from their own checkpoints (${resume} = the folder). "
                  "System: the folder's system.xml unless SYSTEM.xml is given. A finished run "
                  "is left as it is (exit status 0)")
      ->check(CLI::ExistingDirectory);
  run_args.threads = stride::cosim::default_thread_count();
  run->add_option("--threads", run_args.threads,
                  "Threads for stepping independent components concurrently (results are "
                  "identical for any count)")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  run->add_option("--record,--signals", run_args.signals,
                  "Record these signals instead of the system's: comp.var patterns with * and ?, "
                  "separated by commas (e.g. 'robot.base_*,gait.phase'); may be repeated")
      ->allow_extra_args(false);
  run->add_option("--stop-when", run_args.stop_when,
                  "End the run when this output (comp.var; Boolean, Integer or Real) becomes "
                  "true or non-zero, e.g. robot.fallen; may be repeated")
      ->allow_extra_args(false);
  std::string record_interval;
  run->add_option("--record-interval", record_interval,
                  "Recording interval in seconds (a multiple of the base step)");
  std::string checkpoint_every;
  run->add_option("--checkpoint-every", checkpoint_every,
                  "Also write checkpoint.stride every this many simulated seconds, so that a run "
                  "whose process is killed can be continued with --resume (docs/system-xml.md)");
  bool record_view = false;
  std::string record_view_interval = stride::viewer::k_view_interval;
  run->add_flag("--record-view", record_view,
                "Also record what `stride view` replays (base pose, joint angles, falls of every "
                "plant component) into view.csv, every --record-view-interval");
  run->add_option("--record-view-interval", record_view_interval,
                  "Interval of --record-view, s (the nearest multiple of the base step)")
      ->capture_default_str();
  run->add_option("--save-reference", run_args.save_reference,
                  "Also write the results CSV to this file: a reference for `stride test`");
  run->add_flag("--no-plots", run_args.no_plots,
                "Do not write figures after a learner run (see `stride plot`)");
  run->add_option("--agents", run_args.agents,
                  "Run this many agents of the system at once, sharing ${shared_table} "
                  "(replaces the count of <agents>; docs/swarm.md)")
      ->check(CLI::Range(1, 1024));
  stride::cli::add_dds_options(*run, run_args.dds);
  run->add_option("--worker-timeout", run_args.worker_timeout,
                  "Seconds to wait for a worker named in the system to appear")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 3600.0));
  run->add_option("--stall", run_args.stall,
                  "Seconds the network may hold up a worker's reply (beyond the worker's own "
                  "time) before it is logged and counted as a stall in the manifest "
                  "(docs/failover.md)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 60.0));
  run->add_option("--standby", run_args.standby,
                  "Standby workers, separated by commas: a lost worker's components continue on "
                  "the next one from their last state image, the results unchanged (replaces "
                  "<failover standby>; docs/failover.md)")
      ->delimiter(',')
      ->allow_extra_args(false);
  run->add_option("--snapshot-every", run_args.snapshot_every,
                  "Steps between the state images of components with standby workers (default " +
                      std::to_string(stride::remote::k_default_snapshot_every) + ")")
      ->check(CLI::Range(1, 1000000000));

  std::string inspect_file;
  auto* inspect = app.add_subcommand(
      "inspect", "Show an FMU's model description, or where a system's components run");
  inspect->add_option("file", inspect_file, "FMU file or system (XML, SSP, OSP)")
      ->required()
      ->check(CLI::ExistingPath);
  std::string inspect_ssd;
  inspect->add_option("--ssd", inspect_ssd, k_ssd_help);

  stride::cli::test_arguments test_args;
  std::string suite_file;
  auto* test = app.add_subcommand(
      "test",
      "Run a regression suite (docs/regression-suites.md): exit status 0 only if every "
      "case passes");
  test->add_option("suite", suite_file, "Suite XML file")->required()->check(CLI::ExistingFile);
  test->add_option("--junit", test_args.junit, "Write JUnit XML here");
  test->add_option("--filter", test_args.filter, "Run only the cases whose names match (* and ?)");
  test->add_option("--jobs,-j", test_args.jobs, "Cases run at the same time")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  test->add_option("--output,-o", test_args.output,
                   "Folder for the cases' runs (default ./stride-out/<suite>-<YYYYmmdd-HHMMSS>)");
  test->add_flag("--quiet,-q", test_args.quiet, "Print only the closing line");
  std::filesystem::path test_security;  // passed on to the cases' processes in the environment
  stride::cli::add_security_option(*test, test_security);

  stride::cli::validate_arguments validate_args;
  std::string validate_file;
  std::string validate_stop;
  auto* validate = app.add_subcommand(
      "validate",
      "Check an FMU (static checks, import, instantiate) or a system XML (parse, "
      "build, validate; nothing is run)");
  validate->add_option("file", validate_file, "FMU or system (XML, SSP, OSP)")
      ->required()
      ->transform(stride::cli::existing_or_installed_model());
  std::string validate_ssd;
  validate->add_option("--ssd", validate_ssd, k_ssd_help);
  validate->add_option("--stop-time", validate_stop, "Stop time in seconds for a system");
  std::string validate_step, validate_algorithm;
  validate->add_option("--step", validate_step, "Base step in seconds for a system");
  validate->add_option("--algorithm", validate_algorithm, "gauss-seidel or jacobi, for a system");
  validate->add_option("--set", validate_args.sets, "comp.var=value, as for run")
      ->allow_extra_args(false);
  validate->add_flag("--quiet,-q", validate_args.quiet, "Print only problems");

  stride::cli::plot_arguments plot_args;
  auto* plot = stride::cli::add_plot_command(app, plot_args);

  stride::cli::worker_arguments worker_args;
  auto* worker = stride::cli::add_worker_command(app, worker_args);
  stride::cli::workers_arguments workers_args;
  auto* workers = stride::cli::add_workers_command(app, workers_args);
  stride::cli::security_arguments security_args;
  auto* security = stride::cli::add_security_command(app, security_args);

  stride::cli::calibrate_arguments calibrate_args;
  auto* calibrate = stride::cli::add_calibrate_command(app, calibrate_args);

  stride::cli::add_sweep_command(app, stride::cli::study_sweep_extension());  // runs itself

  stride::cli::view_arguments view_args;
  auto* view = stride::cli::add_view_command(app, view_args);

  stride::cli::export_arguments export_args;
  auto* export_command = stride::cli::add_export_command(app, export_args);

  stride::cli::robot_fmu_arguments robot_fmu_args;
  auto* robot_fmu = stride::cli::add_robot_fmu_command(app, robot_fmu_args);

  CLI11_PARSE(app, argc, argv);
  // every DDS participant of this process checks its identity first (docs/distributed.md)
  stride::remote::set_identity_check(&stride::remote::keystore::check_identity);
  // a DDS Security handshake that fails is said once per peer (a worker says it in its log)
  stride::remote::refused_peer_log refused_peers(
      [](const std::string& line) { std::fprintf(stderr, "stride: %s\n", line.c_str()); });

  try {
    if (*run) {
      if (!system_file.empty()) run_args.system = inside(system_file, run_ssd);
      if (!stop_time.empty()) run_args.stop_time = stop_time;
      if (!step.empty()) run_args.step = step;
      if (!algorithm.empty()) run_args.algorithm = algorithm;
      if (!record_interval.empty()) run_args.record_interval = record_interval;
      if (!checkpoint_every.empty()) run_args.checkpoint_every = checkpoint_every;
      if (record_view) {
        // the viewer's preset: its signals at about 30 frames a second, beside the results
        stride::cosim::extra_record view_record;
        view_record.file = stride::viewer::k_view_file;
        view_record.signals = stride::viewer::view_signal_patterns();
        view_record.origin = "--record-view";
        try {
          view_record.interval = stride::cosim::parse_duration(record_view_interval);
        } catch (const std::exception& e) {
          throw stride::cosim::validation_error(std::string("--record-view-interval: ") + e.what());
        }
        run_args.extra_records.push_back(std::move(view_record));
      }
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
    if (*inspect) return stride::cli::inspect(inside(inspect_file, inspect_ssd));
    if (*test) {
      test_args.suite = suite_file;
      stride::suite::assertion_registry kinds = stride::suite::builtin_assertions();
      kinds.merge(stride::study::learner_assertions());  // the study's: best_state, value_at
      return stride::cli::test(test_args, kinds);
    }
    if (*calibrate) return stride::cli::calibrate(calibrate_args);
    if (*worker) return stride::cli::worker(worker_args);
    if (*workers) return stride::cli::workers(workers_args);
    if (*security) return stride::cli::security(security_args);
    if (*plot) {
      // the study adds the learner's figures and summary for its runs
      return stride::cli::plot(plot_args, stride::study::plot_learner_runs);
    }
    if (*view) return stride::cli::view(view_args);
    if (*robot_fmu) return stride::cli::robot_fmu(robot_fmu_args);
    if (*export_command) return stride::cli::export_system(export_args);
    if (*validate) {
      validate_args.file = inside(validate_file, validate_ssd);
      if (!validate_stop.empty()) validate_args.stop_time = validate_stop;
      if (!validate_step.empty()) validate_args.step = validate_step;
      if (!validate_algorithm.empty()) validate_args.algorithm = validate_algorithm;
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
