#include "stride/learner/td_lambda.hpp"

#include <cmath>

namespace stride::learner {

eligibility_traces::entry& eligibility_traces::at(std::size_t s, const value_table& v) {
  for (entry& e : entries) {
    if (e.state == s) return e;
  }
  entries.push_back(entry{s, 0.0, v.get(s)});
  return entries.back();
}

double td_lambda_update(value_table& v, eligibility_traces& z, std::size_t s, double r,
                        std::size_t s_next, const td_params& p) {
  const double delta = r + p.gamma * v.get(s_next) - v.get(s);
  z.at(s, v).z += 1.0;
  const double decay = p.gamma * p.lambda;
  for (auto& e : z.entries) {
    v.add(e.state, p.alpha * delta * e.z);
    e.z = decay * e.z;
  }
  return delta;
}

double sum_abs_value_change(const value_table& v, const eligibility_traces& z) {
  double sum = 0;
  for (const auto& e : z.entries) sum += std::abs(v.get(e.state) - e.v_start);
  return sum;
}

std::size_t successor(const state_grid& g, std::size_t s, std::size_t a) {
  if (a == 0) return s;
  const std::size_t d = (a - 1) / 2;
  return g.neighbour(s, d, (a - 1) % 2 == 0 ? +1 : -1);
}

std::size_t choose_epsilon_greedy(const value_table& v, const state_grid& g, std::size_t s,
                                  double epsilon, rng_state& rng) {
  const std::size_t n = action_count(g);
  if (uniform01(rng) < epsilon) return static_cast<std::size_t>(uniform_below(rng, n));
  // the greedy set, at most 2 * k_max_dimensions + 1 actions
  std::size_t best[2 * k_max_dimensions + 1];
  std::size_t count = 0;
  double best_value = 0;
  for (std::size_t a = 0; a < n; ++a) {
    const double value = v.get(successor(g, s, a));
    if (count == 0 || value > best_value) {
      best_value = value;
      best[0] = a;
      count = 1;
    } else if (value == best_value) {
      best[count++] = a;
    }
  }
  if (count == 1) return best[0];
  return best[uniform_below(rng, count)];
}

double step_reward(double speed_cm_per_s, bool fell, const reward_params& p) {
  if (fell) return p.negative_reward;
  if (p.speed_cap > 0 && speed_cm_per_s >= p.speed_cap) return p.capped_reward;
  return p.k1 * std::pow(10.0, speed_cm_per_s / p.k2);
}

std::size_t best_state(const value_table& v) {
  std::size_t best = 0;
  for (std::size_t s = 1; s < v.size(); ++s) {
    if (v.get(s) > v.get(best)) best = s;
  }
  return best;
}

}  // namespace stride::learner
