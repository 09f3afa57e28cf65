// The position servos of robot_config::servo (or joint_servos) as ODE joint motors (Webots'
// RotationalMotor, docs/robot-model.md §4.2), the friction of passive joints, and the torque
// each motor applied.
#pragma once

#include <vector>

#include "ode_world.hpp"
#include "stride/robot/robot_config.hpp"
#include "stride/robot/robot_model.hpp"

namespace stride::robot {

/// `target` clamped into the joint's limits when c.clamp_to_limits.
double clamp_target(const servo_config& c, const model_joint& j, double target);

/// Once after the world is built, with the servo model of each joint (by model joint): passive
/// joints resist with their URDF friction; servos with compliance > 0 become viscous; every
/// joint reports its constraint forces into world.feedback.
void set_up_joint_motors(ode_world& world, const std::vector<servo_config>& servos);

/// Before every physics step of length dt: each servo motor gets its velocity command from its
/// target (by servo ID − 1) and its servo model (by model joint); servo_velocity (by model joint)
/// remembers the commands for the acceleration limit. Damping acts on servo joints (their
/// servo model's) and passive ones (URDF).
void drive_joints(ode_world& world, const std::vector<servo_config>& servos, double dt,
                  const std::vector<double>& targets, std::vector<double>& servo_velocity);

/// After a physics step: what joint j's constraint applied to its child body along the joint
/// axis, N·m about the axis through the anchor (N for prismatic joints). The other constraint
/// rows of a hinge or slider act across the axis, so this is the motor plus the limit stops.
double motor_effort(const ode_world& world, std::size_t j);

}  // namespace stride::robot
