// The stride subcommands; each returns the process exit code and throws on errors.
#ifndef STRIDE_CLI_COMMANDS_HPP
#define STRIDE_CLI_COMMANDS_HPP

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stride/cosim/run.hpp"
#include "stride/cosim/system_structure.hpp"
#include "stride/remote/settings.hpp"
#include "stride/suite/assertions.hpp"

namespace stride::cli {

struct run_arguments {
  std::optional<std::filesystem::path> system;  ///< nullopt = embedded default scenario
  std::optional<std::string> stop_time;
  std::optional<std::string> step;       ///< --step: replaces the system's base step
  std::optional<std::string> algorithm;  ///< --algorithm: replaces its master algorithm
  std::filesystem::path output;
  std::vector<std::string> sets;
  bool quiet = false;
  bool fmu_debug_log = false;
  std::filesystem::path resume;      ///< --resume DIR (empty: a new run)
  bool no_plots = false;             ///< skip the figures after a learner run
  int threads = 1;                   ///< --threads
  std::vector<std::string> signals;  ///< --record / --signals values (see record_patterns)
  std::optional<std::string> record_interval;
  std::optional<std::string> checkpoint_every;  ///< --checkpoint-every: seconds of simulated time
  std::vector<std::string> stop_when;           ///< --stop-when: outputs that end the run
  bool force = false;                           ///< --force: write into a non-empty output folder
  std::filesystem::path save_reference;         ///< --save-reference: a copy of the results CSV
  remote::dds_settings dds;                     ///< where components with a worker are looked for
  double worker_timeout = 10;                   ///< seconds to wait for a worker to appear
  double stall = 0.2;  ///< --stall: seconds the network may hold up a reply
  int agents = 0;      ///< --agents: replaces the <agents> count (0: keep)
  std::vector<cosim::extra_record> extra_records;  ///< recordings beside the results
  std::vector<std::string> standby;                ///< --standby: replaces the <failover> workers
  std::optional<int> snapshot_every;               ///< --snapshot-every: replaces its interval
};

struct validate_arguments {
  std::filesystem::path file;
  std::optional<std::string> stop_time;
  std::optional<std::string> step;       ///< as for run
  std::optional<std::string> algorithm;  ///< as for run
  std::vector<std::string> sets;
  bool quiet = false;
};

/// What an application built on the framework adds to `stride run` (the CLI itself knows no
/// component): a default system, a check before and a report after a run.
struct run_extension {
  std::string_view default_system_xml;   ///< run when no SYSTEM.xml is given ("" = required)
  std::string_view default_system_name;  ///< names it in messages
  std::function<void(const cosim::system_structure&)> check;
  std::function<void(const cosim::run_report&, const run_arguments&)> report;
};

int run(const run_arguments& args, const run_extension& extension);
/// The signal patterns of `--record` / `--signals` values: each value holds one or more, split
/// at commas and white space. \throws validation_error when there is none.
std::vector<std::string> record_patterns(const std::vector<std::string>& values);
/// The part of `run` for a system with <agents> (cli/run_agents.cpp): `options` as `run` made
/// them from `args`.
int run_agents(cosim::system_structure system, cosim::run_options options,
               const run_arguments& args, const run_extension& extension);

struct test_arguments {
  std::filesystem::path suite;
  std::filesystem::path junit;   ///< empty: none
  std::filesystem::path output;  ///< empty: ./stride-out/<suite>-<stamp>
  std::string filter;
  int jobs = 1;
  bool quiet = false;
};

/// `stride test`: runs a suite; 0 only when every case passed. `kinds` are the assertion kinds
/// (built-in ones plus the application's).
int test(const test_arguments& args, const stride::suite::assertion_registry& kinds);
/// `stride inspect`: an FMU's model description, or (any other file) a system's components and
/// where each runs.
int inspect(const std::filesystem::path& file);

/// --step and --algorithm of run, validate and sweep: replace the system's base step and master
/// algorithm when given. \throws cosim::validation_error for a bad value.
void apply_stepping(cosim::system_structure& system, const std::optional<std::string>& step,
                    const std::optional<std::string>& algorithm);
/// --standby and --snapshot-every: replace the system's <failover> workers and interval when
/// given. \throws cosim::validation_error for an empty name, or an interval without standbys.
void apply_failover(cosim::system_structure& system, const std::vector<std::string>& standby,
                    std::optional<int> snapshot_every);
/// How long `stride run` waits for workers and when a held-up reply is a stall.
remote::timeouts worker_limits(const run_arguments& args);
int validate(const validate_arguments& args);

}  // namespace stride::cli

#endif  // STRIDE_CLI_COMMANDS_HPP
