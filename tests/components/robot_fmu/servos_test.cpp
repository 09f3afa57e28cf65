// The servo model (servos.cpp): first-order step response, speed, acceleration and torque limits.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "stride/robot/robot_sim.hpp"

namespace {

using stride::robot::robot_config;
using stride::robot::robot_sim;

const std::string k_data = STRIDE_TEST_DATA_DIR;

// the arm's shoulder (servo 1) without gravity and with enough torque to reach every command
// within a step (the first needs 0.25 kg·m² · 2 rad/s / 8 ms = 63 N·m): it moves exactly as
// commanded. The 10 g wrist slider is welded: such a torque limit on it is unstable.
robot_config weightless_arm() {
  robot_config c;
  c.urdf_path = k_data + "/arm.urdf";
  c.rigid_servos = {3};
  c.gravity = 0.0;
  c.physics_step = 0.008;
  c.servo.torque_limit = 200.0;
  c.servo.max_velocity = 100.0;
  c.servo.max_acceleration = 0.0;
  c.servo.damping = 0.0;
  return c;
}

TEST(servos, a_step_response_follows_the_first_order_servo) {
  // step n: ω_n = p·(target − q_(n−1)), q_n = q_(n−1) + ω_n·dt, so the error shrinks by
  // (1 − p·dt) per step
  robot_config c = weightless_arm();
  c.servo.p_gain = 10.0;
  robot_sim sim(c);
  const std::vector<double> targets = {0.2, 0.0, 0.0};
  sim.set_joint_targets(targets);
  const double shrink = 1.0 - c.servo.p_gain * c.physics_step;
  for (int n : {1, 5, 20, 60}) {
    while (sim.outputs().time < n * c.physics_step - 1e-12) sim.step(c.physics_step);
    EXPECT_NEAR(sim.outputs().joint_angles[0], 0.2 * (1.0 - std::pow(shrink, n)), 2e-5) << n;
    EXPECT_NEAR(sim.outputs().joint_velocities[0], c.servo.p_gain * 0.2 * std::pow(shrink, n - 1),
                2e-3)
        << n;
  }
}

TEST(servos, the_acceleration_limit_ramps_the_speed_up_to_its_limit) {
  robot_config c = weightless_arm();
  c.servo.p_gain = 100.0;
  c.servo.max_velocity = 1.0;
  c.servo.max_acceleration = 20.0;
  robot_sim sim(c);
  const std::vector<double> targets = {1.5, 0.0, 0.0};
  sim.set_joint_targets(targets);
  // 20 rad/s² for three 8 ms steps: 0.48 rad/s
  sim.step(0.024);
  EXPECT_NEAR(sim.outputs().joint_velocities[0], 0.48, 1e-3);
  // from 0.05 s on the speed limit holds
  sim.step(0.04);
  EXPECT_NEAR(sim.outputs().joint_velocities[0], 1.0, 1e-3);
  // without the ramp the speed limit holds from the first step
  c.servo.max_acceleration = 0.0;
  robot_sim no_ramp(c);
  no_ramp.set_joint_targets(targets);
  no_ramp.step(0.008);
  EXPECT_NEAR(no_ramp.outputs().joint_velocities[0], 1.0, 1e-3);
}

TEST(servos, servo_velocity_is_limited) {
  robot_config c;
  c.urdf_path = k_data + "/arm.urdf";
  c.servo.torque_limit = 50.0;
  c.servo.max_velocity = 1.0;
  c.servo.max_acceleration = 0.0;
  robot_sim sim(c);
  const std::vector<double> targets = {1.5, 0.0, 0.0};
  sim.set_joint_targets(targets);
  sim.step(0.5);
  // 0.5 s at 1 rad/s
  EXPECT_NEAR(sim.outputs().joint_angles[0], 0.5, 0.02);
  EXPECT_LE(std::abs(sim.outputs().joint_velocities[0]), 1.0 + 1e-6);
}

TEST(servos, servo_holds_within_its_torque_limit_and_sags_beyond_it) {
  // the arm needs 4.9 N·m to stay horizontal
  robot_config strong;
  strong.urdf_path = k_data + "/arm.urdf";
  strong.servo.torque_limit = 10.0;
  robot_sim a(strong);
  ASSERT_EQ(a.servo_count(), 3);
  const std::vector<double> level = {0.0, 0.0, 0.0};
  a.set_joint_targets(level);
  a.step(2.0);
  EXPECT_NEAR(a.outputs().joint_angles[0], 0.0, 1e-3);

  robot_config weak;
  weak.urdf_path = k_data + "/arm.urdf";  // default 2.5 N·m
  weak.servo.damping = 0.5;               // settle the swing within the test
  robot_sim b(weak);
  b.set_joint_targets(level);
  b.step(4.0);
  // static balance: motor at its limit against gravity, m·g·r·cos(q) = 2.5 N·m
  double moment = 0.0;  // Σ m·x of the arm bodies, kg·m
  moment += b.model().bodies[0].mass * b.model().bodies[0].com[0];
  moment += b.model().bodies[1].mass * (0.5 + b.model().bodies[1].com[0]);
  const double expected = -std::acos(2.5 / (moment * 9.81));
  EXPECT_NEAR(b.outputs().joint_angles[0], expected, 0.03);
}

TEST(servos, joint_torques_report_what_the_motor_holds_against_gravity) {
  // arm.urdf by hand: the shoulder (axis −y, +q lifts) holds the 1 kg upper arm (CoM 0.5 m out)
  // and the 10 g hand (0.5 m out): at rest level it must supply +m·g·r = 1.01·9.81·0.5 N·m, and
  // nothing else acts about the axis (damping ∝ ω = 0, the stops are far away)
  robot_config c;
  c.urdf_path = k_data + "/arm.urdf";
  c.servo.torque_limit = 10.0;
  robot_sim sim(c);
  sim.step(3.0);
  ASSERT_NEAR(sim.outputs().joint_velocities[0], 0.0, 1e-6);
  const double holding = 1.01 * 9.81 * 0.5;
  // at rest the motor row carries the whole static torque (measured: exact to 1e-9)
  EXPECT_NEAR(sim.outputs().joint_torques[0], holding, 1e-6 * holding);
  EXPECT_EQ(sim.outputs().joint_torques[1], 0.0);  // no servo 2 in this model
  // the wrist slider (axis along the arm, level) carries no weight along its axis (measured:
  // 5e-7 N, from the arm's sag)
  EXPECT_NEAR(sim.outputs().joint_torques[2], 0.0, 1e-5);

  // arm raised vertical (q = π/2): no gravity torque at the shoulder; the wrist slider, now
  // pointing up, holds the 10 g hand with +m·g = 0.0981 N
  const std::vector<double> up = {std::acos(-1.0) / 2.0, 0.0, 0.05};
  sim.set_joint_targets(up);
  sim.step(3.0);
  EXPECT_NEAR(sim.outputs().joint_torques[0], 0.0, 1e-6 * holding);
  EXPECT_NEAR(sim.outputs().joint_torques[2], 0.01 * 9.81, 1e-6 * 0.0981);
}

TEST(servos, a_welded_servo_reports_no_torque) {
  // the welded wrist (rigid_servos) has no joint and reads 0; its hand is then part of the upper
  // arm, so the shoulder holds the same 1.01 kg at 0.5 m
  robot_config c;
  c.urdf_path = k_data + "/arm.urdf";
  c.servo.torque_limit = 10.0;
  c.rigid_servos = {3};
  robot_sim sim(c);
  sim.step(3.0);
  EXPECT_EQ(sim.outputs().joint_torques[2], 0.0);
  const double holding = 1.01 * 9.81 * 0.5;
  EXPECT_NEAR(sim.outputs().joint_torques[0], holding, 1e-6 * holding);
}

}  // namespace
