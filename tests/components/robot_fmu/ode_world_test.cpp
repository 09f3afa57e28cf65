// World building (ode_world.cpp): bodies where the model puts them, welded servos, joint stops.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "stride/robot/darwin.hpp"
#include "stride/robot/robot_sim.hpp"

namespace {

namespace darwin = stride::robot::darwin;
using stride::robot::robot_config;
using stride::robot::robot_sim;

const std::string k_data = STRIDE_TEST_DATA_DIR;
const std::string k_darwin = std::string(STRIDE_SOURCE_DIR) + "/models/darwin-op/darwin-op.urdf";

TEST(ode_world, the_bodies_start_in_the_zero_pose_of_the_model) {
  // arm.urdf at q = 0: upper arm mass 1 kg at x = 0.5, hand 0.01 kg at x = 0.5, both at z = 1
  robot_config c;
  c.urdf_path = k_data + "/arm.urdf";
  robot_sim sim(c);
  EXPECT_NEAR(sim.outputs().com[0], 0.5, 1e-12);
  EXPECT_NEAR(sim.outputs().com[1], 0.0, 1e-12);
  EXPECT_NEAR(sim.outputs().com[2], 1.0, 1e-12);
  EXPECT_EQ(sim.outputs().joint_angles, std::vector<double>(3, 0.0));
}

TEST(ode_world, a_dropped_mesh_box_comes_to_rest_at_its_analytic_height) {
  // mesh_box.urdf: 1 kg, its mesh 0.1 m tall once rolled, centre 0.03 m below the link origin;
  // dropped from 5 cm it settles with the link origin at 0.05 + 0.03 m less the contact give
  robot_config c;
  c.urdf_path = k_data + "/mesh_box.urdf";
  c.reset_clearance = 0.05;
  robot_sim sim(c);
  sim.step(3.0);
  const auto& out = sim.outputs();
  // the give: n contacts, each a spring k = soft_erp / (h · soft_cfm) (ODE's ERP/CFM spring
  // equivalence), share m·g: sink = m·g·h·soft_cfm / (n·soft_erp), at most this with n >= 4
  // corners on the floor
  const double sink_max =
      1.0 * c.gravity * c.physics_step * c.contact.soft_cfm / (4 * c.contact.soft_erp);
  EXPECT_LE(out.base_position[2], 0.08);
  EXPECT_GE(out.base_position[2], 0.08 - sink_max);
  // at rest: half a second later it has not moved
  const double z = out.base_position[2];
  sim.step(0.5);
  EXPECT_NEAR(sim.outputs().base_position[2], z, 1e-9);
  // the deepest corner sinks at least as far as the centre and at most as far as one contact
  // carrying the whole weight (k·sink = m·g)
  const double sink_one = 4 * sink_max;
  EXPECT_GE(out.max_penetration, 0.08 - z - 1e-12);
  EXPECT_LE(out.max_penetration, sink_one);
  // so it lies flat within the give across its 0.05 m narrow side (measured: roll 3.3e-4 rad,
  // from the uneven share of ODE's mesh-plane contacts among the corners)
  EXPECT_LE(std::abs(sim.outputs().roll), sink_one / 0.05);
  EXPECT_LE(std::abs(sim.outputs().pitch), sink_one / 0.2);
  EXPECT_NEAR(out.com[2], out.base_position[2], 1e-12);  // the centre of mass is at the origin
}

TEST(ode_world, rigid_servos_are_welded_at_their_initial_angle_within_the_limits) {
  robot_config c;
  c.urdf_path = k_data + "/arm.urdf";
  c.servo.torque_limit = 10.0;
  c.initial_pose = {0.2, 0.0, 0.5};  // the wrist slider stops at 0.1
  c.rigid_servos = {3};
  robot_sim sim(c);
  EXPECT_EQ(sim.servo_count(), 3);
  EXPECT_EQ(sim.model().bodies.size(), 1u);
  EXPECT_EQ(sim.model().joints.size(), 1u);
  EXPECT_NEAR(sim.model().total_mass(), 1.01, 1e-12);
  EXPECT_EQ(sim.outputs().joint_angles[2], 0.1);
  // its target is ignored; the other servo still moves
  const std::vector<double> targets = {0.5, 0.0, 0.0};
  sim.set_joint_targets(targets);
  sim.step(1.0);
  EXPECT_EQ(sim.outputs().joint_angles[2], 0.1);
  EXPECT_EQ(sim.outputs().joint_velocities[2], 0.0);
  EXPECT_NEAR(sim.outputs().joint_angles[0], 0.5, 2e-3);
}

TEST(ode_world, joint_limits_stop_a_joint_whose_target_is_not_clamped) {
  robot_config c;
  c.urdf_path = k_data + "/arm.urdf";
  c.servo.torque_limit = 10.0;
  c.servo.clamp_to_limits = false;
  robot_sim sim(c);
  const std::vector<double> beyond = {3.0, 0.0, 0.5};
  sim.set_joint_targets(beyond);
  sim.step(2.0);
  EXPECT_NEAR(sim.outputs().joint_angles[0], 2.0, 0.02);   // hinge stop
  EXPECT_NEAR(sim.outputs().joint_angles[2], 0.1, 0.005);  // slider stop
}

TEST(ode_world, welding_the_darwin_arms_and_head_keeps_its_mass_and_pose) {
  robot_config all = darwin::default_config(k_darwin);
  all.rigid_servos.clear();
  const robot_sim full(all);
  const robot_sim welded(darwin::default_config(k_darwin));
  EXPECT_EQ(full.model().bodies.size(), 21u);
  EXPECT_EQ(welded.model().bodies.size(), 15u);
  EXPECT_NEAR(welded.model().total_mass(), full.model().total_mass(), 1e-12);
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    EXPECT_NEAR(welded.outputs().com[k], full.outputs().com[k], 1e-12);
    EXPECT_NEAR(welded.outputs().base_position[k], full.outputs().base_position[k], 1e-12);
  }
  EXPECT_EQ(welded.outputs().joint_angles.size(), 20u);
  for (std::size_t i = 0; i < 20; ++i) {
    EXPECT_NEAR(welded.outputs().joint_angles[i], full.outputs().joint_angles[i], 1e-12) << i;
  }
}

}  // namespace
