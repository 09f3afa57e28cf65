// The fall rule (fall.cpp): each condition alone, just past and just inside its threshold, for
// the DARwIn profiles and the authors' protocol; robot_sim applying it to the standing robot.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>

#include "stride/robot/darwin.hpp"
#include "stride/robot/fall.hpp"
#include "stride/robot/robot_sim.hpp"

namespace {

namespace darwin = stride::robot::darwin;
using stride::robot::is_fallen;
using stride::robot::pose;
using stride::robot::robot_config;
using stride::robot::robot_sim;

const std::string k_darwin = std::string(STRIDE_SOURCE_DIR) + "/models/darwin-op/darwin-op.urdf";
constexpr double k_pi = std::numbers::pi;
// a margin far above rounding and far below anything physical
constexpr double k_eps = 1e-6;
// the walk-ready torso height (docs/robot-model.md §5.2): "normal height" for the tilt cases
constexpr double k_standing = 0.317;

// root frame turned by `yaw` about the vertical, then tilted by `tilt` about the horizontal axis
// at `azimuth` from x; a tilt about a horizontal axis moves the z axis by exactly that angle
pose root_at(double height, double tilt, double azimuth = 0.0, double yaw = 0.0) {
  const Eigen::Vector3d axis(std::cos(azimuth), std::sin(azimuth), 0.0);
  const Eigen::Matrix3d r =
      (Eigen::AngleAxisd(tilt, axis) * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()))
          .toRotationMatrix();
  pose p;
  p.position = {0.25, -0.5, height};  // x and y play no part
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) p.rotation[static_cast<std::size_t>(3 * i + k)] = r(i, k);
  }
  return p;
}

TEST(fall, the_darwin_profiles_use_the_documented_thresholds) {
  // models/darwin-op/README.md, "fall detection": tilt > 0.8 rad or torso origin < 0.18 m
  for (auto profile : {darwin::plant_profile::stiff, darwin::plant_profile::webots}) {
    const robot_config c = darwin::default_config("", profile);
    EXPECT_EQ(c.fall_tilt, 0.8) << darwin::to_string(profile);
    EXPECT_EQ(c.fall_height, 0.18) << darwin::to_string(profile);
  }
}

TEST(fall, tilt_alone_past_the_threshold_is_a_fall_in_any_direction) {
  for (auto profile : {darwin::plant_profile::stiff, darwin::plant_profile::webots}) {
    const robot_config c = darwin::default_config("", profile);
    EXPECT_FALSE(is_fallen(root_at(k_standing, 0.0), c));
    // forward, backward, sideways both ways, diagonal; each with and without a yaw
    for (double azimuth : {0.0, 0.5 * k_pi, k_pi, -0.5 * k_pi, 0.75}) {
      for (double yaw : {0.0, 2.0}) {
        EXPECT_TRUE(is_fallen(root_at(k_standing, 0.8 + k_eps, azimuth, yaw), c))
            << azimuth << " " << yaw;
        EXPECT_FALSE(is_fallen(root_at(k_standing, 0.8 - k_eps, azimuth, yaw), c))
            << azimuth << " " << yaw;
      }
    }
    // upside down, high above the floor
    EXPECT_TRUE(is_fallen(root_at(1.0, k_pi), c));
  }
}

TEST(fall, height_alone_under_the_threshold_is_a_fall) {
  for (auto profile : {darwin::plant_profile::stiff, darwin::plant_profile::webots}) {
    const robot_config c = darwin::default_config("", profile);
    EXPECT_TRUE(is_fallen(root_at(0.18 - k_eps, 0.0), c));
    EXPECT_FALSE(is_fallen(root_at(0.18 + k_eps, 0.0), c));
    // a tilt just inside its threshold does not change that
    EXPECT_TRUE(is_fallen(root_at(0.18 - k_eps, 0.8 - k_eps), c));
    EXPECT_FALSE(is_fallen(root_at(0.18 + k_eps, 0.8 - k_eps), c));
    EXPECT_TRUE(is_fallen(root_at(-0.1, 0.0), c));
  }
}

TEST(fall, yaw_alone_is_never_a_fall) {
  const robot_config c = darwin::default_config("");
  for (double yaw : {0.5, -1.5, k_pi})
    EXPECT_FALSE(is_fallen(root_at(k_standing, 0.0, 0.0, yaw), c));
}

TEST(fall, the_authors_protocol_falls_on_height_alone_at_0_15_m) {
  // docs/learner.md, "Protocols": a fall is the torso below 0.15 m with no tilt rule
  // (robot.fall_height 0.15, robot.fall_tilt 3.2 > pi)
  robot_config c = darwin::default_config("", darwin::plant_profile::webots);
  c.fall_height = 0.15;
  c.fall_tilt = 3.2;
  EXPECT_TRUE(is_fallen(root_at(0.15 - k_eps, 0.0), c));
  EXPECT_FALSE(is_fallen(root_at(0.15 + k_eps, 0.0), c));
  // between the two height thresholds: a fall for the profiles, not for the authors' rule
  EXPECT_TRUE(is_fallen(root_at(0.16, 0.0), darwin::default_config("")));
  EXPECT_FALSE(is_fallen(root_at(0.16, 0.0), c));
  // no tilt counts, not even upside down
  EXPECT_FALSE(is_fallen(root_at(k_standing, 0.5 * k_pi), c));
  EXPECT_FALSE(is_fallen(root_at(k_standing, k_pi), c));
}

// the standing DARwIn after one physics step, with the given thresholds
bool falls_standing(double fall_tilt, double fall_height) {
  robot_config c = darwin::default_config(k_darwin);
  c.fall_tilt = fall_tilt;
  c.fall_height = fall_height;
  robot_sim sim(c);
  sim.step(c.physics_step);
  return sim.outputs().fallen;
}

TEST(fall, the_plant_applies_the_height_condition_alone_to_its_torso_origin) {
  // the torso origin stands at 0.317 m (docs/robot-model.md §5.2); tilt rule off (3.2 > pi)
  EXPECT_TRUE(falls_standing(3.2, 0.33));
  EXPECT_FALSE(falls_standing(3.2, 0.30));
}

TEST(fall, the_plant_applies_the_tilt_condition_alone_to_its_torso_lean) {
  // the torso leans 12.94 deg = 0.226 rad in the walk-ready pose (docs/robot-model.md §5.2);
  // height rule off
  EXPECT_TRUE(falls_standing(0.20, -1.0));
  EXPECT_FALSE(falls_standing(0.25, -1.0));
}

}  // namespace
