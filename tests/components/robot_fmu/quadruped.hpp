// The test quadruped (data/quadruped.urdf) driven by joint name, standing on bent knees.
#pragma once

#include <string>

#include "stride/robot/robot_config.hpp"

namespace stride::test {

/// Its total mass by hand from the URDF: body 4 kg, four legs of 0.3 + 0.2 + 0.05 kg.
inline constexpr double k_quadruped_mass = 4.0 + 4.0 * (0.3 + 0.2 + 0.05);

/// Servos by name (hips 1..4, knees 5..8), hips +0.5 rad and knees −1.0 rad: each foot straight
/// under its hip, 0.263 m down. Stiff P servos with ample torque; feet as contact links.
inline robot::robot_config quadruped_config() {
  robot::robot_config c;
  c.urdf_path = std::string(STRIDE_TEST_DATA_DIR) + "/quadruped.urdf";
  c.servo_joints = {"fl_hip",  "fr_hip",  "hl_hip",  "hr_hip",
                    "fl_knee", "fr_knee", "hl_knee", "hr_knee"};
  c.initial_pose = {0.5, 0.5, 0.5, 0.5, -1.0, -1.0, -1.0, -1.0};
  c.servo.p_gain = 20.0;
  c.servo.torque_limit = 10.0;
  c.contact_links = {"fl_foot", "fr_foot", "hl_foot", "hr_foot"};
  return c;
}

}  // namespace stride::test
