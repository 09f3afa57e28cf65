// Servos by joint name and servo models by joint name (servo_joints.cpp), through robot_sim.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "stride/robot/robot_sim.hpp"

namespace {

using stride::robot::robot_config;
using stride::robot::robot_sim;
using stride::robot::servo_config;
using testing::HasSubstr;

const std::string k_data = STRIDE_TEST_DATA_DIR;

// arm.urdf: servo tags 1 (shoulder, revolute) and 3 (wrist, prismatic); holding the arm level
// takes 4.95 N·m at the shoulder
robot_config arm() {
  robot_config c;
  c.urdf_path = k_data + "/arm.urdf";
  c.servo.torque_limit = 10.0;
  return c;
}

std::string message(const robot_config& c) {
  try {
    robot_sim sim(c);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "<accepted>";
}

TEST(servo_joints, servo_ids_follow_the_listed_joint_names_not_the_urdf_tags) {
  robot_config c = arm();
  c.servo_joints = {"wrist", "shoulder"};
  robot_sim sim(c);
  ASSERT_EQ(sim.servo_count(), 2);  // the URDF tags would give 3
  // ID 1 is now the wrist (m), ID 2 the shoulder (rad)
  const std::vector<double> targets = {0.05, 0.5};
  sim.set_joint_targets(targets);
  sim.step(2.0);
  EXPECT_NEAR(sim.outputs().joint_angles[0], 0.05, 1e-3);
  EXPECT_NEAR(sim.outputs().joint_angles[1], 0.5, 2e-3);
}

TEST(servo_joints, initial_pose_follows_the_listed_order) {
  robot_config c = arm();
  c.servo_joints = {"wrist", "shoulder"};
  c.initial_pose = {0.08, 0.3};
  robot_sim sim(c);
  EXPECT_NEAR(sim.outputs().joint_angles[0], 0.08, 1e-9);
  EXPECT_NEAR(sim.outputs().joint_angles[1], 0.3, 1e-9);
}

TEST(servo_joints, a_movable_joint_not_listed_is_passive) {
  // the shoulder without its servo: nothing holds the 1 kg arm, which swings down
  robot_config c = arm();
  c.servo_joints = {"wrist"};
  robot_sim sim(c);
  ASSERT_EQ(sim.servo_count(), 1);
  const double z0 = sim.outputs().com[2];
  sim.step(0.3);
  // free fall of a pendulum's start: well beyond what a 10 N·m servo would let it sag
  EXPECT_LT(sim.outputs().com[2], z0 - 0.1);
  // the listed one is driven
  robot_config held = arm();
  held.servo_joints = {"shoulder"};
  robot_sim h(held);
  h.step(0.3);
  EXPECT_NEAR(h.outputs().com[2], z0, 2e-3);
}

TEST(servo_joints, bad_names_are_named) {
  robot_config c = arm();
  c.servo_joints = {"shoulder", "elbow"};
  EXPECT_THAT(message(c),
              HasSubstr("robot_config.servo_joints: joint 'elbow' is not a movable joint"));
  c.servo_joints = {"shoulder", "wrist", "shoulder"};
  EXPECT_THAT(message(c), HasSubstr("robot_config.servo_joints: joint 'shoulder' is listed twice"));
  // a fixed joint is not a movable joint
  robot_config p;
  p.urdf_path = k_data + "/pendulum.urdf";
  p.servo_joints = {"bob_weld"};
  EXPECT_THAT(message(p), HasSubstr("joint 'bob_weld' is not a movable joint"));
}

TEST(joint_servos, a_named_joint_gets_its_own_servo_model) {
  // default servo: 2.5 N·m cannot hold the level arm (4.95 N·m); the shoulder's own can
  robot_config c;
  c.urdf_path = k_data + "/arm.urdf";
  servo_config strong;
  strong.torque_limit = 10.0;
  c.joint_servos = {{"shoulder", strong}};
  robot_sim sim(c);
  sim.step(2.0);
  EXPECT_NEAR(sim.outputs().joint_angles[0], 0.0, 1e-3);

  // the later entry for a joint wins: a weak shoulder sags to m·g·r·cos(q) = 2.5 N·m
  servo_config weak;
  weak.damping = 0.5;  // settles the swing within the test
  c.joint_servos = {{"shoulder", strong}, {"shoulder", weak}};
  robot_sim sags(c);
  sags.step(4.0);
  // arm.urdf by hand: 1 kg at 0.5 m plus the 10 g hand at 0.5 m
  const double expected = -std::acos(2.5 / ((1.0 + 0.01) * 0.5 * 9.81));
  EXPECT_NEAR(sags.outputs().joint_angles[0], expected, 0.03);
}

TEST(joint_servos, bad_entries_are_named) {
  robot_config c = arm();
  c.joint_servos = {{"elbow", servo_config{}}};
  EXPECT_THAT(message(c),
              HasSubstr("robot_config.joint_servos: joint 'elbow' is not a servo joint"));
  // with servo_joints the unlisted wrist is passive: no servo model for it
  c.servo_joints = {"shoulder"};
  c.joint_servos = {{"wrist", servo_config{}}};
  EXPECT_THAT(message(c), HasSubstr("joint 'wrist' is not a servo joint"));
  servo_config bad;
  bad.max_velocity = 0.0;
  c = arm();
  c.joint_servos = {{"wrist", bad}};
  EXPECT_THAT(message(c), HasSubstr("robot_config.joint_servos[wrist].max_velocity: must be > 0"));
}

}  // namespace
