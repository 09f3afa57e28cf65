// Sensors (sensors.cpp): IMU at rest, in free fall and turning; saturation; centre of mass.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

#include "stride/robot/darwin.hpp"
#include "stride/robot/robot_sim.hpp"

namespace {

namespace darwin = stride::robot::darwin;
using stride::robot::robot_config;
using stride::robot::robot_outputs;
using stride::robot::robot_sim;

const std::string k_data = STRIDE_TEST_DATA_DIR;
const std::string k_darwin = std::string(STRIDE_SOURCE_DIR) + "/models/darwin-op/darwin-op.urdf";

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

}  // namespace
