// robot_sim on small test models: pendulum period, joint signs, step rule, errors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "quadruped.hpp"
#include "stride/robot/robot_sim.hpp"

namespace {

using stride::robot::robot_config;
using stride::robot::robot_sim;

const std::string k_data = STRIDE_TEST_DATA_DIR;

robot_config config_for(const std::string& file) {
  robot_config c;
  c.urdf_path = k_data + "/" + file;
  return c;
}

TEST(robot_sim, pendulum_swings_with_the_compound_pendulum_period) {
  robot_config c = config_for("pendulum.urdf");
  c.physics_step = 0.001;
  robot_sim sim(c);
  const auto& body = sim.model().bodies[0];
  const double d = -body.com[2];                               // pivot to CoM
  const double i_pivot = body.inertia[1] + body.mass * d * d;  // about the pivot axis y
  const double expected = 2.0 * std::numbers::pi * std::sqrt(i_pivot / (body.mass * 9.81 * d));

  // a short horizontal kick, then free swinging; the fixed-base "pitch" is the pendulum angle
  sim.set_push(2.0, 0.0);
  sim.step(0.02);
  sim.set_push(0.0, 0.0);
  std::vector<double> crossings;
  double last = sim.outputs().pitch;
  double amplitude = 0.0;
  while (sim.outputs().time < 6.0) {
    sim.step(0.001);
    const double now = sim.outputs().pitch;
    amplitude = std::max(amplitude, std::abs(now));
    if ((last < 0.0) != (now < 0.0)) {
      // linear interpolation of the zero crossing
      crossings.push_back(sim.outputs().time - 0.001 * now / (now - last));
    }
    last = now;
  }
  ASSERT_GE(crossings.size(), 8u);
  EXPECT_GT(amplitude, 0.01);
  EXPECT_LT(amplitude, 0.2);  // small-angle regime
  const double period =
      2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  EXPECT_NEAR(period, expected, 0.005 * expected);
  EXPECT_FALSE(sim.outputs().fallen);  // fixed-base models never fall
}

TEST(robot_sim, a_passive_pendulum_released_at_5_degrees_keeps_the_finite_amplitude_period) {
  // tilted_pendulum.urdf by hand: 1 kg solid sphere (r = 0.05 m) 0.5 m below a passive pivot
  // without damping or friction, released from rest 5° from its rest position (q = −5°)
  const double m = 1.0, d = 0.5, g = 9.81, theta0 = 5.0 * std::numbers::pi / 180.0;
  const double i_pivot = 0.4 * m * 0.05 * 0.05 + m * d * d;
  const double t0 = 2.0 * std::numbers::pi * std::sqrt(i_pivot / (m * g * d));
  // finite amplitude: T = T0·(1 + θ0²/16 + 11·θ0⁴/3072 + …), here +0.048 %
  const double expected = t0 * (1.0 + theta0 * theta0 / 16.0 + 11.0 * std::pow(theta0, 4) / 3072.0);

  robot_config c = config_for("tilted_pendulum.urdf");
  // ODE's semi-implicit step errs in the period by about (ω·h)²/24 (ω = 4.4 rad/s): 1e-6 at
  // h = 1 ms, far below the amplitude term this test resolves (8 ms would leave 5e-5)
  c.physics_step = 0.001;
  robot_sim sim(c);
  ASSERT_EQ(sim.servo_count(), 0);  // no servo tags: the pivot is passive
  ASSERT_NEAR(sim.outputs().pitch, theta0, 1e-9);
  std::vector<double> crossings;
  double last = 0.0;
  double amplitude = 0.0;
  bool first = true;
  while (sim.outputs().time < 10.0) {
    sim.step(c.physics_step);
    // the fixed-base body's pitch is the angle from the rest position (its frame is upright
    // when the bob hangs straight down; at the release it is turned +5° about y)
    const double now = sim.outputs().pitch;
    // the amplitude of the last swing (one period is 1.42 s)
    if (sim.outputs().time > 8.5) amplitude = std::max(amplitude, std::abs(now));
    if (!first && (last < 0.0) != (now < 0.0)) {
      crossings.push_back(sim.outputs().time - c.physics_step * now / (now - last));
    }
    last = now;
    first = false;
  }
  ASSERT_GE(crossings.size(), 12u);
  // no damping anywhere: after 6 swings the amplitude is still the release angle (a damping of
  // 5e-4 N·m·s/rad would take 0.9 % off it; measured: 3e-9 rad off)
  EXPECT_NEAR(amplitude, theta0, 1e-4 * theta0);
  const double period =
      2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  // the band: ten times the step's error above, five times below the amplitude term (measured:
  // 1e-7 off)
  EXPECT_NEAR(period, expected, 1e-5 * expected);
}

TEST(robot_sim, a_quadruped_driven_by_joint_name_stands_on_bent_knees) {
  robot_sim sim(stride::test::quadruped_config());
  ASSERT_EQ(sim.servo_count(), 8);
  sim.step(2.0);
  const double height_2s = sim.outputs().base_position[2];
  sim.step(3.0);
  const auto& o = sim.outputs();
  EXPECT_FALSE(o.fallen);
  // by hand: hip 0.04 m below the body origin, foot 2·0.15·cos(0.5) = 0.263 m below the hip,
  // capsule radius 0.02 m: 0.323 m. The velocity servos hold their targets exactly at rest; what
  // is left is the soft contacts' penetration (measured 0.3 mm)
  EXPECT_NEAR(o.base_position[2], 0.04 + 0.3 * std::cos(0.5) + 0.02, 0.001);
  EXPECT_NEAR(o.base_position[2], height_2s, 0.002);
  EXPECT_LT(std::abs(o.roll), 0.02);
  EXPECT_LT(std::abs(o.pitch), 0.02);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(o.joint_angles[k], 0.5, 1e-3) << k;
  for (int k = 4; k < 8; ++k) EXPECT_NEAR(o.joint_angles[k], -1.0, 1e-3) << k;
}

TEST(robot_sim, positive_joint_positions_follow_the_urdf_axis) {
  robot_config c = config_for("arm.urdf");
  c.servo.torque_limit = 10.0;
  robot_sim sim(c);
  const double com_z0 = sim.outputs().com[2];
  const double com_x0 = sim.outputs().com[0];
  // +0.5 rad about (0, -1, 0) lifts the arm; +0.05 m along the arm extends it
  const std::vector<double> targets = {0.5, 0.0, 0.05};
  sim.set_joint_targets(targets);
  sim.step(2.0);
  EXPECT_NEAR(sim.outputs().joint_angles[0], 0.5, 2e-3);
  EXPECT_NEAR(sim.outputs().joint_angles[2], 0.05, 1e-3);
  EXPECT_EQ(sim.outputs().joint_angles[1], 0.0);  // no servo 2 in this model
  EXPECT_GT(sim.outputs().com[2], com_z0 + 0.2);
  // targets beyond the limits are clamped to them (URDF: shoulder <= 2.0, wrist <= 0.1)
  const std::vector<double> beyond = {3.0, 0.0, 0.5};
  sim.set_joint_targets(beyond);
  sim.step(2.0);
  EXPECT_NEAR(sim.outputs().joint_angles[0], 2.0, 0.01);
  EXPECT_NEAR(sim.outputs().joint_angles[2], 0.1, 2e-3);
  EXPECT_NE(com_x0, sim.outputs().com[0]);
}

TEST(robot_sim, step_runs_whole_physics_steps_and_carries_the_remainder) {
  robot_config c = config_for("pendulum.urdf");
  c.physics_step = 0.008;
  robot_sim sim(c);
  sim.step(0.005);
  EXPECT_EQ(sim.outputs().time, 0.0);
  sim.step(0.005);  // 10 ms requested: one step
  EXPECT_DOUBLE_EQ(sim.outputs().time, 0.008);
  sim.step(0.006);  // 16 ms requested: two steps
  EXPECT_DOUBLE_EQ(sim.outputs().time, 0.016);
  for (int k = 0; k < 1000; ++k) sim.step(0.004);  // 4.016 s: exactly 502 steps
  EXPECT_DOUBLE_EQ(sim.outputs().time, 502 * 0.008);
  EXPECT_THROW(sim.step(-0.001), std::invalid_argument);
}

TEST(robot_sim, the_configured_package_path_finds_meshes) {
  // a URDF outside the data folder naming the cube through package://data/ (the data folder is
  // the package "data"): found only with robot_config::package_path
  const std::string urdf =
      (std::filesystem::temp_directory_path() / "stride_robot_sim_test_package.urdf").string();
  std::ofstream(urdf) << "<?xml version=\"1.0\"?><robot name=\"p\"><link name=\"a\"><inertial>"
                         "<mass value=\"1\"/><inertia ixx=\"0.1\" ixy=\"0\" ixz=\"0\" "
                         "iyy=\"0.1\" iyz=\"0\" izz=\"0.1\"/></inertial><collision><geometry>"
                         "<mesh filename=\"package://data/unit_cube.stl\" scale=\"2 2 2\"/>"
                         "</geometry></collision></link></robot>";
  robot_config c;
  c.urdf_path = urdf;
  c.package_path = {"/nonexistent", k_data};
  const robot_sim sim(c);
  EXPECT_EQ(sim.model().bodies[0].shapes[0].mesh->file, k_data + "/unit_cube.stl");
  EXPECT_NEAR(sim.outputs().base_position[2], 1.0, 1e-12);  // a 2 m cube standing on the floor
  c.package_path.clear();
  ::setenv("ROS_PACKAGE_PATH", "", 1);  // nothing from the environment of the test run
  EXPECT_THROW(robot_sim{c}, stride::robot::model_error);
  ::unsetenv("ROS_PACKAGE_PATH");
  std::filesystem::remove(urdf);
}

TEST(robot_sim, bad_settings_name_the_key) {
  auto message = [](robot_config c) -> std::string {
    try {
      robot_sim sim(std::move(c));
    } catch (const std::exception& e) {
      return e.what();
    }
    return "<no error>";
  };
  robot_config c = config_for("arm.urdf");
  c.physics_step = 0.0;
  EXPECT_THAT(message(c), testing::HasSubstr("robot_config.physics_step"));
  c = config_for("arm.urdf");
  c.initial_pose = {0.1};
  EXPECT_THAT(message(c), testing::HasSubstr("robot_config.initial_pose: needs 3 values"));
  c = config_for("arm.urdf");
  c.imu_link = "no_such_link";
  EXPECT_THAT(message(c), testing::HasSubstr("robot_config.imu_link: link 'no_such_link'"));
  c = config_for("arm.urdf");
  c.rigid_servos = {2};
  EXPECT_THAT(message(c), testing::HasSubstr("robot_config.rigid_servos: servo 2"));
  c = robot_config{};
  EXPECT_THAT(message(c), testing::HasSubstr("robot URDF path is empty"));

  robot_sim sim(config_for("arm.urdf"));
  const std::vector<double> wrong_size = {0.0, 0.0};
  EXPECT_THROW(sim.set_joint_targets(wrong_size), std::invalid_argument);
  const std::vector<double> nan = {0.0, std::nan(""), 0.0};
  EXPECT_THROW(sim.set_joint_targets(nan), std::invalid_argument);
  const std::vector<std::uint8_t> garbage(10, 7);
  EXPECT_THROW(sim.restore_state(garbage), std::invalid_argument);
  robot_sim other(config_for("pendulum.urdf"));
  EXPECT_THROW(sim.restore_state(other.save_state()), std::invalid_argument);
}

}  // namespace
