// `stride worker` and `stride workers`, and the DDS options `stride run` shares with them
// (docs/distributed.md).
#ifndef STRIDE_CLI_WORKERS_HPP
#define STRIDE_CLI_WORKERS_HPP

#include <CLI/CLI.hpp>

#include <string>

#include "stride/remote/settings.hpp"

namespace stride::cli {

/// Adds --domain and --dds-config to `command`; parsing fills `dds`.
void add_dds_options(CLI::App& command, remote::dds_settings& dds);

struct worker_arguments {
  std::string name;
  remote::dds_settings dds;
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
