// Contacts (contacts.cpp): floor forces carry the robot, each foot its share by statics, nothing
// touches in the air, world shapes and self-collision stop bodies.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "oracle.hpp"
#include "quadruped.hpp"
#include "stride/robot/darwin.hpp"
#include "stride/robot/robot_sim.hpp"

namespace {

namespace darwin = stride::robot::darwin;
using stride::robot::robot_config;
using stride::robot::robot_outputs;
using stride::robot::robot_sim;

const std::string k_data = STRIDE_TEST_DATA_DIR;
const std::string k_darwin = std::string(STRIDE_SOURCE_DIR) + "/models/darwin-op/darwin-op.urdf";

// the weight from the URDF's <mass> elements, read afresh (docs/robot-model.md §2.1: 2.9253 kg)
double urdf_weight() {
  return stride::test::urdf_oracle(k_darwin).total_mass() * stride::test::k_gravity;
}

// floor forces averaged over `seconds` of a robot at rest, so that no single step's settling counts
struct foot_loads {
  double left = 0.0, right = 0.0, fx = 0.0, fy = 0.0;
};
foot_loads average_loads(robot_sim& sim, double seconds) {
  foot_loads a;
  const int n = static_cast<int>(std::lround(seconds / sim.config().physics_step));
  for (int k = 0; k < n; ++k) {
    sim.step(sim.config().physics_step);
    const robot_outputs& o = sim.outputs();
    a.left += o.left_foot_force[2] / n;
    a.right += o.right_foot_force[2] / n;
    a.fx += (o.left_foot_force[0] + o.right_foot_force[0]) / n;
    a.fy += (o.left_foot_force[1] + o.right_foot_force[1]) / n;
  }
  return a;
}

TEST(contacts, standing_still_each_foot_carries_half_the_urdf_weight) {
  robot_sim sim(darwin::default_config(k_darwin));
  sim.step(1.0);
  const foot_loads f = average_loads(sim, 1.0);
  const double weight = urdf_weight();
  ASSERT_NEAR(weight, 2.9253 * 9.81, 0.001);
  // standing still the body does not accelerate, so the floor carries exactly the weight; the
  // soft contacts have settled after a second (measured: within 0.001 %)
  EXPECT_NEAR(f.left + f.right, weight, 0.001 * weight);
  // the robot is mirror-symmetric but for the arms' pitch (page 9 shoulders −48°/+41°), which
  // moves the centre of mass fore and aft, not sideways: each foot carries half
  EXPECT_NEAR(f.left, 0.5 * weight, 0.005 * weight);
  EXPECT_NEAR(f.right, 0.5 * weight, 0.005 * weight);
  EXPECT_LT(std::hypot(f.fx, f.fy), 0.001 * weight);
  // the soles sink into the soft contact by about half a millimetre (models/darwin-op/README.md)
  EXPECT_GT(sim.outputs().max_penetration, 0.0001);
  EXPECT_LT(sim.outputs().max_penetration, 0.002);
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

// Statics of a body on two soles. The soles are 66 mm wide boxes centred 48 mm either side of
// the middle (hip at y = ±37 mm, sole box at ±11 mm in the foot: docs/robot-model.md §1.3,
// §3.3): the left sole's contacts lie in y ∈ [a, b], the right's in [−b, −a], a = 15 mm,
// b = 81 mm, here widened by 3 mm for the small page 9 hip and ankle rolls. Balancing moments
// about x: Σ y·F = W·y_com, hence F_left ≥ W·(y_com + a)/(a + b), whatever the pressure
// distribution under each sole.
constexpr double k_sole_inner = 0.012;
constexpr double k_sole_outer = 0.084;

// stands, then tilts both legs sideways by phi within 1 s (hip and ankle rolls +phi each: a
// parallelogram, the torso stays level), which moves the body over the left foot for phi > 0
robot_sim leaning_sideways(double phi) {
  robot_sim sim(darwin::default_config(k_darwin));
  const std::vector<double> stance = sim.config().initial_pose;
  sim.step(0.5);
  for (int k = 1; k <= 125; ++k) {
    std::vector<double> targets = stance;
    for (int id : {9, 10, 17, 18}) targets[static_cast<std::size_t>(id - 1)] += phi * k / 125.0;
    sim.set_joint_targets(targets);
    sim.step(0.008);
  }
  sim.step(1.0);
  return sim;
}

TEST(contacts, the_body_moved_over_the_left_foot_loads_the_left_foot) {
  robot_sim sim = leaning_sideways(0.35);
  const double y_com = sim.outputs().com[1];
  const foot_loads f = average_loads(sim, 0.5);
  const double weight = urdf_weight();
  ASSERT_FALSE(sim.outputs().fallen);
  // about sin 0.35 · 0.16 m of leg from ankle to hip, for the body above the hips
  EXPECT_GT(y_com, 0.035);
  EXPECT_NEAR(f.left + f.right, weight, 0.001 * weight);
  const double left_min = weight * (y_com + k_sole_inner) / (k_sole_inner + k_sole_outer);
  EXPECT_GT(left_min, 0.55 * weight);
  EXPECT_GE(f.left, left_min);
  EXPECT_LE(f.right, weight - left_min + 0.001 * weight);
}

TEST(contacts, the_body_moved_over_the_right_foot_loads_the_right_foot) {
  robot_sim sim = leaning_sideways(-0.35);
  const double y_com = sim.outputs().com[1];
  const foot_loads f = average_loads(sim, 0.5);
  const double weight = urdf_weight();
  ASSERT_FALSE(sim.outputs().fallen);
  EXPECT_LT(y_com, -0.035);
  EXPECT_NEAR(f.left + f.right, weight, 0.001 * weight);
  const double right_min = weight * (-y_com + k_sole_inner) / (k_sole_inner + k_sole_outer);
  EXPECT_GT(right_min, 0.55 * weight);
  EXPECT_GE(f.right, right_min);
  EXPECT_LE(f.left, weight - right_min + 0.001 * weight);
}

TEST(contacts, a_steady_sideways_push_is_held_by_floor_friction_in_world_axes) {
  robot_sim sim(darwin::default_config(k_darwin));
  sim.step(0.5);
  sim.set_push(0.0, 3.0);  // towards the robot's left, world +y
  sim.step(1.5);
  const foot_loads f = average_loads(sim, 0.5);
  ASSERT_FALSE(sim.outputs().fallen);
  // at rest the floor's horizontal force cancels the push
  EXPECT_NEAR(f.fy, -3.0, 0.05);
  EXPECT_NEAR(f.fx, 0.0, 0.05);
  // and the push's moment about the floor shifts load onto the left foot
  EXPECT_GT(f.left, f.right);
}

TEST(contacts, the_four_feet_of_a_standing_quadruped_carry_its_weight) {
  robot_sim sim(stride::test::quadruped_config());
  sim.step(2.0);
  ASSERT_EQ(sim.outputs().link_forces.size(), 4u);
  // averaged over a second at rest: the body does not accelerate, so the floor carries the
  // weight, all of it through the feet (the body box is clear of the floor)
  std::array<double, 3> sum{0.0, 0.0, 0.0};
  std::array<double, 4> each{0.0, 0.0, 0.0, 0.0};
  const int n = 125;
  for (int k = 0; k < n; ++k) {
    sim.step(sim.config().physics_step);
    for (std::size_t f = 0; f < 4; ++f) {
      for (std::size_t a = 0; a < 3; ++a) sum[a] += sim.outputs().link_forces[f][a] / n;
      each[f] += sim.outputs().link_forces[f][2] / n;
    }
  }
  const double weight = stride::test::k_quadruped_mass * stride::test::k_gravity;
  // measured: exact to 1e-6
  EXPECT_NEAR(sum[2], weight, 0.001 * weight);
  EXPECT_LT(std::hypot(sum[0], sum[1]), 0.001 * weight);
  // statics by hand: each foot is under its hip (x = ±0.15 m); each leg's thigh and shin
  // (0.5 kg) sit 0.15·sin(0.5)/2 behind it, so the centre of mass is 4·0.5·0.03596/6.2 =
  // 11.6 mm behind the body centre and the hind feet carry more; left and right mirror each
  // other. The band covers the feet's rolling contact points and the settled tilt (measured
  // 0.004 N off)
  const double x_com = -4.0 * 0.5 * 0.5 * 0.15 * std::sin(0.5) / stride::test::k_quadruped_mass;
  const double front = 0.5 * weight * (0.15 + x_com) / 0.3;
  const double hind = 0.5 * weight * (0.15 - x_com) / 0.3;
  EXPECT_NEAR(each[0], front, 0.001 * weight);  // fl
  EXPECT_NEAR(each[1], front, 0.001 * weight);  // fr
  EXPECT_NEAR(each[2], hind, 0.001 * weight);   // hl
  EXPECT_NEAR(each[3], hind, 0.001 * weight);   // hr
}

TEST(contacts, contact_links_report_floor_forces_in_their_order_and_bad_names_are_named) {
  // DARwIn standing: contact links naming the feet (in reverse) and a link in the air
  robot_config c = darwin::default_config(k_darwin);
  c.contact_links = {c.right_foot_link, "head_tilt_link", c.left_foot_link};
  robot_sim sim(c);
  sim.step(1.0);
  const foot_loads f = average_loads(sim, 0.2);
  const auto& o = sim.outputs();
  ASSERT_EQ(o.link_forces.size(), 3u);
  EXPECT_EQ(o.link_forces[1], (std::array<double, 3>{0.0, 0.0, 0.0}));
  EXPECT_GT(f.left, 0.3 * urdf_weight());
  EXPECT_EQ(o.link_forces[0], o.right_foot_force);
  EXPECT_EQ(o.link_forces[2], o.left_foot_force);

  c.contact_links = {"no_such_link"};
  try {
    robot_sim bad(c);
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("robot_config.contact_links: link 'no_such_link'"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
