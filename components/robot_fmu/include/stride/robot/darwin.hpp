// DARwIn-OP profile: servo conventions, reference poses and the default plant configuration.
#pragma once

#include <array>
#include <string>

#include "stride/robot/robot_config.hpp"

namespace stride::robot::darwin {

inline constexpr int k_servo_count = 20;

/// Servo count → joint angle in the URDF/Webots convention: (count − 2048)·0.088·π/180 rad.
double servo_count_to_rad(double count);
/// Inverse of servo_count_to_rad (not rounded).
double rad_to_servo_count(double rad);

/// ROBOTIS motion page 9 ("walkready") by servo ID − 1, servo counts (fact sheet 5.1).
inline constexpr std::array<int, k_servo_count> k_walk_ready_counts = {
    1498, 2518, 1845, 2248, 2381, 1712, 2048, 2048, 2052, 2044,
    1637, 2459, 2653, 1443, 2389, 1707, 2057, 2039, 2048, 2161};

/// Page 9 in rad, by servo ID − 1.
std::array<double, k_servo_count> walk_ready_pose();

/// Fact sheet 5.2: torso origin height and forward lean in the walk-ready pose.
inline constexpr double k_walk_ready_torso_height = 0.317;
inline constexpr double k_walk_ready_lean_deg = 12.94;

/// Servo P gain of the DARwIn profile, 1/s (Webots: 10; see models/darwin-op/README.md).
inline constexpr double k_servo_p_gain = 18.0;

/// Physics step of the DARwIn profile, s: Webots' basicTimeStep in the DARwIn-OP worlds.
inline constexpr double k_physics_step = 0.016;

/// The plant configuration used by the framework for the DARwIn-OP (models/darwin-op/README.md):
/// fact-sheet physics and contacts, walk-ready start pose, IMU/feet links of
/// models/darwin-op/darwin-op.urdf. Departures from the robot_config defaults: physics_step =
/// k_physics_step, servo p_gain = k_servo_p_gain with no acceleration limit, and rigid_servos =
/// {3, 4, 5, 6, 19, 20} (arms and head welded in the walk-ready pose; clear it to drive all 20
/// servos).
robot_config default_config(const std::string& urdf_path);

}  // namespace stride::robot::darwin
