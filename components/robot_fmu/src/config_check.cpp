// Checks of a robot_config: ranges of numbers and the size of the initial pose.
#include "config_check.hpp"

#include <cmath>
#include <stdexcept>

namespace stride::robot {

void require(bool ok, const std::string& key, const std::string& what) {
  if (!ok) throw std::invalid_argument("robot_config." + key + ": " + what);
}

namespace {

// `key`: where the servo model sits in robot_config ("servo", "joint_servos[<joint>]")
void check_servo(const servo_config& s, const std::string& key) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  auto non_negative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  require(non_negative(s.p_gain), key + ".p_gain", "must be >= 0");
  require(positive(s.max_velocity), key + ".max_velocity", "must be > 0");
  require(non_negative(s.max_acceleration), key + ".max_acceleration", "must be >= 0");
  require(s.torque_limit >= 0.0, key + ".torque_limit", "must be >= 0 (infinity: unlimited)");
  require(non_negative(s.damping), key + ".damping", "must be >= 0");
  require(non_negative(s.compliance), key + ".compliance", "must be >= 0");
  require(non_negative(s.static_friction), key + ".static_friction", "must be >= 0");
}

}  // namespace

void check_config(const robot_config& c) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  auto non_negative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  require(positive(c.physics_step), "physics_step", "must be > 0");
  require(c.quick_step_iterations > 0, "quick_step_iterations", "must be > 0");
  require(non_negative(c.gravity), "gravity", "must be >= 0");
  require(non_negative(c.erp) && c.erp <= 1.0, "erp", "must be in [0, 1]");
  require(non_negative(c.cfm), "cfm", "must be >= 0");
  require(non_negative(c.contact.mu), "contact.mu", "must be >= 0");
  require(non_negative(c.contact.bounce) && c.contact.bounce <= 1.0, "contact.bounce",
          "must be in [0, 1]");
  require(non_negative(c.contact.bounce_velocity), "contact.bounce_velocity", "must be >= 0");
  require(non_negative(c.contact.soft_erp) && c.contact.soft_erp <= 1.0, "contact.soft_erp",
          "must be in [0, 1]");
  require(non_negative(c.contact.soft_cfm), "contact.soft_cfm", "must be >= 0");
  require(c.contact.max_contacts > 0 && c.contact.max_contacts <= 64, "contact.max_contacts",
          "must be in 1..64");
  check_servo(c.servo, "servo");
  for (const auto& [joint, servo] : c.joint_servos) {
    check_servo(servo, "joint_servos[" + joint + "]");
  }
  require(positive(c.mimic_force_limit), "mimic_force_limit", "must be > 0");
  require(positive(c.imu.gyro_range), "imu.gyro_range", "must be > 0");
  require(positive(c.imu.acc_range), "imu.acc_range", "must be > 0");
  require(non_negative(c.fall_tilt), "fall_tilt", "must be >= 0");
  require(std::isfinite(c.fall_height), "fall_height", "must be finite");
  require(std::isfinite(c.reset_clearance), "reset_clearance", "must be finite");
  for (double q : c.initial_pose) require(std::isfinite(q), "initial_pose", "must be finite");
}

void check_initial_pose(const robot_config& c, int servo_count) {
  require(c.initial_pose.empty() || static_cast<int>(c.initial_pose.size()) == servo_count,
          "initial_pose",
          "needs " + std::to_string(servo_count) + " values (one per servo ID of " + c.urdf_path +
              "), got " + std::to_string(c.initial_pose.size()));
}

}  // namespace stride::robot
