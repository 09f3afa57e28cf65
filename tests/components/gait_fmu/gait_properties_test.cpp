// Property tests of the generator: timing grid, phase boundaries, symmetry, latch schedule,
// stop sequence, IK failure, gyro feedback, footsteps, state copies. Sections (§) refer to
// docs/walking-generator.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "gait_test_util.hpp"
#include "stride/gait/walking.hpp"

namespace {

using namespace stride::gait;
using gait_test::servos;

/// A generator walking with fixed commands re-asserted every tick (the golden driver).
struct driver {
  walking gen;
  walking_params params;
  walking_state state;
  double x = 0, y = 0, a = 0;
  bool aim = false;
  walking_feedback feedback{true, 0, 0};

  explicit driver(walking_params p = {}, ik_mode mode = ik_mode::darwin, double x_mm = 0,
                  double y_mm = 0, double a_deg = 0)
      : gen(mode), params(p), state(gen.initialize(p)), x(x_mm), y(y_mm), a(a_deg) {
    gen.set_command(state, x, y, a, aim);
    gen.start(state);
  }
  void step() {
    gen.set_command(state, x, y, a, aim);
    gen.tick(state, params, feedback);
  }
  void steps(int n) {
    for (int i = 0; i < n; ++i) step();
  }
};

/// Evaluation times of the ticks until the clock has wrapped `cycles` times.
std::vector<double> eval_times(driver& d, int ticks) {
  std::vector<double> t;
  for (int i = 0; i < ticks; ++i) {
    d.step();
    t.push_back(phase_ms(d.state));
  }
  return t;
}

// ---------------------------------------------------------------------------------------------

TEST(gait_timing, ticks_per_cycle_600_550_500) {
  const struct {
    double period;
    int ticks;
  } cases[] = {{600, 75}, {550, 69}, {500, 63}};
  for (const auto& c : cases) {
    walking_params p;
    p.period_time = c.period;
    driver d(p, ik_mode::darwin, 20);
    const std::vector<double> t = eval_times(d, 4 * c.ticks + 1);
    std::vector<int> starts;
    for (int i = 0; i < static_cast<int>(t.size()); ++i)
      if (t[i] == 0.0) starts.push_back(i);
    ASSERT_EQ(starts.size(), 5u) << "T = " << c.period;
    for (std::size_t k = 0; k + 1 < starts.size(); ++k)
      EXPECT_EQ(starts[k + 1] - starts[k], c.ticks) << "T = " << c.period;
  }
}

TEST(gait_timing, tick_grid_and_phase_numbers_t600) {
  driver d({}, ik_mode::darwin, 20);
  for (int cycle = 0; cycle < 2; ++cycle) {
    for (int j = 0; j < 75; ++j) {
      d.step();
      const double expected = j <= 36 ? 8.0 * j : 300.0 + 8.0 * (j - 37);
      EXPECT_NEAR(phase_ms(d.state), expected, 1e-9) << "cycle " << cycle << " tick " << j;
      const int phase = j < 19 ? 0 : j < 37 ? 1 : j < 56 ? 2 : 3;
      EXPECT_EQ(current_phase(d.state), phase) << "tick " << j;
    }
  }
}

TEST(gait_timing, half_cycle_snap_t550) {
  walking_params p;
  p.period_time = 550;
  driver d(p);
  // T/2 = 275: window [271, 279) is hit by t = 272 (tick 34), which is evaluated at 275
  for (int j = 0; j < 69; ++j) {
    d.step();
    const double expected = j <= 33 ? 8.0 * j : 275.0 + 8.0 * (j - 34);
    EXPECT_NEAR(phase_ms(d.state), expected, 1e-9) << "tick " << j;
  }
  d.step();
  EXPECT_EQ(phase_ms(d.state), 0.0);
}

TEST(gait_timing, phase_boundaries_from_pose) {
  // defaults: tL0 = 15, tL1 = 285, tR0 = 315, tR1 = 585 (T = 600, dsp 0.1)
  driver d({}, ik_mode::darwin, 20);
  d.steps(75);  // first cycle has the half step
  for (int j = 0; j < 75; ++j) {
    d.step();
    const double t = phase_ms(d.state);
    const gait_pose& p = last_pose(d.state);
    if (t <= 15 || (t > 285 && t <= 315) || t > 585) {  // double support
      EXPECT_EQ(p.pelvis_left, 0.0) << "t " << t;
      EXPECT_EQ(p.pelvis_right, 0.0) << "t " << t;
      EXPECT_NEAR(p.left.z, p.right.z, 1e-9) << "both feet down at t " << t;
    } else if (t <= 285) {  // left swing, right support
      EXPECT_GT(p.pelvis_left, 0.0) << "t " << t;
      EXPECT_LT(p.pelvis_right, 0.0) << "t " << t;
      EXPECT_GT(p.left.z, p.right.z + 1e-6) << "left foot lifted at t " << t;
      EXPECT_NEAR(p.pelvis_right / p.pelvis_left, -1 / 0.35, 1e-9);
    } else {  // right swing, left support
      EXPECT_GT(p.pelvis_left, 0.0) << "t " << t;
      EXPECT_LT(p.pelvis_right, 0.0) << "t " << t;
      EXPECT_GT(p.right.z, p.left.z + 1e-6) << "right foot lifted at t " << t;
      EXPECT_NEAR(p.pelvis_left / p.pelvis_right, -1 / 0.35, 1e-9);
    }
  }
}

// ---------------------------------------------------------------------------------------------

/// (right ID, left ID, right centre, left centre) of the mirrored servo pairs
struct servo_pair {
  int right, left, right_centre, left_centre;
};
constexpr servo_pair mirror_pairs[] = {
    {1, 2, 1498, 2518},   {7, 8, 2048, 2048},   {9, 10, 2048, 2048}, {11, 12, 2048, 2048},
    {13, 14, 2048, 2048}, {15, 16, 2048, 2048}, {17, 18, 2048, 2048}};

TEST(gait_symmetry, standing_pose_is_mirror_symmetric) {
  const walking gen;
  const walking_state s = gen.initialize(walking_params{});
  for (const servo_pair& m : mirror_pairs)
    EXPECT_EQ(s.servo_count[m.left - 1] - m.left_centre,
              -(s.servo_count[m.right - 1] - m.right_centre))
        << "IDs " << m.right << "/" << m.left;
}

TEST(gait_symmetry, straight_walking_second_half_mirrors_first_half) {
  for (const ik_mode mode : {ik_mode::darwin, ik_mode::geometric}) {
    for (const double x : {0.0, 20.0, -15.0}) {
      driver d({}, mode, x);
      d.steps(150);
      std::vector<walking_state> cycle;
      for (int j = 0; j < 75; ++j) {
        d.step();
        cycle.push_back(d.state);
      }
      for (int k = 0; k <= 36; ++k) {  // t = 8k and t = 300 + 8k
        const walking_state& first = cycle[k];
        const walking_state& second = cycle[37 + k];
        ASSERT_NEAR(phase_ms(second) - phase_ms(first), 300.0, 1e-9);
        for (const servo_pair& m : mirror_pairs)
          EXPECT_EQ(second.servo_count[m.left - 1] - m.left_centre,
                    -(first.servo_count[m.right - 1] - m.right_centre))
              << "X " << x << " mode " << static_cast<int>(mode) << " k " << k << " IDs " << m.right
              << "/" << m.left;
        // the oscillator's 2pi = 2 * 3.141592 makes the halves differ by ~1e-5 mm
        const gait_pose& p1 = last_pose(first);
        const gait_pose& p2 = last_pose(second);
        EXPECT_NEAR(p2.left.x, p1.right.x, 1e-4);
        EXPECT_NEAR(p2.left.y, -p1.right.y, 1e-4);
        EXPECT_NEAR(p2.left.z, p1.right.z, 1e-4);
        EXPECT_NEAR(p2.pelvis_left, -p1.pelvis_right, 1e-4);
      }
    }
  }
}

TEST(gait_trajectory, side_steps_and_turns_never_cross_the_feet) {
  // §4.3: with Y > 0 the feet spread between 0 and 2Y beyond y_offset; yaw toe-out in [0, 2A] when
  // aim is off, toe-in in [-2A, 0] when aim is on; the sign of Y / A mirrors it.
  for (const double y : {30.0, -30.0}) {
    for (const double a : {20.0, -20.0}) {
      for (const bool aim : {false, true}) {
        driver d({}, ik_mode::darwin, 5, y, a);
        d.aim = aim;
        double min_dy = 1e9, max_dy = -1e9, min_dc = 1e9, max_dc = -1e9;
        for (int k = 0; k < 225; ++k) {
          d.step();
          ASSERT_FALSE(last_tick_ik_failed(d.state));
          for (int v : d.state.servo_count) ASSERT_TRUE(v >= 0 && v <= 4095);
          if (k < 75) continue;  // the first cycle still has the half step
          const gait_pose& p = last_pose(d.state);
          min_dy = std::min(min_dy, p.left.y - p.right.y - d.params.y_offset);
          max_dy = std::max(max_dy, p.left.y - p.right.y - d.params.y_offset);
          min_dc = std::min(min_dc, p.left.yaw - p.right.yaw);
          max_dc = std::max(max_dc, p.left.yaw - p.right.yaw);
        }
        const double a_rad = std::abs(a) * framework_pi / 180;
        EXPECT_GT(min_dy, -1e-9) << "Y " << y;
        EXPECT_LT(max_dy, 2 * std::abs(y) + 1e-9) << "Y " << y;
        EXPECT_GT(max_dy, 1.9 * std::abs(y)) << "Y " << y;
        if (!aim) {
          EXPECT_GT(min_dc, -1e-9) << "A " << a;
          EXPECT_GT(max_dc, 0.95 * 2 * a_rad) << "A " << a;
        } else {
          EXPECT_LT(max_dc, 1e-9) << "A " << a;
          EXPECT_LT(min_dc, -0.95 * 2 * a_rad) << "A " << a;
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Latch schedule (§9.1): compare a run with a parameter change against one without.

/// Index of the first tick at which the two runs' servo outputs differ (or -1).
int first_difference(const std::vector<walking_state>& a, const std::vector<walking_state>& b) {
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    if (servos(a[i]) != servos(b[i]) || phase_ms(a[i]) != phase_ms(b[i]))
      return static_cast<int>(i);
  return -1;
}

/// Runs `ticks` ticks with X = 20; before tick `change_at` `change` is applied to the driver.
template <class Change>
std::vector<walking_state> run(int ticks, int change_at, Change change, double x = 20) {
  driver d({}, ik_mode::darwin, x);
  std::vector<walking_state> out;
  for (int i = 0; i < ticks; ++i) {
    if (i == change_at) change(d);
    d.step();
    out.push_back(d.state);
  }
  return out;
}

TEST(gait_latch, period_change_in_first_half_applies_at_half_cycle) {
  const auto reference = run(300, -1, [](driver&) {});
  // tick 85 = t 80 of cycle 2; the T/2 window of the old period is hit by tick 75 + 37 = 112
  const auto changed = run(300, 85, [](driver& d) { d.params.period_time = 500; });
  EXPECT_EQ(first_difference(reference, changed), 112);
  EXPECT_NEAR(phase_ms(changed[112]), 250.0, 1e-9) << "t snaps to the new T/2";
  // then the second half runs at 250 + 8k until >= 500: 32 ticks (250..498), new cycle at 0
  EXPECT_EQ(phase_ms(changed[112 + 32]), 0.0);
  EXPECT_NEAR(phase_ms(changed[112 + 31]), 498.0, 1e-9);
  // and from there on 63 ticks per cycle
  EXPECT_EQ(phase_ms(changed[112 + 32 + 63]), 0.0);
}

TEST(gait_latch, period_change_in_second_half_applies_at_cycle_start) {
  const auto reference = run(300, -1, [](driver&) {});
  const auto changed = run(300, 120, [](driver& d) { d.params.period_time = 500; });  // t = 364
  const int diff = first_difference(reference, changed);
  EXPECT_GE(diff, 150) << "nothing may change before the next t = 0";
  EXPECT_EQ(phase_ms(changed[150]), 0.0);
  // new cycle of 63 ticks: next t = 0 at tick 213
  EXPECT_NEAR(phase_ms(changed[150 + 31]), 250.0, 1e-9);  // t = 248 lies in [246, 254)
  EXPECT_EQ(phase_ms(changed[213]), 0.0);
  EXPECT_LE(diff, 151) << "the new period must be in effect right after t = 0";
}

TEST(gait_latch, x_command_change_applies_only_at_quarter_ticks) {
  // standing in place (X = 0), then X = 20 written at tick 80 (t = 40 of cycle 2)
  const auto reference = run(
      300, -1, [](driver&) {}, 0.0);
  const auto changed = run(
      300, 80, [](driver& d) { d.x = 20; }, 0.0);
  EXPECT_EQ(first_difference(reference, changed), 75 + 19) << "first quarter latch (t = 152)";
  // written just after the T/4 latch: nothing changes until 3T/4 (tick 75 + 56, t = 452)
  const auto late = run(
      300, 95, [](driver& d) { d.x = 20; }, 0.0);
  EXPECT_EQ(first_difference(reference, late), 75 + 56);
}

TEST(gait_latch, quarter_parameter_change_applies_at_next_quarter_tick) {
  const auto reference = run(300, -1, [](driver&) {});
  const auto changed = run(300, 100, [](driver& d) { d.params.foot_height = 30; });  // t = 200
  EXPECT_EQ(first_difference(reference, changed), 75 + 56);
}

TEST(gait_latch, half_parameter_change_applies_at_next_centre) {
  const auto reference = run(300, -1, [](driver&) {});
  const auto changed = run(300, 80, [](driver& d) { d.params.pelvis_offset = 6; });  // t = 40
  // latched at the T/2 tick (112), but the bump is zero in the double support (t = 300, 308):
  // the first tick with a different pelvis term is the first right-swing tick, t = 316
  int first_pelvis = -1;
  for (int k = 0; k < 300 && first_pelvis < 0; ++k)
    if (last_pose(changed[k]).pelvis_left != last_pose(reference[k]).pelvis_left) first_pelvis = k;
  EXPECT_EQ(first_pelvis, 75 + 37 + 2);
  EXPECT_NEAR(phase_ms(changed[114]), 316.0, 1e-9);
  EXPECT_NEAR(last_pose(changed[114]).pelvis_left, 2 * last_pose(reference[114]).pelvis_left, 1e-9);
  const int diff = first_difference(reference, changed);
  EXPECT_GE(diff, 114);
  EXPECT_LE(diff, 120);
  // a change written in the second half waits for t = 0 of the next cycle
  const auto late = run(300, 120, [](driver& d) { d.params.pelvis_offset = 6; });  // t = 364
  int first_late = -1;
  for (int k = 0; k < 300 && first_late < 0; ++k)
    if (last_pose(late[k]).pelvis_left != last_pose(reference[k]).pelvis_left) first_late = k;
  EXPECT_EQ(first_late, 150 + 2) << "t = 16: first left-swing tick of the next cycle";
}

TEST(gait_latch, live_parameter_change_applies_on_the_next_tick) {
  const auto reference = run(200, -1, [](driver&) {});
  const auto changed = run(200, 90, [](driver& d) { d.params.x_offset = -5; });
  EXPECT_EQ(first_difference(reference, changed), 90);
  // hip pitch offset 13 -> 10 deg: +3 deg on the right (dir +1), -3 deg on the left (dir -1)
  const auto lean = run(200, 91, [](driver& d) { d.params.hip_pitch_offset = 10; });
  EXPECT_EQ(first_difference(reference, lean), 91);
  for (int k = 91; k < 200; ++k) {
    const int right = lean[k].servo_count[10] - reference[k].servo_count[10];
    const int left = lean[k].servo_count[11] - reference[k].servo_count[11];
    EXPECT_TRUE(right == 34 || right == 35) << "tick " << k << ": " << right;
    EXPECT_TRUE(left == -34 || left == -35) << "tick " << k << ": " << left;
  }
}

// ---------------------------------------------------------------------------------------------

TEST(gait_stop, stops_at_a_dsp_centre_38_to_75_ticks_after_stop) {
  const walking gen;
  const walking_params params;
  const walking_state standing = gen.initialize(params);
  int min_delay = 1000, max_delay = 0;
  for (int stop_at = 150; stop_at < 225; ++stop_at) {
    driver d({}, ik_mode::darwin, 20);
    d.steps(stop_at);
    d.gen.stop(d.state);
    int delay = 0;
    while (is_running(d.state) && delay < 200) {
      d.gen.tick(d.state, d.params, d.feedback);  // commands no longer re-asserted
      ++delay;
    }
    ASSERT_FALSE(is_running(d.state)) << "stop at tick " << stop_at;
    min_delay = std::min(min_delay, delay);
    max_delay = std::max(max_delay, delay);
    const double t = phase_ms(d.state);
    EXPECT_TRUE(t == 0.0 || std::abs(t - 300.0) < 1e-9) << "stopped at t " << t;
    // standing still: frozen clock, constant outputs close to the standing posture
    const std::vector<int> final_pose = servos(d.state);
    for (int i = 0; i < 5; ++i) d.gen.tick(d.state, d.params, d.feedback);
    EXPECT_EQ(servos(d.state), final_pose);
    EXPECT_EQ(phase_ms(d.state), t);
    for (int id = 1; id <= 20; ++id) {
      if (t == 0.0)
        EXPECT_EQ(final_pose[id - 1], standing.servo_count[id - 1]) << "ID " << id;
      else
        EXPECT_NEAR(final_pose[id - 1], standing.servo_count[id - 1], 1) << "ID " << id;
    }
  }
  EXPECT_EQ(min_delay, 38);
  EXPECT_EQ(max_delay, 75);
}

TEST(gait_stop, reasserted_commands_keep_it_walking_and_restart_resumes) {
  driver d({}, ik_mode::darwin, 20);
  d.steps(100);
  d.gen.stop(d.state);
  d.steps(300);  // the driver keeps writing X = 20
  EXPECT_TRUE(is_running(d.state));
  d.x = 0;
  for (int i = 0; i < 150 && is_running(d.state); ++i) d.step();
  ASSERT_FALSE(is_running(d.state));
  const double frozen = phase_ms(d.state);
  d.gen.start(d.state);
  EXPECT_EQ(footsteps(d.state), 0);
  d.step();
  EXPECT_EQ(phase_ms(d.state), frozen) << "time resumes where it stopped";
  d.step();
  EXPECT_NEAR(phase_ms(d.state), frozen + 8, 1e-9);
}

TEST(gait_stop, footsteps_count_half_cycles) {
  driver d({}, ik_mode::darwin, 20);
  for (int k = 0; k < 300; ++k) {
    d.step();
    const int expected = 2 * (k / 75) + (k % 75 >= 37 ? 1 : 0);
    ASSERT_EQ(footsteps(d.state), expected) << "tick " << k;
  }
  d.gen.stop(d.state);
  d.x = 0;
  int last = footsteps(d.state);
  while (is_running(d.state)) {
    d.step();
    EXPECT_GE(footsteps(d.state), last);
    last = footsteps(d.state);
  }
  // stop() before tick 300 (t = 0) with the commands already zero: step 8 completes at tick 300,
  // the last one (9) at the next centre, where the generator stops
  EXPECT_EQ(last, 9);
  d.steps(20);
  EXPECT_EQ(footsteps(d.state), last) << "a stopped generator counts nothing";
}

// ---------------------------------------------------------------------------------------------

TEST(gait_ik, failure_keeps_previous_outputs_but_time_advances) {
  driver d({}, ik_mode::darwin, 20);
  driver reference({}, ik_mode::darwin, 20);
  d.steps(100);
  reference.steps(100);
  const std::vector<int> before = servos(d.state);
  const double t_before = phase_ms(d.state);
  d.params.z_offset = -80;  // the leg cannot stretch that far
  d.step();
  reference.step();
  EXPECT_TRUE(last_tick_ik_failed(d.state));
  EXPECT_EQ(servos(d.state), before);
  EXPECT_NEAR(phase_ms(d.state), t_before + 8, 1e-9);
  d.step();
  reference.step();
  EXPECT_EQ(servos(d.state), before);
  d.params.z_offset = 20;
  d.step();
  reference.step();
  EXPECT_FALSE(last_tick_ik_failed(d.state));
  EXPECT_EQ(servos(d.state), servos(reference.state)) << "the clock kept running during failure";
  EXPECT_EQ(phase_ms(d.state), phase_ms(reference.state));
}

TEST(gait_ik, darwin_and_geometric_standing_hip_roll) {
  const walking_state darwin = walking(ik_mode::darwin).initialize({});
  const walking_state geometric = walking(ik_mode::geometric).initialize({});
  EXPECT_EQ(darwin.servo_count[8], 2052);
  EXPECT_EQ(darwin.servo_count[9], 2044);
  EXPECT_EQ(geometric.servo_count[8], 2057);
  EXPECT_EQ(geometric.servo_count[9], 2039);
  // §7.3 standing values (framework)
  const std::vector<int> standing = {1498, 2518, 1845, 2248, 2381, 1712, 2048, 2048, 2052, 2044,
                                     1637, 2459, 2653, 1443, 2389, 1707, 2057, 2039, 2048, 2503};
  EXPECT_EQ(servos(darwin), standing);
  EXPECT_FALSE(is_running(darwin));
}

// ---------------------------------------------------------------------------------------------

TEST(gait_feedback, gyro_terms_are_truncated_per_joint) {
  driver plain({}, ik_mode::darwin, 20);
  driver fed({}, ik_mode::darwin, 20);
  fed.feedback = {true, 17, -23};
  driver off({}, ik_mode::darwin, 20);
  off.feedback = {false, 17, -23};
  for (int k = 0; k < 120; ++k) {
    plain.step();
    fed.step();
    off.step();
    ASSERT_EQ(servos(off.state), servos(plain.state)) << "balance off ignores the gyro";
    std::vector<int> delta(20);
    for (int i = 0; i < 20; ++i) delta[i] = fed.state.servo_count[i] - plain.state.servo_count[i];
    // hip roll +trunc(dir*RL*0.5*4) = +46 both; knee -trunc(dir*FB*0.3*4): -20 / +20;
    // ankle pitch -trunc(dir*FB*0.9*4): +61 / -61; ankle roll -trunc(dir*RL*1*4): +92 both
    const std::vector<int> expected = {0, 0, 0,   0,  0,  0,   0,  0,  46, 46,
                                       0, 0, -20, 20, 61, -61, 92, 92, 0,  0};
    ASSERT_EQ(delta, expected) << "tick " << k;
  }
}

TEST(gait_feedback, head_pan_follows_raw_a_command) {
  driver d({}, ik_mode::darwin, 0, 0, 20);
  d.step();
  EXPECT_EQ(d.state.servo_count[18], 2048 + static_cast<int>(20 * counts_per_degree));
  d.a = -300;  // clamped to -180 deg, value to the servo range
  d.step();
  EXPECT_EQ(d.state.servo_count[18], 0);
}

// ---------------------------------------------------------------------------------------------

bool same_state(const walking_state& a, const walking_state& b) {
  return servos(a) == servos(b) && a.time_ms == b.time_ms && a.eval_time_ms == b.eval_time_ms &&
         a.phase == b.phase && a.footsteps == b.footsteps && a.ctrl_running == b.ctrl_running &&
         a.real_running == b.real_running && a.moved_since_centre == b.moved_since_centre &&
         a.ik_failed == b.ik_failed && a.x_command == b.x_command && a.y_command == b.y_command &&
         a.a_command == b.a_command && a.aim_on == b.aim_on &&
         std::memcmp(&a.timing, &b.timing, sizeof a.timing) == 0 &&
         std::memcmp(&a.amplitudes, &b.amplitudes, sizeof a.amplitudes) == 0 &&
         std::memcmp(&a.pose, &b.pose, sizeof a.pose) == 0;
}

TEST(gait_state, copy_continues_identically_and_initialize_is_pure) {
  driver d({}, ik_mode::darwin, 20, 10, 5);
  d.steps(57);
  walking_state saved;
  std::memcpy(&saved, &d.state, sizeof saved);  // trivially copyable: a byte copy is a state
  d.steps(100);
  const std::vector<int> expected = servos(d.state);
  d.state = saved;
  d.steps(100);
  EXPECT_EQ(servos(d.state), expected);

  const walking gen;
  const walking_state a = gen.initialize({});
  const walking_state b = gen.initialize({});
  EXPECT_TRUE(same_state(a, b));
}

TEST(gait_state, invalid_inputs_throw_without_changing_the_state) {
  driver d({}, ik_mode::darwin, 20);
  d.steps(10);
  walking_state before = d.state;
  EXPECT_THROW(d.gen.set_command(d.state, NAN, 0, 0, false), std::invalid_argument);
  d.params.x_offset = INFINITY;
  EXPECT_THROW(d.gen.tick(d.state, d.params, d.feedback), std::invalid_argument);
  EXPECT_TRUE(same_state(before, d.state));
  d.params.x_offset = -10;
  d.steps(27);  // next tick is the T/2 latch: an invalid period is rejected there
  before = d.state;
  d.params.period_time = 0;
  EXPECT_THROW(d.gen.tick(d.state, d.params, d.feedback), std::invalid_argument);
  EXPECT_TRUE(same_state(before, d.state));
  EXPECT_THROW(walking().initialize(d.params), std::invalid_argument);
}

}  // namespace
