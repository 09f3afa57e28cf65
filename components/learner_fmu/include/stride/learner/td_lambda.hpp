// TD(λ) on state values with accumulating eligibility traces, ε-greedy choice over the successor
// states and the paper's reward, as pure functions over a value-table interface: several agents
// (each with its own traces and random numbers) may share one table.
//
// One step, exactly as "Using reinforcement learning to optimize gait generation parameters of a
// humanoid robot" (Silva, Perico, Costa, Bianchi) states it:
//   a  = ε-greedy over V(successor(s, a)) for the 2n+1 actions
//   s' = successor(s, a)
//   δ  = r + γ V(s') − V(s)
//   Z(s) += 1
//   for all s: V(s) += α δ Z(s);  Z(s) = γ λ Z(s)
// Traces are reset at every episode start, so only the states visited in the episode have
// Z(s) ≠ 0: the "for all s" loop runs over those (bit-identical to the full loop, since the other
// states get V += αδ·0).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "stride/learner/grid.hpp"
#include "stride/learner/rng.hpp"

namespace stride::learner {

/// Where V(s) lives. Implementations may be shared by several agents (then they serialise the
/// calls themselves).
class value_table {
 public:
  virtual ~value_table() = default;
  virtual std::size_t size() const = 0;
  virtual double get(std::size_t s) const = 0;
  virtual void add(std::size_t s, double delta) = 0;
  /// Around the update of RL step `step` (1-based; the choice of the next action included): a
  /// table shared with other agents brings itself up to date before and passes the changes on
  /// after. A table of one agent does nothing.
  virtual void before_update(std::int64_t /*step*/) {}
  virtual void after_update(std::int64_t /*step*/) {}
};

/// A value table held as one dense vector.
class dense_value_table final : public value_table {
 public:
  explicit dense_value_table(std::size_t n = 0, double initial = 0.0) : v_(n, initial) {}
  std::size_t size() const override { return v_.size(); }
  double get(std::size_t s) const override { return v_[s]; }
  void add(std::size_t s, double delta) override { v_[s] += delta; }
  std::vector<double>& values() { return v_; }
  const std::vector<double>& values() const { return v_; }

 private:
  std::vector<double> v_;
};

/// Non-zero eligibility traces of one agent, in order of first visit.
struct eligibility_traces {
  struct entry {
    std::size_t state = 0;
    double z = 0;
    double v_start = 0;  ///< V(state) when it was first visited in this episode
  };
  std::vector<entry> entries;

  void clear() { entries.clear(); }
  /// The entry of `s`, added (z = 0, v_start = V(s)) if missing.
  entry& at(std::size_t s, const value_table& v);
};

struct td_params {
  double alpha = 0.10;   ///< learning rate α
  double gamma = 0.90;   ///< discount γ
  double lambda = 0.05;  ///< trace decay λ
};

/// One TD(λ) update for the transition s → s_next with reward r (see the file comment).
/// Returns δ.
double td_lambda_update(value_table& v, eligibility_traces& z, std::size_t s, double r,
                        std::size_t s_next, const td_params& p);

/// Σ |V(s) − V_episode_start(s)| over the states visited since the traces were cleared.
double sum_abs_value_change(const value_table& v, const eligibility_traces& z);

/// Actions: 0 = stay; 2d+1 = one step up along dimension d; 2d+2 = one step down. 2n+1 in all.
inline std::size_t action_count(const state_grid& g) {
  return 2 * g.dimension_count() + 1;
}
/// The (deterministic) successor of `s` under action `a`; a move past the grid edge is clamped
/// (the state stays where it is, as in the authors' Webots controller).
std::size_t successor(const state_grid& g, std::size_t s, std::size_t a);

/// ε-greedy: with probability ε a uniformly random action, else an action whose successor has
/// the largest V, ties broken uniformly at random. Draws: one uniform01, then either one
/// uniform_below(2n+1) or, for a tie among k > 1 actions, one uniform_below(k).
std::size_t choose_epsilon_greedy(const value_table& v, const state_grid& g, std::size_t s,
                                  double epsilon, rng_state& rng);

struct reward_params {
  double k1 = 0.33;               ///< K1
  double k2 = 10.0;               ///< K2, cm/s
  double negative_reward = -400;  ///< reward of a step in which the robot fell
  double speed_cap = 0;  ///< cm/s; from this speed on the reward is capped_reward (0: none)
  double capped_reward = 0;
};

/// r = negative_reward after a fall, capped_reward when speed_cap > 0 and speed ≥ speed_cap,
/// else K1 · 10^(speed / K2) with speed in cm/s.
double step_reward(double speed_cm_per_s, bool fell, const reward_params& p);

/// The state with the largest V (the lowest index among equals).
std::size_t best_state(const value_table& v);

}  // namespace stride::learner
