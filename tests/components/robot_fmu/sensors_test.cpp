// Sensors (sensors.cpp): IMU at rest, in free fall and turning; saturation; base pose; centre
// of mass. Expected values come from hand formulas, physical laws and an independent reading of
// the URDF (oracle.hpp), not from the plant's own model code.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "oracle.hpp"
#include "stride/robot/darwin.hpp"
#include "stride/robot/robot_sim.hpp"

namespace {

namespace darwin = stride::robot::darwin;
using stride::robot::robot_config;
using stride::robot::robot_outputs;
using stride::robot::robot_sim;

const std::string k_data = STRIDE_TEST_DATA_DIR;
const std::string k_darwin = std::string(STRIDE_SOURCE_DIR) + "/models/darwin-op/darwin-op.urdf";
using stride::test::k_gravity;
using stride::test::page_9;
using stride::test::walk_ready_lean;

Eigen::Matrix3d base_rotation(const robot_outputs& o) {
  return (Eigen::AngleAxisd(o.yaw, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(o.pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(o.roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// the arm held level by a strong servo; the IMU is on the root link, the upper arm
robot_config held_arm() {
  robot_config c;
  c.urdf_path = k_data + "/arm.urdf";
  c.servo.torque_limit = 10.0;
  return c;
}

TEST(sensors, an_arm_held_level_reads_gravity_and_no_rotation) {
  robot_sim sim(held_arm());
  const std::vector<double> level = {0.0, 0.0, 0.0};
  sim.set_joint_targets(level);
  sim.step(2.0);
  const robot_outputs& o = sim.outputs();
  EXPECT_NEAR(o.acc[0], 0.0, 0.01);
  EXPECT_NEAR(o.acc[1], 0.0, 1e-6);
  EXPECT_NEAR(o.acc[2], 9.81, 0.01);
  for (double w : o.gyro) EXPECT_NEAR(w, 0.0, 1e-3);
}

TEST(sensors, the_gyro_reads_the_joint_rate_about_the_joint_axis) {
  robot_config c = held_arm();
  c.gravity = 0.0;
  robot_sim sim(c);
  const std::vector<double> up = {1.0, 0.0, 0.0};
  sim.set_joint_targets(up);
  sim.step(0.05);
  const robot_outputs& o = sim.outputs();
  ASSERT_GT(o.joint_velocities[0], 1.0);
  // shoulder axis (0, −1, 0) in the upper arm's frame
  EXPECT_NEAR(o.gyro[1], -o.joint_velocities[0], 1e-9);
  EXPECT_NEAR(o.gyro[0], 0.0, 1e-9);
  EXPECT_NEAR(o.gyro[2], 0.0, 1e-9);
}

TEST(sensors, gyro_and_accelerometer_saturate_at_their_ranges) {
  robot_config c = held_arm();
  c.imu.gyro_range = 0.1;
  c.imu.acc_range = 1.0;
  robot_sim sim(c);
  EXPECT_EQ(sim.outputs().acc[2], 1.0);  // 9.81 at rest
  const std::vector<double> up = {1.0, 0.0, 0.0};
  sim.set_joint_targets(up);
  sim.step(0.05);
  EXPECT_EQ(sim.outputs().gyro[1], -0.1);
  EXPECT_GT(sim.outputs().joint_velocities[0], 0.5);
}

TEST(sensors, in_free_fall_the_accelerometer_reads_nothing) {
  robot_config c = darwin::default_config(k_darwin);
  c.reset_clearance = 0.5;
  robot_sim sim(c);
  EXPECT_NEAR(sim.outputs().acc[2], 9.81 * std::cos(sim.outputs().pitch), 1e-9);  // at rest
  sim.step(0.1);
  for (double a : sim.outputs().acc) EXPECT_NEAR(a, 0.0, 1e-3);
  EXPECT_LT(sim.outputs().left_foot_force[2], 1e-12);
}

TEST(sensors, the_centre_of_mass_is_the_mass_weighted_body_centres) {
  robot_sim sim(darwin::default_config(k_darwin));
  sim.step(0.3);
  const robot_outputs& o = sim.outputs();
  const auto& model = sim.model();
  // joint positions by model joint from the encoders, root pose from the base outputs
  std::vector<double> q(model.joints.size());
  for (std::size_t j = 0; j < q.size(); ++j) {
    q[j] = o.joint_angles[static_cast<std::size_t>(model.joints[j].servo_id - 1)];
  }
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(o.yaw, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(o.pitch, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(o.roll, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  stride::robot::pose root;
  root.position = o.base_position;
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) root.rotation[static_cast<std::size_t>(3 * i + k)] = r(i, k);
  }
  const auto frames = model.forward_kinematics(root, q);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t b = 0; b < frames.size(); ++b) {
    const auto& f = frames[b];
    Eigen::Matrix3d rb;
    rb << f.rotation[0], f.rotation[1], f.rotation[2], f.rotation[3], f.rotation[4], f.rotation[5],
        f.rotation[6], f.rotation[7], f.rotation[8];
    const Eigen::Vector3d com(model.bodies[b].com[0], model.bodies[b].com[1],
                              model.bodies[b].com[2]);
    sum += model.bodies[b].mass *
           (rb * com + Eigen::Vector3d(f.position[0], f.position[1], f.position[2]));
  }
  const Eigen::Vector3d expected = sum / model.total_mass();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(o.com[static_cast<std::size_t>(i)], expected[i], 1e-4) << i;
  }
}

TEST(sensors, at_rest_the_imu_reads_gravity_in_the_leaning_torso_and_no_rotation) {
  robot_sim sim(darwin::default_config(k_darwin));
  sim.step(2.0);
  const robot_outputs& o = sim.outputs();
  // imu_link is parallel to base_link, which leans forward by the walk-ready lean (12.94 deg):
  // the specific force of gravity, in m/s² (not g), is (−g·sin, 0, g·cos) of the lean; the feet
  // settling into the floor tilts it by a few thousandths of a degree
  const double lean = walk_ready_lean();
  ASSERT_NEAR(lean, 12.94 * std::numbers::pi / 180.0, 1e-3);
  EXPECT_NEAR(o.acc[0], -k_gravity * std::sin(lean), 0.005);
  EXPECT_NEAR(o.acc[1], 0.0, 0.005);
  EXPECT_NEAR(o.acc[2], k_gravity * std::cos(lean), 0.005);
  for (double w : o.gyro) EXPECT_NEAR(w, 0.0, 1e-3);  // rad/s
  // the CM-730 reads its 512 centre: the board integer of a rate that small is 0 or −1
  const darwin::gyro_counts board = darwin::board_gyro(o.gyro);
  EXPECT_GE(darwin::board_integer(board.fb), -1);
  EXPECT_LE(darwin::board_integer(board.fb), 0);
  EXPECT_GE(darwin::board_integer(board.rl), -1);
  EXPECT_LE(darwin::board_integer(board.rl), 0);
}

TEST(sensors, the_base_and_centre_of_mass_fall_freely_until_the_feet_touch) {
  robot_config c = darwin::default_config(k_darwin);
  c.reset_clearance = 0.5;
  robot_sim sim(c);
  const robot_outputs start = sim.outputs();
  const double dt = c.physics_step;
  // 0.5 m takes sqrt(2·0.5/g) = 0.32 s; 18 steps of 16 ms are 0.288 s, all in the air
  for (int n = 1; n <= 18; ++n) {
    sim.step(dt);
    const robot_outputs& o = sim.outputs();
    // ODE's semi-implicit Euler (v += g·dt, then x += v·dt) drops g·dt²·n(n+1)/2 after n steps,
    // which tends to g·t²/2; every body falls alike, so the pose does not change
    const double drop = k_gravity * dt * dt * n * (n + 1) / 2.0;
    ASSERT_NEAR(start.base_position[2] - o.base_position[2], drop, 1e-9) << n;
    ASSERT_NEAR(start.com[2] - o.com[2], drop, 1e-9) << n;
    // and the velocity after n steps is g·dt·n, straight down, without any turn
    ASSERT_NEAR(o.base_velocity[2], -k_gravity * dt * n, 1e-9) << n;
    ASSERT_NEAR(o.base_velocity[0], 0.0, 1e-9);
    ASSERT_NEAR(o.base_velocity[1], 0.0, 1e-9);
    for (double w : o.base_angular_velocity) ASSERT_NEAR(w, 0.0, 1e-9);
    for (int i = 0; i < 2; ++i) {
      ASSERT_NEAR(o.base_position[static_cast<std::size_t>(i)],
                  start.base_position[static_cast<std::size_t>(i)], 1e-9);
      ASSERT_NEAR(o.com[static_cast<std::size_t>(i)], start.com[static_cast<std::size_t>(i)], 1e-9);
    }
    ASSERT_NEAR(o.roll, start.roll, 1e-9);
    ASSERT_NEAR(o.pitch, start.pitch, 1e-9);
    ASSERT_NEAR(o.yaw, start.yaw, 1e-9);
  }
}

// the pendulum's root link turns about the pivot: its origin (the pivot itself) stays still while
// the body turns at the joint's rate about y
TEST(sensors, the_base_velocity_is_that_of_the_root_link_origin) {
  robot_config c;
  c.urdf_path = k_data + "/tilted_pendulum.urdf";
  c.physics_step = 0.001;
  robot_sim sim(c);
  sim.step(0.2);
  const robot_outputs& o = sim.outputs();
  const double bob_speed = std::abs(o.base_angular_velocity[1]) * 0.5;  // 0.5 m below the pivot
  ASSERT_GT(bob_speed, 0.02);                                           // it swings
  // the pivot moves only by the give of ODE's soft constraint (world CFM 1e-5)
  for (double v : o.base_velocity) EXPECT_LT(std::abs(v), 1e-3 * bob_speed);
  EXPECT_NEAR(o.base_angular_velocity[0], 0.0, 1e-9);
  EXPECT_NEAR(o.base_angular_velocity[2], 0.0, 1e-9);
}

TEST(sensors, a_robot_reset_turned_on_its_hips_reports_the_hand_computed_orientation) {
  // both hip yaws at +theta: the legs turn by Rz(−theta) (axis −z, docs/robot-model.md §1.3),
  // the soles are then pitched by −lean; reset levels the soles, so the torso is the inverse,
  // R = Ry(lean)·Rz(theta) (the small opposite hip and ankle rolls of the two legs cancel).
  // Its roll/pitch/yaw (R = Rz(yaw)·Ry(pitch)·Rx(roll)) are all three different and non-zero.
  const double theta = 0.4;
  const double lean = walk_ready_lean();
  robot_config c = darwin::default_config(k_darwin);
  c.initial_pose[6] = theta;  // r_hip_yaw, ID 7
  c.initial_pose[7] = theta;  // l_hip_yaw, ID 8
  robot_sim sim(c);
  const robot_outputs& o = sim.outputs();
  const double yaw = std::atan2(std::sin(theta), std::cos(lean) * std::cos(theta));
  const double pitch = std::asin(std::sin(lean) * std::cos(theta));
  const double roll = std::atan2(std::sin(lean) * std::sin(theta), std::cos(lean));
  EXPECT_NEAR(o.yaw, yaw, 2e-3);      // 0.409 rad
  EXPECT_NEAR(o.pitch, pitch, 2e-3);  // 0.208 rad
  EXPECT_NEAR(o.roll, roll, 2e-3);    // 0.089 rad
}

TEST(sensors, the_centre_of_mass_at_reset_is_the_urdf_masses_at_the_walk_ready_pose) {
  robot_sim sim(darwin::default_config(k_darwin));
  const robot_outputs& o = sim.outputs();
  // the URDF read afresh: every link's mass at its frame for the page 9 angles (arms and head
  // welded there), then placed by the reported base pose
  const stride::test::urdf_oracle urdf(k_darwin);
  const Eigen::Vector3d in_base = urdf.com_in_root(page_9());
  const Eigen::Vector3d expected =
      Eigen::Vector3d(o.base_position[0], o.base_position[1], o.base_position[2]) +
      base_rotation(o) * in_base;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(o.com[static_cast<std::size_t>(i)], expected[i], 1e-9) << i;  // m
  }
  // docs/robot-model.md §5.2: 0.201 m high; on the plane of symmetry but for the arms
  EXPECT_NEAR(o.com[2], 0.201, 0.002);
  EXPECT_NEAR(o.com[1], 0.0, 0.003);
}

}  // namespace
