// The reset stance (stance.cpp): soles level on the floor, the clearance, no feet: upright.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
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

Eigen::Matrix3d rotation(const stride::robot::mat3& m) {
  Eigen::Matrix3d r;
  r << m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8];
  return r;
}

struct sole {
  Eigen::Vector3d normal;  // the foot link's z axis in the world
  double lowest = 0.0;     // lowest corner of the foot box, world z
};

// where the foot `link` is after reset, from the outputs and the model's forward kinematics
sole sole_of(const robot_sim& sim, const std::string& link) {
  const auto& o = sim.outputs();
  const auto& model = sim.model();
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
  const auto& lf = model.links[static_cast<std::size_t>(model.find_link(link))];
  const auto& body_frame = frames[static_cast<std::size_t>(lf.body)];
  const Eigen::Matrix3d rb = rotation(body_frame.rotation);
  const Eigen::Vector3d pb(body_frame.position[0], body_frame.position[1], body_frame.position[2]);
  sole s;
  s.normal = rb * rotation(lf.in_body.rotation) * Eigen::Vector3d::UnitZ();
  s.lowest = std::numeric_limits<double>::infinity();
  const auto& box = model.bodies[static_cast<std::size_t>(lf.body)].shapes.front();
  const Eigen::Matrix3d rs = rotation(box.origin.rotation);
  const Eigen::Vector3d ps(box.origin.position[0], box.origin.position[1], box.origin.position[2]);
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d local(((corner & 1) ? 0.5 : -0.5) * box.size[0],
                                ((corner & 2) ? 0.5 : -0.5) * box.size[1],
                                ((corner & 4) ? 0.5 : -0.5) * box.size[2]);
    s.lowest = std::min(s.lowest, (rb * (rs * local + ps) + pb).z());
  }
  return s;
}

TEST(stance, reset_puts_both_soles_level_on_the_floor) {
  robot_sim sim(darwin::default_config(k_darwin));
  for (const char* foot : {"l_ank_roll_link", "r_ank_roll_link"}) {
    const sole s = sole_of(sim, foot);
    // the two feet differ by the small ankle and hip roll of the pose: their mean is level
    EXPECT_GT(s.normal.z(), std::cos(0.01)) << foot;
    EXPECT_NEAR(s.lowest, 0.0, 1e-9) << foot;
  }
  EXPECT_NEAR(sim.outputs().base_position[0], 0.0, 1e-12);
  EXPECT_NEAR(sim.outputs().base_position[1], 0.0, 1e-12);
}

TEST(stance, the_clearance_lifts_the_robot_without_turning_it) {
  robot_config c = darwin::default_config(k_darwin);
  robot_sim on_floor(c);
  c.reset_clearance = 0.05;
  robot_sim lifted(c);
  EXPECT_NEAR(lifted.outputs().base_position[2] - on_floor.outputs().base_position[2], 0.05, 1e-12);
  EXPECT_EQ(lifted.outputs().pitch, on_floor.outputs().pitch);
  EXPECT_EQ(lifted.outputs().roll, on_floor.outputs().roll);
}

TEST(stance, without_feet_the_base_stands_upright) {
  robot_config c = darwin::default_config(k_darwin);
  c.left_foot_link.clear();
  c.right_foot_link.clear();
  robot_sim sim(c);
  EXPECT_EQ(sim.outputs().pitch, 0.0);
  EXPECT_EQ(sim.outputs().roll, 0.0);
  EXPECT_EQ(sim.outputs().yaw, 0.0);
  // the feet now lean back by the torso's walk-ready lean and touch with a heel edge only
  const sole s = sole_of(sim, "l_ank_roll_link");
  EXPECT_NEAR(std::acos(s.normal.z()), darwin::k_walk_ready_lean_deg * std::numbers::pi / 180.0,
              0.01);
  EXPECT_NEAR(s.lowest, 0.0, 1e-9);
}

TEST(stance, a_mesh_rests_on_its_lowest_vertex) {
  // mesh_box.urdf: the mesh's 0.1 m side is vertical (rolled 90 deg), its centre 0.03 m below
  // the link origin: lowest vertex on the floor puts the origin at 0.05 + 0.03 m
  robot_config c;
  c.urdf_path = k_data + "/mesh_box.urdf";
  robot_sim sim(c);
  EXPECT_NEAR(sim.outputs().base_position[2], 0.08, 1e-12);
  c.reset_clearance = 0.02;
  robot_sim lifted(c);
  EXPECT_NEAR(lifted.outputs().base_position[2], 0.10, 1e-12);
}

}  // namespace
