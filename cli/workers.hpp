// `stride worker` and `stride workers`, and the DDS options `stride run` shares with them
// (docs/distributed.md).
#ifndef STRIDE_CLI_WORKERS_HPP
#define STRIDE_CLI_WORKERS_HPP

#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "stride/remote/settings.hpp"

namespace stride::cli {

/// Adds --domain, --dds-config and --security to `command`; parsing fills `dds`.
void add_dds_options(CLI::App& command, remote::dds_settings& dds);
/// Adds --security: a DDS Security identity for every participant of the process (it is also
/// put into STRIDE_SECURITY, for the participants of FMUs and for child processes).
void add_security_option(CLI::App& command, std::filesystem::path& identity);

struct worker_arguments {
  std::string name;
  remote::dds_settings dds;
  bool insecure = false;                         ///< serve without security although reachable
  std::vector<std::filesystem::path> allow_fmu;  ///< --allow-fmu sources (empty: any FMU)
};

struct workers_arguments {
  remote::dds_settings dds;
  double wait = 1.0;  ///< seconds to listen for announcements
};

CLI::App* add_worker_command(CLI::App& app, worker_arguments& args);
CLI::App* add_workers_command(CLI::App& app, workers_arguments& args);

/// Serves until SIGINT or SIGTERM; 0 after a clean stop.
int worker(const worker_arguments& args);
/// Prints the workers announced on the domain.
int workers(const workers_arguments& args);

}  // namespace stride::cli

#endif  // STRIDE_CLI_WORKERS_HPP
