// Contacts (contacts.cpp): floor forces carry the robot, nothing touches in the air, world
// shapes and self-collision stop bodies.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
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

TEST(contacts, standing_feet_carry_the_weight) {
  robot_sim sim(darwin::default_config(k_darwin));
  sim.step(1.0);
  const robot_outputs& o = sim.outputs();
  const double weight = sim.model().total_mass() * 9.81;
  EXPECT_NEAR(o.left_foot_force[2] + o.right_foot_force[2], weight, 0.02 * weight);
  EXPECT_NEAR(o.left_foot_force[2], 0.5 * weight, 0.1 * weight);
  // standing still: the floor pushes up, hardly sideways
  EXPECT_LT(std::hypot(o.left_foot_force[0] + o.right_foot_force[0],
                       o.left_foot_force[1] + o.right_foot_force[1]),
            0.02 * weight);
  EXPECT_GT(o.max_penetration, 0.0);
  EXPECT_LT(o.max_penetration, 0.005);
}

TEST(contacts, nothing_touches_in_the_air) {
  robot_config c = darwin::default_config(k_darwin);
  c.reset_clearance = 0.05;
  robot_sim sim(c);
  const robot_outputs& o = sim.outputs();
  sim.step(c.physics_step);  // 1.3 mm of free fall
  EXPECT_EQ(o.left_foot_force[2], 0.0);
  EXPECT_EQ(o.right_foot_force[2], 0.0);
  EXPECT_EQ(o.max_penetration, 0.0);
  sim.step(1.0);  // landed
  EXPECT_GT(o.left_foot_force[2] + o.right_foot_force[2], 0.5 * sim.model().total_mass() * 9.81);
}

TEST(contacts, without_foot_links_the_robot_stands_but_reports_no_force) {
  robot_config c = darwin::default_config(k_darwin);
  c.left_foot_link.clear();
  c.right_foot_link.clear();
  robot_sim sim(c);
  sim.step(0.5);
  EXPECT_FALSE(sim.outputs().fallen);
  EXPECT_GT(sim.outputs().base_position[2], 0.2);
  EXPECT_GT(sim.outputs().max_penetration, 0.0);
  EXPECT_EQ(sim.outputs().left_foot_force[2], 0.0);
  EXPECT_EQ(sim.outputs().right_foot_force[2], 0.0);
}

TEST(contacts, a_world_shape_stops_a_body_that_is_not_jointed_to_the_world) {
  robot_config c;
  c.urdf_path = k_data + "/table_arm.urdf";
  robot_sim sim(c);
  ASSERT_EQ(sim.model().bodies[0].link, "upper");  // the fixed-base "root": pitch = arm angle
  sim.step(3.0);
  // the forearm's ball rests on the table top: 0.6·sin(θ) = 0.8 − 0.6 − 0.03
  EXPECT_NEAR(sim.outputs().pitch, std::asin(0.17 / 0.6), 0.003);
}

TEST(contacts, self_collision_stops_a_folding_finger_and_can_be_switched_off) {
  auto fold = [](bool self_collision) {
    robot_config c;
    c.urdf_path = k_data + "/table_arm.urdf";
    c.contact.self_collision = self_collision;
    robot_sim sim(c);
    const std::vector<double> targets = {0.0, 0.0, 3.0, 0.0};
    sim.set_joint_targets(targets);
    sim.step(2.0);
    return sim.outputs().joint_angles[2];
  };
  // the tip ball (r 0.04) meets the first link (r 0.02) where 0.2·sin(π − θ) = 0.06
  EXPECT_NEAR(fold(true), std::numbers::pi - std::asin(0.3), 0.01);
  EXPECT_NEAR(fold(false), 3.0, 0.005);
}

}  // namespace
