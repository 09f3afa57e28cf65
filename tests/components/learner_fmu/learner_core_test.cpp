// The learner core without FMI: grid parsing, RNG, TD(lambda) against hand-computed values,
// epsilon-greedy statistics, reward, episode rules, determinism and checkpoints.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <sstream>

#include "stride/learner/artefacts.hpp"
#include "stride/learner/session.hpp"

namespace stride::learner {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const learner_error& e) {
    return e.what();
  }
  return "(no error)";
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// ---------------------------------------------------------------------------------------------
// grid

TEST(learner_grid, parses_the_paper_grid_of_455_states) {
  const auto g = state_grid::parse("period_time:450:960:15, swing_right_left:15:39:2");
  ASSERT_EQ(g.dimension_count(), 2u);
  EXPECT_EQ(g.dimensions()[0].count, 35);
  EXPECT_EQ(g.dimensions()[1].count, 13);
  EXPECT_EQ(g.size(), 455u);
  EXPECT_EQ(g.values(0), (std::vector<double>{450, 15}));
  EXPECT_EQ(g.values(454), (std::vector<double>{960, 39}));
  // the first dimension runs fastest
  EXPECT_EQ(g.values(1), (std::vector<double>{465, 15}));
  EXPECT_EQ(g.values(35), (std::vector<double>{450, 17}));
  EXPECT_EQ(g.find({600, 21}, "p"), g.index({10, 3}));
  EXPECT_EQ(g.str(), "period_time:450:960:15,swing_right_left:15:39:2");
}

TEST(learner_grid, decimal_steps_give_exact_decimal_values) {
  const auto g = state_grid::parse("dsp_ratio:0.1:0.5:0.1");
  ASSERT_EQ(g.size(), 5u);
  EXPECT_EQ(g.dimensions()[0].value(2), 0.3);
  EXPECT_EQ(g.dimensions()[0].value(4), 0.5);
}

TEST(learner_grid, four_dimensions_and_clamped_neighbours) {
  const auto g = state_grid::parse("a:0:2:1;b:0:1:1;c:0:2:1;d:5:5:1");
  EXPECT_EQ(g.size(), 18u);
  const std::size_t corner = g.index({2, 1, 0, 0});
  EXPECT_EQ(g.neighbour(corner, 0, +1), corner);  // clamped at the edge
  EXPECT_EQ(g.neighbour(corner, 1, +1), corner);
  EXPECT_EQ(g.neighbour(corner, 0, -1), g.index({1, 1, 0, 0}));
  EXPECT_EQ(g.neighbour(corner, 2, +1), g.index({2, 1, 1, 0}));
  EXPECT_EQ(g.neighbour(corner, 3, -1), corner);
}

TEST(learner_grid, bad_grid_strings_are_errors_naming_the_fault) {
  EXPECT_THAT(error_of([] { state_grid::parse(""); }), HasSubstr("grid: empty"));
  EXPECT_THAT(error_of([] { state_grid::parse("period_time:450:960"); }),
              HasSubstr("'period_time:450:960': expected name:min:max:step"));
  EXPECT_THAT(error_of([] { state_grid::parse("period_time:450:abc:15"); }),
              HasSubstr("max: 'abc' is not a finite number"));
  EXPECT_THAT(error_of([] { state_grid::parse("period_time:+-450:960:15"); }),
              HasSubstr("min: '+-450' is not a finite number"));
  EXPECT_THAT(error_of([] { state_grid::parse("period_time:450:inf:15"); }),
              HasSubstr("max: 'inf' is not a finite number"));
  EXPECT_THAT(error_of([] { state_grid::parse("period_time:450:960:0"); }),
              HasSubstr("step must be > 0"));
  EXPECT_THAT(error_of([] { state_grid::parse("period_time:960:450:15"); }),
              HasSubstr("max < min"));
  EXPECT_THAT(error_of([] { state_grid::parse("period_time:450:960:16"); }),
              HasSubstr("is not a whole number"));
  EXPECT_THAT(error_of([] { state_grid::parse("a:0:1:1,a:0:1:1"); }),
              HasSubstr("parameter 'a' repeated"));
  EXPECT_THAT(error_of([] { state_grid::parse("a:0:1:1,b:0:1:1,c:0:1:1,d:0:1:1,e:0:1:1"); }),
              HasSubstr("more than 4 dimensions"));
  EXPECT_THAT(error_of([] { state_grid::parse("a b:0:1:1"); }), HasSubstr("not a valid name"));
  EXPECT_THAT(error_of([] { state_grid::parse("a:0:1:1,,b:0:1:1"); }),
              HasSubstr("empty dimension"));
}

TEST(learner_grid, settings_out_of_range_are_errors_naming_the_setting) {
  learner_config c;
  EXPECT_NO_THROW(c.validate());
  c.td.alpha = 1.5;
  EXPECT_THAT(error_of([&] { c.validate(); }), HasSubstr("alpha: must be in (0, 1]"));
  c = learner_config{};
  c.epsilon = -0.1;
  EXPECT_THAT(error_of([&] { c.validate(); }), HasSubstr("epsilon"));
  c = learner_config{};
  c.mode = learner_mode::evaluate;
  c.eval_point = {600};
  EXPECT_THAT(error_of([&] { c.validate(); }), HasSubstr("eval_point: needs one value per grid"));
  EXPECT_THAT(error_of([] { parse_step_list("100,x", "snapshot_steps"); }),
              HasSubstr("snapshot_steps: 'x' is not a positive whole number"));
  EXPECT_THAT(error_of([] { parse_step_list("100,-5", "s"); }),
              HasSubstr("'-5' is not a positive"));
  EXPECT_THAT(error_of([] { parse_step_list("1e5", "s"); }), HasSubstr("'1e5' is not a positive"));
  EXPECT_EQ(parse_step_list("300, 100,100", "s"), (std::vector<std::int64_t>{100, 300}));
}

// ---------------------------------------------------------------------------------------------
// random numbers

TEST(learner_rng, same_seed_same_sequence_and_uniform_ranges) {
  rng_state a = seed_rng(42), b = seed_rng(42), c = seed_rng(43);
  bool differs = false;
  for (int i = 0; i < 100; ++i) {
    const auto x = next_u64(a);
    EXPECT_EQ(x, next_u64(b));
    differs = differs || x != next_u64(c);
  }
  EXPECT_TRUE(differs);
  std::map<std::uint64_t, int> counts;
  for (int i = 0; i < 70000; ++i) {
    const auto k = uniform_below(a, 7);
    ASSERT_LT(k, 7u);
    ++counts[k];
    const double u = uniform01(a);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
  }
  for (const auto& [k, n] : counts) {
    EXPECT_NEAR(n, 10000, 400) << k;
  }
}

// ---------------------------------------------------------------------------------------------
// TD(lambda)

TEST(learner_td, update_matches_hand_computed_values_on_a_3x3_grid) {
  const auto g = state_grid::parse("a:0:2:1,b:0:2:1");
  dense_value_table v(g.size(), 0.0);
  eligibility_traces z;
  const td_params p{0.1, 0.9, 0.5};  // gamma * lambda = 0.45
  const std::size_t s0 = g.index({0, 0}), s1 = g.index({1, 0}), s2 = g.index({1, 1});

  // step 1: s0 -> s1, r = 10: delta = 10; Z(s0) = 1; V(s0) = 1; Z(s0) = 0.45
  EXPECT_DOUBLE_EQ(td_lambda_update(v, z, s0, 10.0, s1, p), 10.0);
  EXPECT_DOUBLE_EQ(v.get(s0), 1.0);
  // step 2: s1 -> s2, r = 5: delta = 5 + 0.9*0 - 0 = 5; Z(s1) = 1
  //   V(s0) = 1 + 0.1*5*0.45 = 1.225; V(s1) = 0.5; Z(s0) = 0.2025, Z(s1) = 0.45
  EXPECT_DOUBLE_EQ(td_lambda_update(v, z, s1, 5.0, s2, p), 5.0);
  EXPECT_DOUBLE_EQ(v.get(s0), 1.225);
  EXPECT_DOUBLE_EQ(v.get(s1), 0.5);
  // step 3: s2 -> s1, r = -400: delta = -400 + 0.9*0.5 - 0 = -399.55; Z(s2) = 1
  //   V(s0) = 1.225 + 0.1*(-399.55)*0.2025 = -6.8658875
  //   V(s1) = 0.5 + 0.1*(-399.55)*0.45 = -17.47975
  //   V(s2) = 0 + 0.1*(-399.55)*1 = -39.955
  EXPECT_DOUBLE_EQ(td_lambda_update(v, z, s2, -400.0, s1, p), -399.55);
  EXPECT_NEAR(v.get(s0), -6.8658875, 1e-12);
  EXPECT_NEAR(v.get(s1), -17.47975, 1e-12);
  EXPECT_NEAR(v.get(s2), -39.955, 1e-12);
  // untouched states stay 0, the traces decayed once more
  for (std::size_t s = 0; s < g.size(); ++s) {
    if (s != s0 && s != s1 && s != s2) {
      EXPECT_EQ(v.get(s), 0.0);
    }
  }
  ASSERT_EQ(z.entries.size(), 3u);
  EXPECT_NEAR(z.entries[0].z, 0.45 * 0.45 * 0.45, 1e-15);
  // a revisit accumulates: Z(s1) = 0.45*0.45 + 1 before the update
  td_lambda_update(v, z, s1, 0.0, s1, p);
  EXPECT_NEAR(z.entries[1].z, (0.45 * 0.45 + 1) * 0.45, 1e-15);
  // sum |dV| since the traces were cleared
  EXPECT_NEAR(sum_abs_value_change(v, z),
              std::abs(v.get(s0)) + std::abs(v.get(s1)) + std::abs(v.get(s2)), 1e-12);
}

TEST(learner_td, actions_and_successors_on_a_3x3_grid) {
  const auto g = state_grid::parse("a:0:2:1,b:0:2:1");
  ASSERT_EQ(action_count(g), 5u);
  const std::size_t c = g.index({1, 1});
  EXPECT_EQ(successor(g, c, 0), c);
  EXPECT_EQ(successor(g, c, 1), g.index({2, 1}));
  EXPECT_EQ(successor(g, c, 2), g.index({0, 1}));
  EXPECT_EQ(successor(g, c, 3), g.index({1, 2}));
  EXPECT_EQ(successor(g, c, 4), g.index({1, 0}));
  EXPECT_EQ(successor(g, g.index({2, 2}), 1), g.index({2, 2}));  // clamped
}

TEST(learner_td, epsilon_greedy_statistics) {
  const auto g = state_grid::parse("a:0:2:1,b:0:2:1");
  dense_value_table v(g.size(), 0.0);
  const std::size_t c = g.index({1, 1});
  v.add(g.index({2, 1}), 5.0);  // action 1 is the unique greedy one
  rng_state rng = seed_rng(7);
  const int n = 40000;
  std::map<std::size_t, int> counts;
  for (int i = 0; i < n; ++i) ++counts[choose_epsilon_greedy(v, g, c, 0.2, rng)];
  // greedy with 1 - eps + eps/5 = 0.84, every other action eps/5 = 0.04
  EXPECT_NEAR(counts[1] / double(n), 0.84, 0.01);
  for (std::size_t a : {0u, 2u, 3u, 4u}) {
    EXPECT_NEAR(counts[a] / double(n), 0.04, 0.006) << a;
  }

  // epsilon 0: ties are broken uniformly
  counts.clear();
  dense_value_table flat(g.size(), 0.0);
  for (int i = 0; i < n; ++i) ++counts[choose_epsilon_greedy(flat, g, c, 0.0, rng)];
  for (std::size_t a = 0; a < 5; ++a) {
    EXPECT_NEAR(counts[a] / double(n), 0.2, 0.01) << a;
  }
  // ... among the best only
  flat.add(g.index({0, 1}), 1.0);
  flat.add(g.index({1, 0}), 1.0);
  counts.clear();
  for (int i = 0; i < n; ++i) ++counts[choose_epsilon_greedy(flat, g, c, 0.0, rng)];
  EXPECT_EQ(counts[0] + counts[1] + counts[3], 0);
  EXPECT_NEAR(counts[2] / double(n), 0.5, 0.015);
}

TEST(learner_td, reward_formula) {
  const reward_params p{0.33, 10.0, -400.0};
  EXPECT_DOUBLE_EQ(step_reward(0.0, false, p), 0.33);
  EXPECT_DOUBLE_EQ(step_reward(10.0, false, p), 3.3);
  EXPECT_NEAR(step_reward(20.0, false, p), 33.0, 1e-12);
  EXPECT_NEAR(step_reward(15.0, false, p), 0.33 * std::pow(10.0, 1.5), 1e-12);
  EXPECT_EQ(step_reward(25.0, true, p), -400.0);
}

// ---------------------------------------------------------------------------------------------
// episodes, with a scripted plant: one footstep per call, speed from the state, falls on demand

struct scripted_plant {
  double x = 0;
  int footsteps = 0;
  bool fallen = false;
  int seen_restarts = 0;
  // m per footstep of a state's values; a fall when fall(values) is true
  std::function<double(const std::vector<double>&)> stride = [](auto&) { return 0.05; };
  std::function<bool(const std::vector<double>&)> fall = [](auto&) { return false; };

  plant_inputs step(const session& s, const session_state& st) {
    if (st.restarts != seen_restarts) {
      seen_restarts = st.restarts;
      x = 0;
      footsteps = 0;
      fallen = false;
      return {x, 0, fallen, footsteps};
    }
    const auto values = s.current_values();
    if (fall(values)) {
      fallen = true;
    } else {
      ++footsteps;
      x += stride(values);
    }
    return {x, 0, fallen, footsteps};
  }
};

struct run_result {
  std::vector<step_record> steps;
  std::vector<episode_record> episodes;
  std::vector<double> values;
};

run_result run_scripted(learner_config c, scripted_plant plant, int max_calls = 100000) {
  session_state st;
  dense_value_table v(c.grid.size(), c.initial_value);
  eligibility_traces z;
  session s(c, st, v, z);
  s.start();
  plant.seen_restarts = st.restarts - 1;  // the first call returns the fresh plant
  run_result out;
  for (int i = 0; i < max_calls; ++i) {
    const auto in = plant.step(s, st);
    const auto r = s.advance(in, 300'000'000);
    if (r.step) out.steps.push_back(*r.step);
    if (r.episode) out.episodes.push_back(*r.episode);
    if (r.finished) break;
    if (r.episode) s.begin_episode();
  }
  out.values = v.values();
  return out;
}

learner_config small_config() {
  learner_config c;
  c.grid = state_grid::parse("period_time:450:750:50,swing_right_left:15:35:5");
  c.footsteps_per_step = 2;
  c.settle_footsteps = 1;
  return c;
}

TEST(learner_session, an_episode_ends_after_40_steps) {
  learner_config c = small_config();
  c.total_steps = 120;
  const auto r = run_scripted(c, scripted_plant{});
  ASSERT_EQ(r.episodes.size(), 3u);
  for (const auto& e : r.episodes) {
    EXPECT_EQ(e.steps, 40);
    EXPECT_EQ(e.falls, 0);
    EXPECT_TRUE(e.complete);
  }
  EXPECT_EQ(r.steps.size(), 120u);
  // W = 2 footsteps of 0.05 m in 2 * 0.3 s: 8.333 cm/s
  EXPECT_NEAR(r.steps[0].speed, 100 * 0.1 / 0.6, 1e-9);
  EXPECT_NEAR(r.steps[0].reward, 0.33 * std::pow(10.0, r.steps[0].speed / 10), 1e-12);
  EXPECT_EQ(r.episodes[1].rl_step, 80);
}

TEST(learner_session, an_episode_ends_after_10_falls) {
  learner_config c = small_config();
  c.total_steps = 30;
  c.epsilon = 0;
  scripted_plant p;
  p.fall = [](const std::vector<double>& v) { return v[1] >= 25; };  // half the grid falls
  const auto r = run_scripted(c, p);
  ASSERT_FALSE(r.episodes.empty());
  int falls = 0;
  for (const auto& s : r.steps) {
    EXPECT_EQ(s.values, c.grid.values(s.state));
    EXPECT_EQ(s.fell, s.values[1] >= 25);
    if (s.fell) {
      ++falls;
      EXPECT_EQ(s.reward, -400.0);
      EXPECT_EQ(s.speed, 0.0);
    }
  }
  EXPECT_GT(falls, 0);
  for (const auto& e : r.episodes) {
    EXPECT_TRUE(e.steps == 40 || e.falls == 10 || !e.complete)
        << "episode " << e.episode << ": " << e.steps << " steps, " << e.falls << " falls";
  }
  // a plant that always falls: 10 steps, 10 falls per episode
  scripted_plant always;
  always.fall = [](auto&) { return true; };
  const auto r2 = run_scripted(c, always);
  ASSERT_GE(r2.episodes.size(), 2u);
  EXPECT_EQ(r2.episodes[0].steps, 10);
  EXPECT_EQ(r2.episodes[0].falls, 10);
  EXPECT_EQ(r2.episodes[0].reward, -4000.0);
}

// ---------------------------------------------------------------------------------------------
// protocols

TEST(learner_protocol, names_and_the_authors_controller_settings) {
  EXPECT_EQ(parse_protocol("paper"), protocol::paper);
  EXPECT_EQ(parse_protocol("authors-code"), protocol::authors_code);
  EXPECT_EQ(parse_protocol("authors"), std::nullopt);
  EXPECT_EQ(to_string(protocol::authors_code), "authors-code");
  const learner_config paper = protocol_defaults(protocol::paper);
  EXPECT_EQ(paper.td.lambda, 0.05);
  EXPECT_EQ(paper.reward.negative_reward, -400);
  EXPECT_EQ(paper.steps_per_episode, 40);
  EXPECT_EQ(paper.reward.speed_cap, 0);
  EXPECT_TRUE(paper.balance);
  const learner_config a = protocol_defaults(protocol::authors_code);
  EXPECT_EQ(a.rules, protocol::authors_code);
  EXPECT_EQ(a.td.lambda, 0.3);
  EXPECT_EQ(a.td.alpha, 0.1);
  EXPECT_EQ(a.td.gamma, 0.9);
  EXPECT_EQ(a.epsilon, 0.15);
  EXPECT_EQ(a.reward.negative_reward, -200);
  EXPECT_EQ(a.steps_per_episode, 30);
  EXPECT_EQ(a.max_falls, 10);
  EXPECT_EQ(a.footsteps_per_step, 4);
  EXPECT_EQ(a.settle_footsteps, 0);
  EXPECT_FALSE(a.balance);
  // the controller's reward: pow(10, (v + 1e-5)/10)/3 below 30 cm/s, 50 from there
  for (double v : {0.0, 7.5, 20.0, 29.99}) {
    EXPECT_NEAR(step_reward(v, false, a.reward), std::pow(10.0, (v + 1e-5) / 10) / 3, 1e-12);
  }
  EXPECT_EQ(step_reward(30.0, false, a.reward), 50.0);
  EXPECT_EQ(step_reward(45.0, false, a.reward), 50.0);
  EXPECT_EQ(step_reward(45.0, true, a.reward), -200.0);
  // its window is timed in periods: the grid must have one
  learner_config no_period = a;
  no_period.grid = state_grid::parse("swing_right_left:15:39:2");
  EXPECT_THAT(error_of([&] { no_period.validate(); }), HasSubstr("period_time dimension"));
  EXPECT_THAT(a.canonical(), HasSubstr("protocol=authors-code\n"));
}

// A plant walking at `speed(values)` m/s, stepped every 16 ms like the authors' controller;
// falls when fall(values) is true.
struct timed_plant {
  double x = 0;
  int footsteps = 0;
  bool fallen = false;
  int seen_restarts = -1;
  std::function<double(const std::vector<double>&)> speed = [](auto&) { return 0.1; };
  std::function<bool(const std::vector<double>&)> fall = [](auto&) { return false; };

  plant_inputs step(const session& s, const session_state& st, double h) {
    if (st.restarts != seen_restarts) {
      seen_restarts = st.restarts;
      x = 0;
      fallen = false;
      return {x, 0, fallen, footsteps};
    }
    const auto values = s.current_values();
    if (fall(values)) fallen = true;
    if (!fallen) x += speed(values) * h;
    return {x, 0, fallen, footsteps};
  }
};

run_result run_timed(learner_config c, timed_plant plant, int max_calls = 1'000'000) {
  session_state st;
  dense_value_table v(c.grid.size(), c.initial_value);
  eligibility_traces z;
  session s(c, st, v, z);
  s.start();
  run_result out;
  for (int i = 0; i < max_calls; ++i) {
    const auto r = s.advance(plant.step(s, st, 0.016), 16'000'000);
    if (r.step) out.steps.push_back(*r.step);
    if (r.episode) out.episodes.push_back(*r.episode);
    if (r.finished) break;
    if (r.episode) s.begin_episode();
  }
  out.values = v.values();
  return out;
}

TEST(learner_session, authors_code_windows_last_2w_periods_and_report_twice_the_speed) {
  learner_config c = protocol_defaults(protocol::authors_code);
  c.grid = state_grid::parse("period_time:450:750:150,swing_right_left:15:35:10");
  c.total_steps = 60;
  timed_plant p;
  p.speed = [](const std::vector<double>& v) { return v[1] == 35 ? 0.001 : 0.08; };
  const auto r = run_timed(c, p);
  ASSERT_EQ(r.steps.size(), 60u);
  int slow = 0;
  for (const auto& s : r.steps) {
    ASSERT_FALSE(s.fell);
    // ceil(period/8 * W) control iterations of 16 ms: 8 periods for 600 and 750 ms
    const double period = s.values[0];
    const double iterations = std::ceil(period / 8 * 4);
    EXPECT_NEAR(s.duration, iterations * 0.016, 1e-12) << "period " << period;
    if (s.distance <= 0.01) {
      ++slow;  // less than 1 cm counts as standing still
      EXPECT_EQ(s.speed, 0.0);
      EXPECT_NEAR(s.reward, std::pow(10.0, 1e-6) / 3, 1e-15);
      continue;
    }
    // these periods give whole iterations, so the window is exactly 2·W periods and the speed
    // exactly twice the physical speed of the same window
    EXPECT_EQ(s.speed, 2 * (100 * s.distance / s.duration)) << "period " << period;
    EXPECT_NEAR(s.speed, 100 * s.distance / (4 * period / 1000), 1e-9);
  }
  EXPECT_GT(slow, 0);
}

TEST(learner_session, authors_code_episodes_end_after_more_than_30_steps_in_a_row_without_a_fall) {
  learner_config c = protocol_defaults(protocol::authors_code);
  c.grid = state_grid::parse("period_time:450:750:150,swing_right_left:15:35:10");
  c.total_steps = 93;
  const auto r = run_timed(c, timed_plant{});
  ASSERT_EQ(r.episodes.size(), 3u);
  for (const auto& e : r.episodes) EXPECT_EQ(e.steps, 31);
  // a plant that always falls: the episode ends at the 11th fall
  timed_plant always;
  always.fall = [](auto&) { return true; };
  c.total_steps = 33;
  const auto r2 = run_timed(c, always);
  ASSERT_EQ(r2.episodes.size(), 3u);
  EXPECT_EQ(r2.episodes[0].steps, 11);
  EXPECT_EQ(r2.episodes[0].falls, 11);
  EXPECT_EQ(r2.episodes[0].reward, -2200.0);
  // one fall restarts the count, the falling step counting as the first: 1 + 30 more steps
  timed_plant once;
  int calls = 0;
  once.fall = [&calls](auto&) { return ++calls == 400; };  // in the second window (225..375 each)
  c.total_steps = 32;
  const auto r3 = run_timed(c, once);
  ASSERT_FALSE(r3.episodes.empty());
  EXPECT_TRUE(r3.steps[1].fell);
  EXPECT_EQ(r3.episodes[0].falls, 1);
  EXPECT_EQ(r3.episodes[0].steps, 32);
}

TEST(learner_session, same_seed_gives_an_identical_value_table) {
  learner_config c = small_config();
  c.total_steps = 2000;
  scripted_plant p;
  p.stride = [](const std::vector<double>& v) { return 0.03 + 0.0001 * (v[0] - 450) / v[1]; };
  p.fall = [](const std::vector<double>& v) { return v[0] == 450 && v[1] == 35; };
  const auto a = run_scripted(c, p), b = run_scripted(c, p);
  ASSERT_EQ(a.values.size(), b.values.size());
  EXPECT_EQ(0, std::memcmp(a.values.data(), b.values.data(), a.values.size() * sizeof(double)));
  c.seed = 2;
  const auto other = run_scripted(c, p);
  EXPECT_NE(0, std::memcmp(a.values.data(), other.values.data(), a.values.size() * sizeof(double)));
}

TEST(learner_session, evaluation_mode_measures_without_learning) {
  learner_config c = small_config();
  c.mode = learner_mode::evaluate;
  c.eval_point = {600, 20};
  c.total_steps = 10;
  session_state st;
  dense_value_table v(c.grid.size());
  eligibility_traces z;
  session s(c, st, v, z);
  s.start();
  EXPECT_EQ(s.current_values(), (std::vector<double>{600, 20}));
  scripted_plant p;
  p.seen_restarts = st.restarts - 1;
  int steps = 0;
  for (int i = 0; i < 1000 && s.phase() != walk_phase::finished; ++i) {
    const advance_report r = s.advance(p.step(s, st), 300'000'000);
    if (!r.step) continue;
    ++steps;
    // the log names the point walked, not a grid state
    EXPECT_EQ(r.step->values, (std::vector<double>{600, 20}));
  }
  EXPECT_EQ(steps, 10);
  EXPECT_NEAR(st.eval_distance, 10 * 0.1, 1e-12);
  EXPECT_NEAR(st.eval_time, 10 * 0.6, 1e-9);
  for (double x : v.values()) {
    EXPECT_EQ(x, 0.0);
  }
}

TEST(learner_session, an_evaluation_stands_for_stand_time_before_it_walks_and_measures) {
  learner_config c = small_config();
  c.mode = learner_mode::evaluate;
  c.eval_point = {600, 20};
  c.stand_time = 1.0;
  c.step_timeout = 0.5;  // shorter than the stand: standing is no lack of progress
  session_state st;
  dense_value_table v(c.grid.size());
  eligibility_traces z;
  session s(c, st, v, z);
  s.start();
  EXPECT_FALSE(s.walking());
  plant_inputs standing;  // no footsteps while the gait does not walk
  for (int i = 0; i < 3; ++i) {
    const advance_report r = s.advance(standing, 300'000'000);
    EXPECT_FALSE(r.step.has_value());
  }
  EXPECT_FALSE(s.walking());  // 0.9 s
  s.advance(standing, 300'000'000);
  EXPECT_TRUE(s.walking());  // 1.2 s
  scripted_plant p;
  p.seen_restarts = st.restarts;
  int steps = 0;
  for (int i = 0; i < 100 && steps < 3; ++i) {
    if (s.advance(p.step(s, st), 300'000'000).step) ++steps;
  }
  EXPECT_EQ(steps, 3);
  EXPECT_NEAR(st.eval_time, 3 * 0.6, 1e-9);  // windows measured only while walking
}

TEST(learner_session, a_plant_without_footsteps_or_reset_is_an_error) {
  learner_config c = small_config();
  c.step_timeout = 5;
  session_state st;
  dense_value_table v(c.grid.size());
  eligibility_traces z;
  session s(c, st, v, z);
  s.start();
  std::string e = error_of([&] {
    for (int i = 0; i < 100; ++i) s.advance(plant_inputs{}, 300'000'000);
  });
  EXPECT_THAT(e, HasSubstr("gait.footsteps"));
  s.start();
  plant_inputs fallen;
  fallen.fallen = true;
  e = error_of([&] {
    for (int i = 0; i < 3; ++i) s.advance(fallen, 300'000'000);
  });
  EXPECT_THAT(e, HasSubstr("robot.reset"));
}

// ---------------------------------------------------------------------------------------------
// checkpoints

TEST(learner_checkpoint, round_trip_and_configuration_check) {
  const fs::path dir =
      fs::temp_directory_path() / ("stride-learner-ck-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  checkpoint c;
  c.config = small_config().canonical();
  c.state = {std::byte{1}, std::byte{2}, std::byte{3}};
  c.values = {1.5, -400, 0.1};
  c.traces = {{2, 0.45, -1.0}};
  c.file_sizes = {{"episodes.csv", 1234}};
  write_checkpoint(dir / "checkpoint.bin", c);
  EXPECT_FALSE(fs::exists(dir / "checkpoint.bin.tmp"));
  const checkpoint r = read_checkpoint(dir / "checkpoint.bin");
  EXPECT_EQ(r.config, c.config);
  EXPECT_EQ(r.state, c.state);
  EXPECT_EQ(r.values, c.values);
  ASSERT_EQ(r.traces.size(), 1u);
  EXPECT_EQ(r.traces[0].z, 0.45);
  EXPECT_EQ(r.file_sizes.at("episodes.csv"), 1234u);

  learner_config other = small_config();
  other.td.alpha = 0.2;
  EXPECT_THAT(error_of([&] { check_checkpoint_config(c.config, other.canonical(), "ck"); }),
              HasSubstr("written with alpha = 0.1, this run has alpha = 0.2"));
  // truncated and foreign files
  fs::resize_file(dir / "checkpoint.bin", 30);
  EXPECT_THAT(error_of([&] { read_checkpoint(dir / "checkpoint.bin"); }), HasSubstr("truncated"));
  std::ofstream(dir / "other.bin") << "hello world";
  EXPECT_THAT(error_of([&] { read_checkpoint(dir / "other.bin"); }),
              HasSubstr("not a learner checkpoint"));
  // the earlier format copied the session state from memory: refused by name
  std::vector<std::byte> earlier = checkpoint_bytes(c);
  earlier[7] = std::byte{'1'};
  EXPECT_THAT(error_of([&] { checkpoint_from_bytes(earlier, "old.bin"); }),
              HasSubstr("old.bin: a checkpoint of an earlier Stride (format 1"));
  fs::remove_all(dir);
}

TEST(learner_artefacts, run_files_read_back_what_was_written) {
  const fs::path dir =
      fs::temp_directory_path() / ("stride-learner-files-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto g = state_grid::parse("period_time:450:960:15,swing_right_left:15:39:2");
  dense_value_table v(g.size());
  v.add(g.find({645, 29}, "t"), 10.0);
  const best_summary b = summarize_best(g, v, 1);
  EXPECT_EQ(b.best_values, (std::vector<double>{645, 29}));
  EXPECT_THAT(b.text, HasSubstr("period_time = 645, swing_right_left = 29"));
  write_best(dir, b, protocol::authors_code, 1200, 30, 7);
  const best_record best = read_best(dir / run_files::best);
  EXPECT_EQ(best.rules, protocol::authors_code);
  EXPECT_EQ(best.rl_steps, 1200);
  EXPECT_EQ(best.episodes, 30);
  EXPECT_EQ(best.falls, 7);
  EXPECT_THAT(best.text, HasSubstr("best state: period_time = 645"));

  evaluation_result e;
  e.point = {{"period_time", 600}, {"swing_right_left", 20}};
  e.windows = 12;
  e.falls = 1;
  e.distance = 4.25;
  e.measured_time = 57.6;
  e.mean_speed = 14.75;
  e.sim_time = 60;
  e.physical_speed = 7.378472222222222;
  e.rules = protocol::authors_code;
  write_evaluation(dir, e);
  const evaluation_result back = read_evaluation(dir / run_files::evaluation);
  EXPECT_EQ(back.point, e.point);
  EXPECT_EQ(back.windows, 12);
  EXPECT_EQ(back.falls, 1);
  EXPECT_EQ(back.distance, 4.25);
  EXPECT_EQ(back.measured_time, 57.6);
  EXPECT_EQ(back.mean_speed, 14.75);
  EXPECT_EQ(back.physical_speed, e.physical_speed);
  EXPECT_EQ(back.rules, protocol::authors_code);

  write_value_table(dir / run_files::value_table, g, v);
  std::ofstream(dir / run_files::value_table, std::ios::app) << "450,1";  // a row cut by a kill
  const csv_columns t = read_csv_log(dir / run_files::value_table);
  EXPECT_EQ(t.header, (std::vector<std::string>{"period_time", "swing_right_left", "V"}));
  ASSERT_EQ(t.rows.size(), g.size());
  EXPECT_EQ(t.rows[g.find({645, 29}, "t")], (std::vector<double>{645, 29, 10}));
  EXPECT_EQ(t.column("V"), 2);

  EXPECT_EQ(run_files::snapshot(50000), "v_snapshot_50000.csv");
  EXPECT_EQ(run_files::snapshot_step("v_snapshot_50000.csv"), 50000);
  EXPECT_EQ(run_files::snapshot_step("v_snapshot_x.csv"), -1);
  EXPECT_EQ(run_files::snapshot_step("v_table.csv"), -1);
  EXPECT_THAT(error_of([&] { read_best(dir / "nothing.txt"); }), HasSubstr("nothing.txt"));
  fs::remove_all(dir);
}

// A learner re-created after a lost worker opens its logs afresh and then restores a state: the
// rows up to that state must survive (docs/failover.md); a fresh run still replaces old logs.
TEST(learner_artefacts,
     new_logs_replace_old_ones_at_the_first_row_so_a_restored_state_keeps_its_rows) {
  const fs::path dir =
      fs::temp_directory_path() / ("stride-learner-logs-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto g = state_grid::parse("period_time:450:960:15,swing_right_left:15:39:2");
  const fs::path episodes = dir / run_files::episodes;
  std::ofstream(episodes) << "rows of an older run\n";
  const auto text = [&] { return read_text(episodes); };
  episode_record e;
  e.episode = 1;
  std::map<std::string, std::uint64_t> saved;
  {
    artefact_writer first(dir, g, false, nullptr);
    EXPECT_EQ(text(), "rows of an older run\n");  // not yet: nothing was written
    first.episode(e);
    saved = first.flush();
    e.episode = 2;
    first.episode(e);
  }
  const std::string at_save = text().substr(0, saved.at(run_files::episodes));
  EXPECT_THAT(at_save, HasSubstr("episode,steps"));
  EXPECT_THAT(text(), HasSubstr("\n2,"));
  {
    artefact_writer again(dir, g, false, nullptr);  // the re-created instance
    again.cut_back(saved);                          // its restored state
  }
  EXPECT_EQ(text(), at_save);
  { artefact_writer fresh(dir, g, false, nullptr); }  // a new run writes nothing
  EXPECT_EQ(text(),
            "episode,steps,falls,reward,sum_abs_dv,start_period_time,"
            "start_swing_right_left,rl_step,time,complete\n");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace stride::learner
