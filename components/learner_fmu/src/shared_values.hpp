// The learner's value table when several agents share it (docs/swarm.md): a replica of the
// shared table that takes the merged table before each update and sends this agent's increments
// after it. One agent in synchronous mode learns bit-identically to an unshared learner: the
// service adds its increments in the same order to the same numbers.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

#include "stride/learner/artefacts.hpp"
#include "stride/learner/td_lambda.hpp"
#include "stride/remote/shared_table.hpp"

namespace stride::learner {

class shared_values final : public value_table {
 public:
  /// Called with each merged table the replica takes (snapshots, progress).
  using merged_callback = std::function<void(const remote::table_snapshot&)>;

  /// `initial` is the table every agent starts from; `last_step` this agent's final RL step;
  /// `resumed` set when the run continues an interrupted one: what this agent's checkpoint holds
  /// (all zero without one).
  shared_values(dense_value_table& replica, std::vector<double> initial,
                const remote::table_endpoint& where, int agent, std::int64_t last_step,
                merged_callback on_merged, const shared_checkpoint* resumed = nullptr);

  std::size_t size() const override { return replica_.size(); }
  double get(std::size_t s) const override { return replica_.get(s); }
  void add(std::size_t s, double delta) override;
  void before_update(std::int64_t step) override;
  void after_update(std::int64_t step) override;

  /// A restored state continues after `at.round` (a copy of this agent made anew, e.g. on a
  /// standby worker): the service answers the rounds it walks again with the tables it merged
  /// then and counts their updates no second time.
  void rejoin(const shared_checkpoint& at);
  /// After this agent's last step: waits for every agent's and takes the final table.
  void finish();
  /// Updates merged into the replica's table, all agents counted.
  std::int64_t merged_updates() const { return merged_updates_; }
  /// The last round this agent sent, and its update (for checkpoints).
  std::int64_t last_round() const { return last_round_; }
  const std::vector<std::uint32_t>& last_entries() const { return entries_; }
  const std::vector<double>& last_increments() const { return increments_; }

 private:
  void take(const remote::table_snapshot& t);

  dense_value_table& replica_;
  remote::table_client client_;
  std::int64_t last_step_;
  merged_callback on_merged_;
  std::vector<double> initial_;
  std::vector<std::uint32_t> entries_;  // the update being made, then the last one sent
  std::vector<double> increments_;
  std::int64_t last_round_ = 0;
  std::int64_t merged_updates_ = 0;
};

}  // namespace stride::learner
