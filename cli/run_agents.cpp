// `stride run` of a system with agents: the shared table's service in this process, the agents
// (on threads or workers) through libstride, the table written at the end (docs/swarm.md).
#include <csignal>
#include <cstdio>
#include <fstream>

#include "commands.hpp"
#include "stop_signals.hpp"
#include "stride/common/files.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/run_agents.hpp"
#include "stride/remote/remote_placement.hpp"
#include "stride/remote/shared_table.hpp"

namespace stride::cli {

namespace fs = std::filesystem;
using namespace stride::cosim;

namespace {

void write_table(const fs::path& file, const remote::table_snapshot& table) {
  std::string text = "entry,value\n";
  char line[64];
  for (std::size_t i = 0; i < table.values.size(); ++i) {
    std::snprintf(line, sizeof line, "%zu,%.17g\n", i, table.values[i]);
    text += line;
  }
  try {
    common::write_file_atomically(file, text);
  } catch (const std::runtime_error& e) {
    throw error(e.what());
  }
}

}  // namespace

int run_agents(cosim::system_structure system, cosim::run_options options,
               const run_arguments& args, const run_extension& extension) {
  const bool resuming = !options.resume_dir.empty();
  if (!resuming && options.output_dir.empty()) options.output_dir = default_output_dir(system);
  const fs::path dir = resuming ? options.resume_dir : options.output_dir;
  if (!resuming && !options.force_output) check_output_folder_free(dir);
  // checked before the journal is made there: the agents' runs write next to it
  options.force_output = true;
  fs::create_directories(dir);
  remote::table_endpoint where;
  where.domain = args.dds.domain;
  where.config_file = args.dds.config_file;
  where.table = remote::unique_table_name("run");
  where.agents = system.agents.count;
  where.synchronous = system.agents.synchronous;
  // synchronous rounds are journaled, so that the run can be resumed bit-identically
  remote::table_journal journal;
  if (where.synchronous) journal.file = dir / "shared_table.journal";
  journal.resume = resuming;
  if (resuming && where.synchronous && !fs::exists(journal.file)) {
    throw validation_error("--resume: " + journal.file.string() +
                           " is missing (the agents' shared table cannot be rebuilt)");
  }
  if (resuming && !where.synchronous) {
    throw validation_error(
        "--resume: asynchronous agents cannot be resumed (their run is not "
        "repeatable; docs/swarm.md)");
  }
  remote::table_service service(where, journal);
  agents_options agents;
  agents.count = where.agents;
  agents.shared_table = where.str();
  const remote::timeouts limits = worker_limits(args);
  // every agent is a run of its own, for its workers too
  agents.placements = [&args, limits](int) {
    return std::vector<std::shared_ptr<placement_resolver>>{
        std::make_shared<remote::remote_placement>(args.dds, limits)};
  };
  agents.lost = [&service](int agent, const std::string& why) {
    std::fprintf(stderr, "stride: agent %d is lost (%s); the others go on\n", agent, why.c_str());
    service.leave_out(agent);
  };
  agents.abandon = [&service](const std::string& why) { service.abandon(why); };
  if (!args.quiet) {
    std::printf("%d agents (%s), %s %s\n", agents.count,
                where.synchronous ? "synchronous rounds" : "asynchronous",
                resuming ? "resuming" : "output", dir.string().c_str());
  }
  const agents_report report = cosim::run_agents(std::move(system), options, agents);
  // the merged table as the service holds it, whichever agents were lost
  const remote::table_snapshot table = service.current();
  write_table(report.output_dir / "shared_table.csv", table);
  if (report.errors.front().empty() && extension.report) {
    extension.report(report.agents.front(), args);
  }
  if (report.interrupted) {
    const int signal = caught_stop_signal();
    std::fprintf(stderr, "stride: interrupted by %s; what was recorded is in %s\n",
                 signal == SIGTERM ? "SIGTERM" : "SIGINT", report.output_dir.string().c_str());
    return 128 + (signal == SIGTERM ? SIGTERM : SIGINT);
  }
  if (!args.quiet) {
    std::printf("%zu of %zu agents finished (%.2f s wall); the shared table merged %lld updates\n",
                report.agents.size() - report.lost(), report.agents.size(), report.wall_seconds,
                static_cast<long long>(table.updates));
    std::printf("output: %s\n", report.output_dir.string().c_str());
  }
  return 0;
}

}  // namespace stride::cli
