// State images (state_image.cpp): a bit-exact round trip, and damaged images rejected without
// touching the plant.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "stride/robot/darwin.hpp"
#include "stride/robot/robot_sim.hpp"

namespace {

namespace darwin = stride::robot::darwin;
using stride::robot::robot_config;
using stride::robot::robot_sim;
using testing::HasSubstr;

const std::string k_data = STRIDE_TEST_DATA_DIR;
const std::string k_darwin = std::string(STRIDE_SOURCE_DIR) + "/models/darwin-op/darwin-op.urdf";

// a few steps with moving targets and a push, so that every part of the state is non-trivial
void move(robot_sim& sim, int steps) {
  std::vector<double> targets(sim.config().initial_pose);
  for (int k = 0; k < steps; ++k) {
    for (std::size_t i = 0; i < targets.size(); ++i) {
      targets[i] = sim.config().initial_pose[i] + 0.05 * std::sin(0.1 * k + static_cast<double>(i));
    }
    sim.set_joint_targets(targets);
    sim.set_push(k < 10 ? 2.0 : 0.0, 0.5);
    sim.step(0.008);
  }
}

// the message of the std::invalid_argument thrown by restoring `image`
std::string rejection(robot_sim& sim, const std::vector<std::uint8_t>& image) {
  try {
    sim.restore_state(image);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "<accepted>";
}

TEST(state_image, an_image_round_trips_bit_exactly) {
  robot_sim a(darwin::default_config(k_darwin));
  move(a, 60);
  const std::vector<std::uint8_t> image = a.save_state();
  robot_sim b(darwin::default_config(k_darwin));
  b.restore_state(image);
  EXPECT_EQ(b.save_state(), image);
  EXPECT_EQ(b.outputs().time, a.outputs().time);
  EXPECT_EQ(b.outputs().joint_angles, a.outputs().joint_angles);
  EXPECT_EQ(b.outputs().gyro, a.outputs().gyro);
  EXPECT_EQ(b.outputs().acc, a.outputs().acc);
  EXPECT_EQ(b.outputs().left_foot_force, a.outputs().left_foot_force);
  EXPECT_EQ(b.outputs().max_penetration, a.outputs().max_penetration);
  move(a, 40);
  move(b, 40);
  EXPECT_EQ(b.save_state(), a.save_state());
}

TEST(state_image, joint_torques_and_link_forces_round_trip) {
  robot_config c = darwin::default_config(k_darwin);
  c.contact_links = {c.left_foot_link, c.right_foot_link};
  robot_sim a(c);
  move(a, 60);
  robot_sim b(c);
  b.restore_state(a.save_state());
  // both non-trivial, so that the comparison means something
  ASSERT_NE(a.outputs().joint_torques[10], 0.0);
  ASSERT_NE(a.outputs().link_forces[0][2], 0.0);
  EXPECT_EQ(b.outputs().joint_torques, a.outputs().joint_torques);
  EXPECT_EQ(b.outputs().link_forces, a.outputs().link_forces);
  move(a, 20);
  move(b, 20);
  EXPECT_EQ(b.outputs().joint_torques, a.outputs().joint_torques);
  EXPECT_EQ(b.outputs().link_forces, a.outputs().link_forces);
  // an image without the contact links is of another layout
  robot_sim plain(darwin::default_config(k_darwin));
  EXPECT_THAT(rejection(plain, a.save_state()), HasSubstr("saved from a different model"));
}

TEST(state_image, a_mesh_plant_continues_bit_identically_after_a_restore) {
  // mesh_box.urdf dropped from 5 cm: the mesh bounces and settles on the floor
  robot_config c;
  c.urdf_path = k_data + "/mesh_box.urdf";
  c.reset_clearance = 0.05;
  robot_sim a(c);
  a.step(0.1);  // in flight ...
  const std::vector<std::uint8_t> image = a.save_state();
  a.step(0.5);  // ... then the impact, the bounces and the contacts at rest
  robot_sim b(c);
  b.step(0.3);  // a different history, overwritten by the image
  b.restore_state(image);
  b.step(0.5);
  EXPECT_EQ(b.save_state(), a.save_state());
  EXPECT_EQ(b.outputs().base_position, a.outputs().base_position);
  EXPECT_EQ(b.outputs().max_penetration, a.outputs().max_penetration);
  EXPECT_GT(a.outputs().max_penetration, 0.0);  // the mesh does touch the floor
}

TEST(state_image, a_damaged_image_is_rejected_and_the_plant_is_untouched) {
  robot_sim sim(darwin::default_config(k_darwin));
  move(sim, 20);
  const std::vector<std::uint8_t> good = sim.save_state();
  move(sim, 5);
  const std::vector<std::uint8_t> before = sim.save_state();

  std::vector<std::uint8_t> magic = good;
  magic[0] ^= 0xff;
  EXPECT_THAT(rejection(sim, magic), HasSubstr("not a robot_sim state"));
  std::vector<std::uint8_t> version = good;
  version[8] += 1;  // the u32 after the 8-byte magic
  EXPECT_THAT(rejection(sim, version), HasSubstr("wrong version"));
  std::vector<std::uint8_t> layout = good;
  layout[12] += 1;  // body count
  EXPECT_THAT(rejection(sim, layout), HasSubstr("different model than " + k_darwin));
  const std::vector<std::uint8_t> truncated(good.begin(), good.end() - 1);
  EXPECT_THAT(rejection(sim, truncated), HasSubstr("truncated"));
  EXPECT_THAT(rejection(sim, {}), HasSubstr("truncated"));
  std::vector<std::uint8_t> trailing = good;
  trailing.push_back(0);
  EXPECT_THAT(rejection(sim, trailing), HasSubstr("trailing bytes"));
  EXPECT_EQ(sim.save_state(), before);

  // an image of the same model without welded arms and head has more bodies
  robot_config all_servos = darwin::default_config(k_darwin);
  all_servos.rigid_servos.clear();
  robot_sim other(all_servos);
  EXPECT_THAT(rejection(sim, other.save_state()), HasSubstr("different model"));
  EXPECT_EQ(sim.save_state(), before);
  // the good image still restores
  sim.restore_state(good);
  EXPECT_EQ(sim.save_state(), good);
}

}  // namespace
