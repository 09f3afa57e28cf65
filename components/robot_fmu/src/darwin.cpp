// DARwIn-OP profile (docs/robot-model.md §1.4, §4, §5).
#include "stride/robot/darwin.hpp"

#include <cmath>

namespace stride::robot::darwin {

namespace {
constexpr double k_rad_per_count = 0.088 * 3.14159265358979323846 / 180.0;
}

double servo_count_to_rad(double count) {
  return (count - 2048.0) * k_rad_per_count;
}

double rad_to_servo_count(double rad) {
  return 2048.0 + rad / k_rad_per_count;
}

gyro_counts board_gyro(const std::array<double, 3>& gyro) {
  return {-k_gyro_counts_per_rad_s * gyro[1], -k_gyro_counts_per_rad_s * gyro[0]};
}

int board_integer(double counts_minus_centre) {
  return static_cast<int>(std::floor(counts_minus_centre));
}

std::array<double, k_servo_count> walk_ready_pose() {
  std::array<double, k_servo_count> q{};
  for (std::size_t i = 0; i < q.size(); ++i) q[i] = servo_count_to_rad(k_walk_ready_counts[i]);
  return q;
}

std::optional<plant_profile> parse_plant_profile(std::string_view name) {
  if (name == "stiff") return plant_profile::stiff;
  if (name == "webots") return plant_profile::webots;
  return std::nullopt;
}

std::string_view to_string(plant_profile profile) {
  return profile == plant_profile::webots ? "webots" : "stiff";
}

robot_config default_config(const std::string& urdf_path, plant_profile profile) {
  robot_config c;
  c.urdf_path = urdf_path;
  const auto pose = walk_ready_pose();
  c.initial_pose.assign(pose.begin(), pose.end());
  // servo response: robot_config's defaults are Webots' servo (P = 10 with a 55 rad/s² ramp);
  // the stiff profile follows the gait more closely (P = 18, no ramp), measured in
  // models/darwin-op/README.md (servo stiffness)
  if (profile == plant_profile::stiff) {
    c.servo.p_gain = 18.0;
    c.servo.max_acceleration = 0.0;
  }
  // arms (3..6) and head (19, 20) hold constant targets while walking: welding them halves the
  // cost of a physics step
  c.rigid_servos = {3, 4, 5, 6, 19, 20};
  // Webots' basicTimeStep for the DARwIn-OP worlds the study used: the gait ticks twice per
  // physics step and the plant sees the second target, as in Webots (models/darwin-op/README.md)
  c.physics_step = k_physics_step;
  c.imu_link = "imu_link";
  c.left_foot_link = "l_ank_roll_link";
  c.right_foot_link = "r_ank_roll_link";
  return c;
}

}  // namespace stride::robot::darwin
