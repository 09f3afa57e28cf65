// Configuration checks (config_check.cpp): every out-of-range setting names its key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "stride/robot/robot_sim.hpp"

namespace {

using stride::robot::robot_config;
using stride::robot::robot_sim;

const std::string k_data = STRIDE_TEST_DATA_DIR;
constexpr double k_nan = std::numeric_limits<double>::quiet_NaN();
constexpr double k_inf = std::numeric_limits<double>::infinity();

robot_config arm() {
  robot_config c;
  c.urdf_path = k_data + "/arm.urdf";
  return c;
}

// the message of the std::invalid_argument thrown by building a plant with `change` applied
std::string error_of(const std::function<void(robot_config&)>& change) {
  robot_config c = arm();
  change(c);
  try {
    robot_sim sim(c);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "<accepted>";
}

TEST(config_check, every_out_of_range_setting_names_its_key) {
  const struct {
    const char* key;
    std::function<void(robot_config&)> change;
  } cases[] = {
      {"physics_step", [](robot_config& c) { c.physics_step = 0.0; }},
      {"physics_step", [](robot_config& c) { c.physics_step = k_nan; }},
      {"quick_step_iterations", [](robot_config& c) { c.quick_step_iterations = 0; }},
      {"gravity", [](robot_config& c) { c.gravity = -9.81; }},
      {"erp", [](robot_config& c) { c.erp = 1.5; }},
      {"cfm", [](robot_config& c) { c.cfm = -1e-5; }},
      {"contact.mu", [](robot_config& c) { c.contact.mu = k_inf; }},
      {"contact.bounce", [](robot_config& c) { c.contact.bounce = 2.0; }},
      {"contact.bounce_velocity", [](robot_config& c) { c.contact.bounce_velocity = -1.0; }},
      {"contact.soft_erp", [](robot_config& c) { c.contact.soft_erp = -0.1; }},
      {"contact.soft_cfm", [](robot_config& c) { c.contact.soft_cfm = k_nan; }},
      {"contact.max_contacts", [](robot_config& c) { c.contact.max_contacts = 0; }},
      {"contact.max_contacts", [](robot_config& c) { c.contact.max_contacts = 65; }},
      {"servo.p_gain", [](robot_config& c) { c.servo.p_gain = -1.0; }},
      {"servo.max_velocity", [](robot_config& c) { c.servo.max_velocity = 0.0; }},
      {"servo.max_acceleration", [](robot_config& c) { c.servo.max_acceleration = -1.0; }},
      {"servo.torque_limit", [](robot_config& c) { c.servo.torque_limit = -1.0; }},
      {"servo.damping", [](robot_config& c) { c.servo.damping = -1.0; }},
      {"servo.compliance", [](robot_config& c) { c.servo.compliance = k_nan; }},
      {"servo.static_friction", [](robot_config& c) { c.servo.static_friction = -1.0; }},
      {"mimic_force_limit", [](robot_config& c) { c.mimic_force_limit = 0.0; }},
      {"mimic_force_limit", [](robot_config& c) { c.mimic_force_limit = k_nan; }},
      {"imu.gyro_range", [](robot_config& c) { c.imu.gyro_range = 0.0; }},
      {"imu.acc_range", [](robot_config& c) { c.imu.acc_range = -1.0; }},
      {"fall_tilt", [](robot_config& c) { c.fall_tilt = -0.1; }},
      {"fall_height", [](robot_config& c) { c.fall_height = k_inf; }},
      {"reset_clearance", [](robot_config& c) { c.reset_clearance = k_nan; }},
      {"initial_pose",
       [](robot_config& c) {
         c.initial_pose = {0.0, k_nan, 0.0};
       }},
  };
  for (const auto& t : cases) {
    EXPECT_THAT(error_of(t.change),
                testing::StartsWith("robot_config." + std::string(t.key) + ": "))
        << t.key;
  }
}

TEST(config_check, limits_themselves_are_accepted) {
  EXPECT_EQ(error_of([](robot_config& c) {
              c.servo.torque_limit = 0.0;
              c.servo.max_acceleration = 0.0;
              c.gravity = 0.0;
              c.erp = 1.0;
              c.contact.bounce = 0.0;
              c.contact.max_contacts = 64;
            }),
            "<accepted>");
}

TEST(config_check, the_initial_pose_needs_one_value_per_servo_id) {
  EXPECT_EQ(error_of([](robot_config& c) {
              c.initial_pose = {0.1, 0.2};
            }),
            "robot_config.initial_pose: needs 3 values (one per servo ID of " + k_data +
                "/arm.urdf), got 2");
  EXPECT_EQ(error_of([](robot_config& c) { c.initial_pose = {0.1, 0.0, 0.05}; }), "<accepted>");
}

}  // namespace
