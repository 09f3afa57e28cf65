// Several agents at once: the whole system run `count` times concurrently, each copy a complete
// run with its own clock and folder (docs/swarm.md). Agents share nothing here; what they share
// (a table of values) is reached by their components through `${shared_table}`, which the caller
// provides, so libstride needs no transport.
#ifndef STRIDE_COSIM_RUN_AGENTS_HPP
#define STRIDE_COSIM_RUN_AGENTS_HPP

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "stride/cosim/placement.hpp"
#include "stride/cosim/run.hpp"

namespace stride::cosim {

struct agents_options {
  int count = 1;
  /// `${shared_table}` for every agent
  std::string shared_table;
  /// Agent k's placement resolvers (replacing `run_options::build.placements`): each agent is a
  /// run of its own, also for the workers it uses. Empty: the options' resolvers, shared.
  std::function<std::vector<std::shared_ptr<placement_resolver>>(int agent)> placements;
  /// Called once per failed agent, from its thread, while the others go on: what they share
  /// must go on without it (e.g. synchronous rounds stop waiting for it).
  std::function<void(int agent, const std::string& why)> lost;
  /// Called once when the run is interrupted: agents waiting for the others must be released.
  std::function<void(const std::string& why)> abandon;
};

struct agents_report {
  std::filesystem::path output_dir;
  std::vector<run_report> agents;   ///< agent k at [k-1]; output_dir DIR/agent<k>
  std::vector<std::string> errors;  ///< per agent, "" if it finished
  bool interrupted = false;
  double wall_seconds = 0;
  /// agents that failed while others finished
  std::size_t lost() const;
};

/// Runs the agents, agent k on a thread of its own with `${agent}` = k into DIR/agent<k>/
/// (run_system); with `<agents workers=...>` agent k's components without a worker of their own
/// run on worker (k - 1) mod n. An agent that fails is lost: the others go on. Writes
/// DIR/system.xml and DIR/manifest.json (status ok, partial (agents lost), error (all lost) or
/// interrupted; agents, mode, wall time, each agent's status and error). With
/// `options.resume_dir` = DIR of an interrupted run, agent k resumes DIR/agent<k> (its results in
/// a fresh file); what they share must be resumed by the caller.
/// \throws validation_error before anything runs; error after the run when every agent failed
/// (the first one's error), with the manifest written.
agents_report run_agents(system_structure system, const run_options& options,
                         const agents_options& agents);

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_RUN_AGENTS_HPP
