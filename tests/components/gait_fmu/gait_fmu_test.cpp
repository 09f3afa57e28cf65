// gait.fmu through its C interface, loaded with dlopen as any importer does: the golden servo
// output, Webots scaling, parameter checks and latching, config files, Stop(), step sizes and
// FMU state.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "gait_test_util.hpp"
#include "raw_fmu.hpp"

namespace stride::test {
namespace {

constexpr double tick = 0.008;

std::string gait_fmu_path() {
  return std::string(STRIDE_FMU_DIR) + "/gait.fmu";
}

std::vector<int> servo_counts(raw_fmu& f, fmi2Component c) {
  std::vector<fmi2ValueReference> refs;
  for (int i = 1; i <= 20; ++i) refs.push_back(f.vr("servo_count[" + std::to_string(i) + "]"));
  std::vector<int> values(20);
  EXPECT_EQ(f.fmi2GetInteger(c, refs.data(), refs.size(), values.data()), fmi2OK);
  return values;
}

void expect_golden(const std::string& file, double x_move) {
  const auto golden = gait_test::read_csv(gait_test::data_path(file));
  raw_fmu f(gait_fmu_path());
  fmi2Component c = f.instantiate();
  ASSERT_EQ(f.set_real(c, "x_move", x_move), fmi2OK);
  ASSERT_EQ(f.set_boolean(c, "walking", true), fmi2OK);
  f.initialize(c);
  for (std::size_t row = 0; row < golden.rows.size(); ++row) {
    const auto& g = golden.rows[row];
    if (row > 0) {
      ASSERT_EQ(f.fmi2DoStep(c, tick * static_cast<double>(row - 1), tick, fmi2True), fmi2OK);
    }
    const std::vector<int> expected(g.begin() + 2, g.end());
    ASSERT_EQ(servo_counts(f, c), expected) << file << " tick " << g[0];
    ASSERT_EQ(f.boolean(c, "is_walking"), g[1] != 0) << file << " tick " << g[0];
  }
}

TEST(gait_fmu, golden_standing_through_the_fmu) {
  expect_golden("01_stand_default.csv", 0.0);
}

TEST(gait_fmu, golden_forward_walk_through_the_fmu) {
  expect_golden("02_fwd_X20_default.csv", 20.0);
}

TEST(gait_fmu, joint_angles_follow_the_servo_convention) {
  raw_fmu f(gait_fmu_path());
  fmi2Component c = f.instantiate();
  f.initialize(c);
  const std::vector<int> counts = servo_counts(f, c);
  for (int i = 1; i <= 20; ++i) {
    const double expected = (counts[static_cast<std::size_t>(i - 1)] - 2048) * 0.088 * M_PI / 180;
    EXPECT_DOUBLE_EQ(f.real(c, "joint_angle[" + std::to_string(i) + "]"), expected);
  }
}

std::vector<std::vector<int>> walk(double x_move, bool webots_scaling, int ticks) {
  raw_fmu f(gait_fmu_path());
  fmi2Component c = f.instantiate();
  EXPECT_EQ(f.set_boolean(c, "webots_scaling", webots_scaling), fmi2OK);
  EXPECT_EQ(f.set_real(c, "x_move", x_move), fmi2OK);
  EXPECT_EQ(f.set_boolean(c, "walking", true), fmi2OK);
  f.initialize(c);
  std::vector<std::vector<int>> out;
  for (int k = 0; k < ticks; ++k) {
    EXPECT_EQ(f.fmi2DoStep(c, tick * k, tick, fmi2True), fmi2OK);
    out.push_back(servo_counts(f, c));
  }
  return out;
}

TEST(gait_fmu, webots_scaling_maps_one_to_20_mm_and_clamps) {
  const auto reference = walk(20.0, false, 150);
  EXPECT_EQ(walk(1.0, true, 150), reference);
  EXPECT_EQ(walk(1.7, true, 150), reference);  // clamped to 1
  EXPECT_NE(walk(0.5, true, 150), reference);
}

TEST(gait_fmu, invalid_parameter_values_are_rejected_with_a_message) {
  raw_fmu f(gait_fmu_path());
  fmi2Component c = f.instantiate();
  EXPECT_EQ(f.set_real(c, "period_time", 0.0), fmi2Error);
  EXPECT_TRUE(f.logged("period_time")) << f.last_message();
  EXPECT_EQ(f.set_real(c, "dsp_ratio", 1.0), fmi2Error);
  EXPECT_TRUE(f.logged("dsp_ratio")) << f.last_message();
  EXPECT_EQ(f.set_real(c, "x_move", NAN), fmi2Error);
  EXPECT_EQ(f.set_integer(c, "p_gain", -3), fmi2Error);
  EXPECT_EQ(f.set_integer(c, "ik_mode", 2), fmi2Error);
  f.initialize(c);
  EXPECT_EQ(f.set_real(c, "period_time", -5.0), fmi2Error);  // also while running
  EXPECT_EQ(f.set_real(c, "period_time", 500.0), fmi2OK);
}

TEST(gait_fmu, a_period_change_takes_effect_at_the_half_cycle_latch) {
  raw_fmu f(gait_fmu_path());
  fmi2Component c = f.instantiate();
  ASSERT_EQ(f.set_boolean(c, "walking", true), fmi2OK);
  f.initialize(c);
  for (int k = 0; k < 37; ++k) {
    if (k == 10) {
      ASSERT_EQ(f.set_real(c, "period_time", 500.0), fmi2OK);
    }
    ASSERT_EQ(f.fmi2DoStep(c, tick * k, tick, fmi2True), fmi2OK);
    // before the latch the clock still runs on the 600 ms cycle
    ASSERT_NEAR(f.real(c, "phase"), 0.008 * k, 1e-12) << "tick " << k;
  }
  ASSERT_EQ(f.fmi2DoStep(c, tick * 37, tick, fmi2True), fmi2OK);
  EXPECT_NEAR(f.real(c, "phase"), 0.250, 1e-12);  // snapped to the new T/2
  EXPECT_EQ(f.integer(c, "footsteps"), 1);
}

TEST(gait_fmu, walking_false_stops_at_a_double_support_centre) {
  raw_fmu f(gait_fmu_path());
  fmi2Component c = f.instantiate();
  ASSERT_EQ(f.set_real(c, "x_move", 20.0), fmi2OK);
  ASSERT_EQ(f.set_boolean(c, "walking", true), fmi2OK);
  f.initialize(c);
  int k = 0;
  for (; k < 100; ++k) ASSERT_EQ(f.fmi2DoStep(c, tick * k, tick, fmi2True), fmi2OK);
  ASSERT_TRUE(f.boolean(c, "is_walking"));
  ASSERT_EQ(f.set_boolean(c, "walking", false), fmi2OK);
  int stopped_after = -1;
  for (int n = 1; n <= 100; ++n, ++k) {
    ASSERT_EQ(f.fmi2DoStep(c, tick * k, tick, fmi2True), fmi2OK);
    if (!f.boolean(c, "is_walking")) {
      stopped_after = n;
      break;
    }
  }
  EXPECT_GE(stopped_after, 38);
  EXPECT_LE(stopped_after, 75);
  const double phase = f.real(c, "phase");
  EXPECT_TRUE(std::abs(phase) < 1e-12 || std::abs(phase - 0.3) < 1e-12) << phase;
}

TEST(gait_fmu, a_step_runs_whole_ticks_and_drops_the_remainder) {
  raw_fmu a(gait_fmu_path()), b(gait_fmu_path());
  fmi2Component ca = a.instantiate(), cb = b.instantiate();
  for (auto [f, c] : {std::pair{&a, ca}, std::pair{&b, cb}}) {
    ASSERT_EQ(f->set_real(c, "x_move", 20.0), fmi2OK);
    ASSERT_EQ(f->set_boolean(c, "walking", true), fmi2OK);
    f->initialize(c);
  }
  for (int k = 0; k < 40; ++k) {
    ASSERT_EQ(a.fmi2DoStep(ca, 0.016 * k, 0.016, fmi2True), fmi2OK);  // two ticks
    ASSERT_EQ(b.fmi2DoStep(cb, 0.016 * k, 0.008, fmi2True), fmi2OK);
    ASSERT_EQ(b.fmi2DoStep(cb, 0.016 * k + 0.008, 0.008, fmi2True), fmi2OK);
    ASSERT_EQ(servo_counts(a, ca), servo_counts(b, cb)) << "step " << k;
  }
  // 10 ms: one tick, remainder dropped, with a warning
  ASSERT_EQ(a.fmi2DoStep(ca, 0.64, 0.010, fmi2True), fmi2OK);
  ASSERT_EQ(b.fmi2DoStep(cb, 0.64, 0.008, fmi2True), fmi2OK);
  EXPECT_EQ(servo_counts(a, ca), servo_counts(b, cb));
  EXPECT_TRUE(a.logged("not a multiple of 8 ms"));
}

TEST(gait_fmu, config_file_loads_before_initialization_and_explicit_sets_win) {
  const auto dir = std::filesystem::temp_directory_path() / "stride-gait-fmu-test";
  std::filesystem::create_directories(dir);
  const auto ini = dir / "custom.ini";
  std::ofstream(ini) << "[Walking Config]\nperiod_time = 550 ; faster\nhip_pitch_offset = 10\n"
                        "x_offset = -5\n";
  raw_fmu f(gait_fmu_path());
  fmi2Component c = f.instantiate();
  ASSERT_EQ(f.set_string(c, "config_file", ini.string()), fmi2OK);
  ASSERT_EQ(f.set_real(c, "x_offset", -12.0), fmi2OK);
  f.initialize(c);
  EXPECT_EQ(f.real(c, "period_time"), 550.0);
  EXPECT_EQ(f.real(c, "hip_pitch_offset"), 10.0);
  EXPECT_EQ(f.real(c, "x_offset"), -12.0);  // set explicitly: the file does not override it

  // the shipped resources/config.ini holds the framework defaults
  fmi2Component d = f.instantiate("defaults");
  ASSERT_EQ(f.set_string(d, "config_file", "config.ini"), fmi2OK);
  f.initialize(d);
  EXPECT_EQ(servo_counts(f, d),
            std::vector<int>({1498, 2518, 1845, 2248, 2381, 1712, 2048, 2048, 2052, 2044,
                              1637, 2459, 2653, 1443, 2389, 1707, 2057, 2039, 2048, 2503}));
  std::filesystem::remove_all(dir);
}

TEST(gait_fmu, a_missing_or_bad_config_file_fails_initialization_with_its_name) {
  raw_fmu f(gait_fmu_path());
  fmi2Component c = f.instantiate();
  ASSERT_EQ(f.set_string(c, "config_file", "no-such-config.ini"), fmi2OK);
  ASSERT_EQ(f.fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0), fmi2OK);
  ASSERT_EQ(f.fmi2EnterInitializationMode(c), fmi2OK);
  EXPECT_EQ(f.fmi2ExitInitializationMode(c), fmi2Error);
  EXPECT_TRUE(f.logged("no-such-config.ini")) << f.last_message();
}

TEST(gait_fmu, restart_begins_the_walk_again_from_the_standing_pose) {
  const auto golden = gait_test::read_csv(gait_test::data_path("02_fwd_X20_default.csv"));
  raw_fmu f(gait_fmu_path());
  fmi2Component c = f.instantiate();
  ASSERT_EQ(f.set_real(c, "x_move", 20.0), fmi2OK);
  ASSERT_EQ(f.set_boolean(c, "walking", true), fmi2OK);
  f.initialize(c);
  int k = 0;
  for (; k < 130; ++k) ASSERT_EQ(f.fmi2DoStep(c, tick * k, tick, fmi2True), fmi2OK);
  ASSERT_EQ(f.set_integer(c, "restart", 1), fmi2OK);
  for (std::size_t row = 1; row < 100; ++row, ++k) {
    ASSERT_EQ(f.fmi2DoStep(c, tick * k, tick, fmi2True), fmi2OK);
    const std::vector<int> expected(golden.rows[row].begin() + 2, golden.rows[row].end());
    ASSERT_EQ(servo_counts(f, c), expected) << "tick " << row - 1 << " after the restart";
  }
  EXPECT_EQ(f.integer(c, "footsteps"), 2);
}

TEST(gait_fmu, fmu_state_restores_the_continuation) {
  raw_fmu f(gait_fmu_path());
  fmi2Component c = f.instantiate();
  ASSERT_EQ(f.set_real(c, "x_move", 20.0), fmi2OK);
  ASSERT_EQ(f.set_integer(c, "ik_mode", 1), fmi2OK);
  ASSERT_EQ(f.set_boolean(c, "walking", true), fmi2OK);
  f.initialize(c);
  for (int k = 0; k < 50; ++k) ASSERT_EQ(f.fmi2DoStep(c, tick * k, tick, fmi2True), fmi2OK);
  fmi2FMUstate s = nullptr;
  ASSERT_EQ(f.fmi2GetFMUstate(c, &s), fmi2OK);
  std::vector<std::vector<int>> first, second;
  for (int k = 50; k < 80; ++k) {
    ASSERT_EQ(f.fmi2DoStep(c, tick * k, tick, fmi2True), fmi2OK);
    first.push_back(servo_counts(f, c));
  }
  ASSERT_EQ(f.fmi2SetFMUstate(c, s), fmi2OK);
  for (int k = 50; k < 80; ++k) {
    ASSERT_EQ(f.fmi2DoStep(c, tick * k, tick, fmi2True), fmi2OK);
    second.push_back(servo_counts(f, c));
  }
  EXPECT_EQ(first, second);
  f.fmi2FreeFMUstate(c, &s);
}

}  // namespace
}  // namespace stride::test
