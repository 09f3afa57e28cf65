// Leg IK/FK, the darwin IK quirk, servo conversion and the templated standing posture. Sections
// (§) refer to docs/walking-generator.md: IK/FK §6, the quirk §6.4.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "gait_test_util.hpp"
#include "stride/gait/kinematics.hpp"
#include "stride/gait/walking.hpp"

namespace {

using namespace stride::gait;

constexpr double deg = std::numbers::pi / 180.0;

void expect_round_trip(const foot_target<double>& e, double tol, const char* what) {
  double q[6];
  ASSERT_TRUE(leg_ik(e, ik_mode::geometric, q)) << what;
  const foot_target<double> back = leg_fk(q);
  EXPECT_NEAR(back.x, e.x, tol) << what;
  EXPECT_NEAR(back.y, e.y, tol) << what;
  EXPECT_NEAR(back.z, e.z, tol) << what;
  EXPECT_NEAR(back.roll, e.roll, tol) << what;
  EXPECT_NEAR(back.pitch, e.pitch, tol) << what;
  EXPECT_NEAR(back.yaw, e.yaw, tol) << what;
}

TEST(gait_kinematics, geometric_ik_round_trip_random_targets) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> lin(-40, 40), height(0, 80), ang(-0.35, 0.35);
  int solved = 0;
  for (int i = 0; i < 2000; ++i) {
    const foot_target<double> e{lin(rng), lin(rng), height(rng), ang(rng), ang(rng), ang(rng)};
    double q[6];
    if (!leg_ik(e, ik_mode::geometric, q)) continue;
    ++solved;
    expect_round_trip(e, 1e-9, "random target");
  }
  EXPECT_GT(solved, 1700);  // some corners of the box are out of reach
}

TEST(gait_kinematics, geometric_ik_round_trip_along_a_walk) {
  walking_params p;
  p.roll_offset = 3;
  p.pitch_offset = -4;
  p.yaw_offset = 5;
  const walking gen(ik_mode::geometric);
  walking_state s = gen.initialize(p);
  gen.set_command(s, 25, 30, 15, false);
  gen.start(s);
  for (int k = 0; k < 160; ++k) {
    gen.tick(s, p, walking_feedback{});
    ASSERT_FALSE(last_tick_ik_failed(s));
    expect_round_trip(last_pose(s).right, 1e-9, "right foot");
    expect_round_trip(last_pose(s).left, 1e-9, "left foot");
  }
}

TEST(gait_kinematics, reference_standing_example_angles) {
  // §6.3: right leg e_R = (-10, -2.5, 20, 0, 0, 0), framework behaviour
  double q[6];
  ASSERT_TRUE(leg_ik(foot_target<double>{-10, -2.5, 20, 0, 0, 0}, ik_mode::darwin, q));
  const double expected[6] = {0, -0.431, -23.148, 53.190, -30.042, 0.863};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(q[i] / deg, expected[i], 1e-3) << "joint " << i;
  ASSERT_TRUE(leg_ik(foot_target<double>{-10, 2.5, 20, 0, 0, 0}, ik_mode::darwin, q));
  EXPECT_NEAR(q[1] / deg, 0.431, 1e-3);
  EXPECT_NEAR(q[5] / deg, -0.863, 1e-3);
}

TEST(gait_kinematics, darwin_quirk_halves_lateral_and_yaw_corrections) {
  double qd[6], qg[6];
  // lateral offset: hip roll is half of the ideal, the foot reaches about 40 % of y (§6.4)
  for (const double y : {2.5, 22.5}) {
    const foot_target<double> e{-10, y, 20, 0, 0, 0};
    ASSERT_TRUE(leg_ik(e, ik_mode::darwin, qd));
    ASSERT_TRUE(leg_ik(e, ik_mode::geometric, qg));
    EXPECT_NEAR(qg[1], -qg[5], 1e-12) << "ideal: hip roll = -ankle roll (flat foot)";
    EXPECT_NEAR(qd[1], 0.5 * qg[1], 0.02 * std::abs(qg[1])) << "y " << y;
    const double reached = leg_fk(qd).y;
    EXPECT_NEAR(reached, y == 2.5 ? 1.0 : 9.0, 0.3) << "y " << y;
  }
  // foot yaw 20 deg -> hip yaw about 10 deg
  const foot_target<double> turn{-10, 0, 20, 0, 0, 20 * deg};
  ASSERT_TRUE(leg_ik(turn, ik_mode::darwin, qd));
  ASSERT_TRUE(leg_ik(turn, ik_mode::geometric, qg));
  EXPECT_NEAR(qg[0] / deg, 20.0, 1e-9);
  EXPECT_NEAR(qd[0] / deg, 10.0, 0.3);
  // pure x/z offsets with a flat foot are exact in both modes
  const foot_target<double> sag{15, 0, 40, 0, 0, 0};
  ASSERT_TRUE(leg_ik(sag, ik_mode::darwin, qd));
  const foot_target<double> back = leg_fk(qd);
  EXPECT_NEAR(back.x, 15, 1e-9);
  EXPECT_NEAR(back.z, 40, 1e-9);
  EXPECT_NEAR(back.pitch, 0, 1e-9);
}

TEST(gait_kinematics, unreachable_target_fails_and_keeps_output) {
  double q[6] = {1, 2, 3, 4, 5, 6};
  EXPECT_FALSE(leg_ik(foot_target<double>{0, 0, -30, 0, 0, 0}, ik_mode::darwin, q));
  EXPECT_FALSE(leg_ik(foot_target<double>{150, 0, 20, 0, 0, 0}, ik_mode::geometric, q));
  EXPECT_FALSE(leg_ik(foot_target<double>{NAN, 0, 20, 0, 0, 0}, ik_mode::geometric, q));
  EXPECT_EQ(q[0], 1);
  EXPECT_EQ(q[5], 6);
  // fully stretched leg is still reachable (knee = 0)
  EXPECT_TRUE(leg_ik(foot_target<double>{0, 0, 0, 0, 0, 0}, ik_mode::geometric, q));
  EXPECT_NEAR(q[3], 0, 1e-6);
}

TEST(gait_kinematics, servo_count_to_rad_webots_convention) {
  EXPECT_EQ(servo_count_to_rad(2048), 0.0);
  EXPECT_DOUBLE_EQ(servo_count_to_rad(3048), 1000 * 0.088 * std::numbers::pi / 180);
  EXPECT_DOUBLE_EQ(servo_count_to_rad(1498), -550 * 0.088 * std::numbers::pi / 180);
  EXPECT_DOUBLE_EQ(servo_count_to_rad(2548.0), servo_count_to_rad(2548));
}

/// Standing counts of the template vs the generator's initialize(), for one parameter set.
void check_standing(const walking_params& p, ik_mode mode) {
  const walking_state s = walking(mode).initialize(p);
  std::array<double, servo_total> counts{};
  ASSERT_TRUE(standing_servo_counts(standing_params<double>::from(p), mode, counts));
  for (int i = 0; i < servo_total; ++i) {
    // the template omits only the final truncation of the joint term
    const double base = i == 0 ? 1498 : i == 1 ? 2518 : 2048;
    const double joint = counts[i] - base;
    EXPECT_EQ(static_cast<int>(base) + static_cast<int>(joint), s.servo_count[i])
        << "ID " << i + 1 << " count " << counts[i];
    EXPECT_LT(std::abs(counts[i] - s.servo_count[i]), 1.0);
  }
  const std::array<double, servo_total> angles =
      standing_joint_angles(standing_params<double>::from(p), mode);
  for (int i = 0; i < servo_total; ++i) EXPECT_DOUBLE_EQ(angles[i], servo_count_to_rad(counts[i]));
}

TEST(gait_kinematics, standing_template_matches_initialize) {
  check_standing(walking_params{}, ik_mode::darwin);
  check_standing(walking_params{}, ik_mode::geometric);
  walking_params custom;
  custom.x_offset = 4.5;
  custom.y_offset = 12;
  custom.z_offset = 31;
  custom.roll_offset = 2.5;
  custom.pitch_offset = -3;
  custom.yaw_offset = 7;
  custom.hip_pitch_offset = 9.5;
  custom.foot_height = 33;
  custom.swing_top_down = 7;
  custom.period_time = 550;
  custom.dsp_ratio = 0.16;
  check_standing(custom, ik_mode::darwin);
  check_standing(custom, ik_mode::geometric);
}

TEST(gait_kinematics, standing_template_reports_ik_failure) {
  walking_params p;
  p.z_offset = -100;
  std::array<double, servo_total> out{};
  out.fill(7);
  EXPECT_FALSE(standing_joint_angles(standing_params<double>::from(p), ik_mode::darwin, out));
  EXPECT_EQ(out[10], 7);
  EXPECT_THROW(standing_joint_angles(standing_params<double>::from(p), ik_mode::darwin),
               std::domain_error);
}

}  // namespace
