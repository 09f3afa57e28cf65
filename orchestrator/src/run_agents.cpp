#include "stride/cosim/run_agents.hpp"

#include <atomic>
#include <chrono>
#include <mutex>
#include <sstream>
#include <thread>

#include "run_files.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim {

namespace fs = std::filesystem;

std::size_t agents_report::lost() const {
  std::size_t n = 0;
  for (const auto& e : errors) n += e.empty() ? 0 : 1;
  return n;
}

namespace {

std::string status_of(const agents_report& r) {
  if (r.interrupted) return "interrupted";
  if (r.lost() == 0) return "ok";
  return r.lost() == r.errors.size() ? "error" : "partial";
}

std::string manifest_json(const system_structure& s, const agents_report& r,
                          const std::string& started) {
  std::ostringstream j;
  j << "{\n";
  j << "  \"stride_version\": " << json_string(version()) << ",\n";
  j << "  \"status\": " << json_string(status_of(r)) << ",\n";
  j << "  \"system\": " << json_string(s.name) << ",\n";
  j << "  \"system_file\": " << json_string(s.where.file) << ",\n";
  j << "  \"started_utc\": " << json_string(started) << ",\n";
  j << "  \"agents\": " << r.errors.size() << ",\n";
  j << "  \"mode\": " << json_string(s.agents.synchronous ? "synchronous" : "asynchronous")
    << ",\n";
  j << "  \"lost\": " << r.lost() << ",\n";
  j << "  \"wall_time_s\": " << json_number(r.wall_seconds) << ",\n";
  j << "  \"agent_runs\": [";
  for (std::size_t k = 0; k < r.errors.size(); ++k) {
    const std::string& worker =
        s.agents.workers.empty() ? std::string() : s.agents.workers[k % s.agents.workers.size()];
    j << (k ? ",\n" : "\n") << "    {\"folder\": " << json_string("agent" + std::to_string(k + 1))
      << ", \"where\": " << json_string(worker.empty() ? "this process" : "worker " + worker)
      << ", \"status\": " << json_string(r.errors[k].empty() ? "ok" : "lost");
    if (!r.errors[k].empty()) j << ", \"error\": " << json_string(r.errors[k]);
    j << "}";
  }
  j << "\n  ]\n}\n";
  return j.str();
}

}  // namespace

agents_report run_agents(system_structure system, const run_options& options,
                         const agents_options& agents) {
  if (agents.count < 1) {
    throw validation_error("agents: count must be at least 1, got " + std::to_string(agents.count));
  }
  if (!system.failover.standby.empty() && !system.agents.synchronous) {
    // a replayed agent must meet the tables it met the first time: only rounds give them again
    const std::string where = system.failover.where.str();
    throw validation_error((where.empty() ? std::string() : where + ": ") +
                           "standby workers (<failover>, --standby) need synchronous agents: "
                           "asynchronous ones cannot walk their steps again (docs/failover.md)");
  }
  system.agents.count = agents.count;
  const bool resuming = !options.resume_dir.empty();
  if (resuming && !fs::is_directory(options.resume_dir)) {
    throw validation_error("--resume: " + options.resume_dir.string() + " is not a folder");
  }

  agents_report report;
  report.output_dir = resuming                     ? options.resume_dir
                      : options.output_dir.empty() ? default_output_dir(system)
                                                   : options.output_dir;
  if (!resuming && !options.force_output) check_output_folder_free(report.output_dir);
  create_output_folder(report.output_dir);
  system_structure as_written = system;
  for (const auto& o : options.overrides) apply_override(as_written, o);
  write_file(report.output_dir / "system.xml", to_xml(as_written));
  const std::string started = utc_now();

  const auto n = static_cast<std::size_t>(agents.count);
  report.agents.resize(n);
  report.errors.resize(n);
  std::atomic<bool> stop{false};
  std::atomic<std::size_t> running{n};
  const auto wall_start = std::chrono::steady_clock::now();
  std::vector<std::thread> threads;
  for (std::size_t k = 0; k < n; ++k) {
    threads.emplace_back([&, k] {
      const int agent = static_cast<int>(k + 1);
      try {
        run_options o = options;
        o.output_dir = report.output_dir / ("agent" + std::to_string(agent));
        if (resuming) {
          // each agent continues its own folder (made now if it was killed before it had one)
          create_output_folder(o.output_dir);
          o.resume_dir = o.output_dir;
          o.record_file = fresh_results_name(o.output_dir, system.record.file);
        }
        o.progress = false;  // several bars would garble each other; components log progress
        o.interrupt = &stop;
        o.placeholders["agent"] = std::to_string(agent);
        o.placeholders["shared_table"] = agents.shared_table;
        if (agents.placements) o.build.placements = agents.placements(agent);
        const auto& workers = system.agents.workers;
        report.agents[k] = run_system(
            workers.empty() ? system : on_worker(system, workers[k % workers.size()]), o);
      } catch (const std::exception& e) {
        report.errors[k] = e.what();
        if (agents.lost) agents.lost(agent, e.what());
      }
      --running;
    });
  }
  // the agents stop at the caller's interrupt too
  while (running > 0) {
    if (options.interrupt != nullptr && options.interrupt->load() && !stop) {
      stop = true;
      report.interrupted = true;
      if (agents.abandon) agents.abandon("interrupted");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  for (auto& t : threads) t.join();
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  write_file(report.output_dir / "manifest.json", manifest_json(as_written, report, started));
  if (!report.interrupted && report.lost() == n) {
    throw error("every agent failed; agent 1: " + report.errors.front());
  }
  return report;
}

}  // namespace stride::cosim
