#include "workers.hpp"

#include <cstdio>
#include <cstdlib>

#include "stop_signals.hpp"
#include "stride/cosim/error.hpp"
#include "stride/remote/reach.hpp"
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
  add_security_option(command, dds.security);
}

void add_security_option(CLI::App& command, std::filesystem::path& identity) {
  // The environment carries the identity to every participant of the process (the shared
  // table's clients inside FMUs too) and to the processes it starts (`stride test` cases).
  command
      .add_option("--security", identity,
                  std::string("DDS Security identity folder KEYSTORE/NAME (`stride security add`) "
                              "for every DDS participant of this process (default: $") +
                      remote::k_security_env + ")")
      ->check(CLI::ExistingDirectory)
      ->each([](const std::string& dir) {
        ::setenv(remote::k_security_env, std::filesystem::absolute(dir).c_str(), 1);
      });
}

CLI::App* add_worker_command(CLI::App& app, worker_arguments& args) {
  auto* c = app.add_subcommand(
      "worker",
      "Host components for runs on the DDS domain (components with worker=\"NAME\" in a system "
      "XML) until SIGINT or SIGTERM");
  c->add_option("--name", args.name, "Name the system XML refers to (default <host>-<pid>)");
  add_dds_options(*c, args.dds);
  c->add_flag("--insecure", args.insecure,
              "Serve without DDS Security although the DDS configuration reaches other hosts: "
              "anyone who reaches the domain can then run code here (docs/distributed.md)");
  c->add_option("--allow-fmu", args.allow_fmu,
                "Accept only FMU archives whose SHA-256 is listed in this file (`sha256sum` "
                "lines) or is that of a .fmu file in this folder; may be repeated")
      ->check(CLI::ExistingPath)
      ->allow_extra_args(false);
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

namespace {

// A worker that other hosts can reach runs only with DDS Security, or when told --insecure.
void check_exposure(const worker_arguments& args) {
  const bool secure = !remote::effective_identity(args.dds).empty();
  if (secure && args.insecure) {
    throw cosim::validation_error("--insecure and a security identity exclude each other");
  }
  if (secure) return;
  const std::string reach = remote::reach_beyond_loopback(args.dds);
  if (!reach.empty() && !args.insecure) {
    throw cosim::validation_error(
        "the worker is not started: " + reach +
        ", and without DDS Security any host that reaches it could run code here. Give it an "
        "identity (--security KEYSTORE/NAME, docs/distributed.md) or accept that with "
        "--insecure");
  }
  if (args.insecure) {
    std::fprintf(stderr,
                 "stride worker: warning: --insecure: every process that reaches DDS domain %d "
                 "%s can load and run FMUs here and read and change the values of its runs\n",
                 args.dds.domain, reach.empty() ? "on this machine" : "over the network");
  }
}

}  // namespace

int worker(const worker_arguments& args) {
  check_exposure(args);
  remote::worker_options o;
  if (!args.allow_fmu.empty()) {
    o.allowed_fmus.emplace();
    for (const auto& source : args.allow_fmu) remote::add_allowed_fmus(source, *o.allowed_fmus);
  }
  const std::atomic<bool>& stop = catch_stop_signals();
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
