// DARwIn-OP profile: servo conventions, reference poses and the default plant configuration.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "stride/robot/robot_config.hpp"

namespace stride::robot::darwin {

inline constexpr int k_servo_count = 20;

/// Servo count → joint angle in the URDF/Webots convention: (count − 2048)·0.088·π/180 rad.
double servo_count_to_rad(double count);
/// Inverse of servo_count_to_rad (not rounded).
double rad_to_servo_count(double rad);

/// ROBOTIS motion page 9 ("walkready") by servo ID − 1, servo counts
/// (docs/robot-model.md §5.1).
inline constexpr std::array<int, k_servo_count> k_walk_ready_counts = {
    1498, 2518, 1845, 2248, 2381, 1712, 2048, 2048, 2052, 2044,
    1637, 2459, 2653, 1443, 2389, 1707, 2057, 2039, 2048, 2161};

/// Page 9 in rad, by servo ID − 1.
std::array<double, k_servo_count> walk_ready_pose();

/// docs/robot-model.md §5.2: torso origin height and forward lean in the walk-ready pose.
inline constexpr double k_walk_ready_torso_height = 0.317;
inline constexpr double k_walk_ready_lean_deg = 12.94;

/// CM-730 gyro counts per rad/s: 512 counts for 27.925 rad/s (Webots' lookup table).
inline constexpr double k_gyro_counts_per_rad_s = 512.0 / 27.925;

/// The gyro as the CM-730 board reads it, counts minus the 512 centre, not yet made integer.
struct gyro_counts {
  /// front/back: gyro[1] − 512, what the gait's balance loop reads as FB
  double fb = 0.0;
  /// right/left: gyro[0] − 512, what it reads as RL
  double rl = 0.0;
};

/// Board reading of `gyro` (robot_outputs::gyro, rad/s in the IMU frame). The board is mounted
/// rotated 180° about z (docs/robot-model.md §1.4): rl = −k·ω_x, fb = −k·ω_y,
/// k = k_gyro_counts_per_rad_s.
gyro_counts board_gyro(const std::array<double, 3>& gyro);

/// The integer the board reports for a count minus the centre: Webots truncates the raw value
/// 512 + x towards zero, i.e. floor(x) on the board's range.
int board_integer(double counts_minus_centre);

/// Physics step of the DARwIn profiles, s: Webots' basicTimeStep in the DARwIn-OP worlds.
inline constexpr double k_physics_step = 0.016;

/// Named plant settings of the DARwIn-OP; they differ only in the servo response
/// (models/darwin-op/README.md, "Plant profiles").
enum class plant_profile {
  /// servo P = 18 1/s without an acceleration ramp: follows the gait closely (the default)
  stiff,
  /// Webots' own servo: P = 10 1/s with a 55 rad/s² ramp, as in the study's simulator
  webots,
};

/// "stiff" or "webots"; nullopt for any other name.
std::optional<plant_profile> parse_plant_profile(std::string_view name);
std::string_view to_string(plant_profile profile);

/// The plant configuration of the DARwIn-OP (models/darwin-op/README.md): Webots' world and
/// contact settings, walk-ready start pose, IMU/feet links of models/darwin-op/darwin-op.urdf,
/// physics_step = k_physics_step, rigid_servos = {3, 4, 5, 6, 19, 20} (arms and head welded in
/// the walk-ready pose; clear it to drive all 20 servos) and the servo of `profile`.
robot_config default_config(const std::string& urdf_path,
                            plant_profile profile = plant_profile::stiff);

}  // namespace stride::robot::darwin
