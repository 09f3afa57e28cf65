// robot_sim::save_state images: a header naming the plant's layout, every body's state, then
// the plant's own memory. Doubles are stored as their bytes, so a restore is bit-exact.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "plant_state.hpp"

namespace stride::robot {

/// The content of one image.
struct plant_snapshot {
  std::vector<body_state> bodies;
  plant_state plant;
};

/// Image of `s`; its layout counts are s.bodies, s.plant.servo_velocity (one per joint),
/// s.plant.targets and s.plant.joint_torques (one per servo) and s.plant.link_forces.
std::vector<std::uint8_t> encode_state_image(const plant_snapshot& s);

/// Reads an image of a plant with this many bodies, joints, servos and contact links. Throws
/// std::invalid_argument for an image that is not a plant state, of another version, of another
/// layout (the message names `source`, the plant's model), truncated or with trailing bytes.
plant_snapshot decode_state_image(std::span<const std::uint8_t> image, std::size_t bodies,
                                  std::size_t joints, std::size_t servos, std::size_t contact_links,
                                  const std::string& source);

}  // namespace stride::robot
