// A complete recorded run: output folder, results CSV, system copy, manifest. Shared by the
// `stride` CLI and other tools.
#ifndef STRIDE_COSIM_RUN_HPP
#define STRIDE_COSIM_RUN_HPP

#include <atomic>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "stride/cosim/execution.hpp"
#include "stride/cosim/system_builder.hpp"
#include "stride/cosim/system_structure.hpp"

namespace stride::cosim {

/// The library version ("0.1.0").
std::string_view version() noexcept;

/// What ended a run that did not fail, for people: "stop time", "interrupted", the stop
/// condition "comp.var" that held, or "component NAME requested termination".
std::string end_reason(const run_result& result);

/// A recording beside the results: its own CSV in the output folder, its own signals and
/// interval (e.g. what a viewer needs, at a frame rate, without bloating the results).
struct extra_record {
  std::string file;                  ///< relative to the output folder
  std::vector<std::string> signals;  ///< patterns with * and ?; those matching nothing are skipped
  /// The interval wanted; run_system takes the positive multiple of the base step closest to it
  /// (nullopt: every base step).
  std::optional<duration> interval;
  std::string origin;  ///< names it in messages ("--record-view")
};

struct run_options {
  /// output folder; empty = ./stride-out/<system-name>-<YYYYmmdd-HHMMSS> (suffixed -2, -3 … if
  /// it exists)
  std::filesystem::path output_dir;
  /// Write into an output folder that exists and is not empty (`--force`; files of the same
  /// name are replaced). Without it such a folder is refused (check_output_folder_free).
  bool force_output = false;
  std::vector<std::string> overrides;  ///< "comp.var=value", applied in order
  std::optional<time_point> stop;      ///< replaces the system's stop time
  bool progress = true;                ///< progress display on stderr
  build_options build;
  /// Continue the run recorded in this folder: it becomes the output folder and `${resume}` in
  /// parameter values is replaced by it (else by ""). When the folder holds the checkpoint of an
  /// interrupted run (checkpoint_file), the whole system goes on from the moment it was
  /// interrupted: simulated time continues and the results file is continued, so that the two
  /// parts form the rows of one run. Otherwise the run starts over and the system must use
  /// `${resume}` somewhere (components that continue from checkpoints of their own).
  std::filesystem::path resume_dir;
  /// Replaces the system's results file name (e.g. to keep the file of an interrupted run).
  std::optional<std::string> record_file;
  /// Replace what the system records: these signal patterns (recording on) ...
  std::vector<std::string> record_signals;
  /// ... and this interval (a multiple of the base step).
  std::optional<duration> record_interval;
  /// Further recordings (not part of system.xml: a resumed run gets them from its options).
  /// \throws validation_error when one matches no variable at all or names a file the run
  /// writes anyway.
  std::vector<extra_record> extra_records;
  /// Stop conditions, "comp.var" (or patterns with * and ?: the Boolean, Integer and Real
  /// outputs they match): the run ends at the first communication point at which one of these
  /// outputs is true or non-zero (execution::stop_when). \throws validation_error naming a
  /// pattern that matches no variable, or a variable that is no Boolean, Integer or Real output.
  std::vector<std::string> stop_when;
  /// Checked between steps: once set, the run ends there, with what was recorded written, a
  /// manifest that says "interrupted" and when ("interrupted_at", seconds), and the state of every
  /// component in checkpoint_file() for `resume_dir` (e.g. set by SIGINT).
  const std::atomic<bool>* interrupt = nullptr;
  /// Also writes checkpoint_file() every this much simulated time (the results written up to
  /// it first), so that a run whose process is killed or whose host is lost can be resumed
  /// from the last one with `resume_dir`. Not for agents (their shared table's journal does it).
  std::optional<duration> checkpoint_every;
  /// Build, check and initialize everything as for the run, then end before the first step
  /// (`stride validate`): no manifest is written.
  bool initialize_only = false;
  /// Further `${name}` values. `${agent}` (default "1") and `${shared_table}` (default "") are
  /// set by run_agents (stride/cosim/run_agents.hpp) for each agent.
  std::map<std::string, std::string> placeholders;
};

/// Replaces the placeholders in every parameter value: `${output_dir}` by the run's output folder,
/// `${resume}` by the folder being resumed ("" when not resuming) and `${name}` by
/// `more[name]`; returns how many values mention `${resume}`. \throws validation_error naming
/// file and line for any other `${...}`.
std::size_t substitute_placeholders(system_structure& system,
                                    const std::filesystem::path& output_dir,
                                    const std::filesystem::path& resume_dir,
                                    const std::map<std::string, std::string>& more = {});

/// `${agent}` = "1" and `${shared_table}` = "": the placeholders of a run that is not one of
/// several agents (run_system adds them unless run_options::placeholders has them).
std::map<std::string, std::string> single_run_placeholders();

/// What a run produced.
struct run_report {
  /// The system as run: overrides applied, replica groups expanded, placeholders substituted.
  system_structure system;
  std::filesystem::path output_dir;
  std::filesystem::path results_file;              ///< empty if recording is disabled
  std::vector<std::filesystem::path> extra_files;  ///< of run_options::extra_records, in order
  std::filesystem::path manifest_file;
  run_result result;
  /// from the start of initialization to the end of the simulation (components' termination
  /// not included), as the progress display counts it
  double wall_seconds = 0;
  double real_time_factor = 0;  ///< simulated time / wall_seconds (cosim::real_time_factor)
  std::string error;            ///< non-empty if the run failed (then also thrown)
};

/// The file in a run's folder with the state of the whole system at the moment the run was
/// interrupted (run_options::interrupt); a run that finishes removes it.
std::filesystem::path checkpoint_file(const std::filesystem::path& run_dir);

/// What manifest.json in a run's folder says ("" for what it does not say or a missing file).
struct run_status {
  std::string status;    ///< "ok", "interrupted", "error" (agents: also "partial")
  std::string end_time;  ///< seconds, as written
  std::string ended_by;
};
run_status read_run_status(const std::filesystem::path& run_dir);

/// A results file name not yet in `dir` ("results-resumed.csv", "results-resumed-2.csv" ...), so
/// that an interrupted run's results stay as they are when it is resumed.
std::string fresh_results_name(const std::filesystem::path& dir, const std::string& name);

/// \throws validation_error when `dir` exists and is not an empty folder: a file, an earlier run
/// (its system.xml, which every run writes first) or anything else a new run would mix its files
/// with or overwrite without a word. The message names the folder and, for a run, says so.
void check_output_folder_free(const std::filesystem::path& dir);

/// The default output folder name for a system, relative to the working directory.
std::filesystem::path default_output_dir(const system_structure& system);

/// A system with <agents> is run by run_agents (one call of this per agent); here it is an
/// error, except for `initialize_only` (one agent is checked).
/// Applies overrides, expands replica groups, substitutes placeholders, builds, creates the
/// output folder (refused when it exists and is not empty, except to resume it or with
/// `force_output`), writes `system.xml`
/// (with overrides; groups and placeholders kept), records, runs and writes `manifest.json` (with
/// every parameter value the system sets). On a run-time error the results so far and a manifest
/// with "status": "error" are written and the error is rethrown.
run_report run_system(system_structure system, const run_options& options);

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_RUN_HPP
