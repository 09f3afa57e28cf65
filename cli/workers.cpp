#include "workers.hpp"

#include <cstdio>

#include "stop_signals.hpp"
#include "stride/remote/worker.hpp"

namespace stride::cli {

void add_dds_options(CLI::App& command, remote::dds_settings& dds) {
  command.add_option("--domain", dds.domain, "DDS domain of the run and its workers")
      ->capture_default_str()
      ->check(CLI::Range(0, 230));
  command
      .add_option("--dds-config", dds.config_file,
                  "Cyclone DDS configuration file (default: CYCLONEDDS_URI if set, else this "
                  "machine only over loopback)")
      ->check(CLI::ExistingFile);
}

CLI::App* add_worker_command(CLI::App& app, worker_arguments& args) {
  auto* c = app.add_subcommand(
      "worker",
      "Host components for runs on the DDS domain (components with worker=\"NAME\" in a system "
      "XML) until SIGINT or SIGTERM");
  c->add_option("--name", args.name, "Name the system XML refers to (default <host>-<pid>)");
  add_dds_options(*c, args.dds);
  return c;
}

CLI::App* add_workers_command(CLI::App& app, workers_arguments& args) {
  auto* c = app.add_subcommand("workers", "List the workers announced on the DDS domain");
  add_dds_options(*c, args.dds);
  c->add_option("--wait", args.wait, "Seconds to listen for announcements")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 60.0));
  return c;
}

int worker(const worker_arguments& args) {
  const std::atomic<bool>& stop = catch_stop_signals();
  remote::worker_options o;
  o.name = args.name;
  o.dds = args.dds;
  o.log = stdout;
  remote::serve(o, stop);
  std::printf("worker stopped\n");
  return 0;
}

int workers(const workers_arguments& args) {
  const auto found = remote::visible_workers(
      args.dds, std::chrono::milliseconds(static_cast<long>(args.wait * 1000)));
  if (found.empty()) {
    std::printf("no worker on DDS domain %d\n", args.dds.domain);
    return 0;
  }
  std::printf("%-24s %-24s %8s  %s\n", "name", "host", "pid", "version");
  for (const auto& w : found) {
    std::printf("%-24s %-24s %8lld  %s\n", w.name.c_str(), w.host.c_str(), w.pid,
                w.version.c_str());
  }
  return 0;
}

}  // namespace stride::cli
