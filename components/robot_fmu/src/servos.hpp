// The position servos of robot_config::servo as ODE joint motors (Webots' RotationalMotor,
// docs/robot-model.md §4.2), and the friction of passive joints.
#pragma once

#include <vector>

#include "ode_world.hpp"
#include "stride/robot/robot_config.hpp"
#include "stride/robot/robot_model.hpp"

namespace stride::robot {

/// `target` clamped into the joint's limits when c.clamp_to_limits.
double clamp_target(const servo_config& c, const model_joint& j, double target);

/// Once after the world is built: passive joints resist with their URDF friction; with
/// c.compliance > 0 the servo motors become viscous.
void set_up_joint_motors(ode_world& world, const servo_config& c);

/// Before every physics step of length dt: each servo motor gets its velocity command from its
/// target (by servo ID − 1); servo_velocity (by model joint) remembers the commands for the
/// acceleration limit. Damping acts on servo joints (c.damping) and passive ones (URDF).
void drive_joints(ode_world& world, const servo_config& c, double dt,
                  const std::vector<double>& targets, std::vector<double>& servo_velocity);

}  // namespace stride::robot
