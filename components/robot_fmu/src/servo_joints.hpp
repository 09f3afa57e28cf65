// Which joints are servos and which servo model each one has: robot_config::servo_joints (servo
// IDs by joint name, instead of the URDF's <servo> tags) and robot_config::joint_servos.
#pragma once

#include <vector>

#include "stride/robot/robot_config.hpp"
#include "stride/robot/robot_model.hpp"

namespace stride::robot {

/// With config.servo_joints set, gives model joint servo_joints[i] servo ID i + 1 and makes every
/// other joint passive; without, leaves the URDF's servo IDs. Throws std::invalid_argument naming
/// the joint for a name that is not a movable joint of the model or is listed twice.
void assign_servo_joints(robot_model& model, const robot_config& config);

/// Throws std::invalid_argument naming the joint if a config.joint_servos entry does not name a
/// servo joint of `model` (after assign_servo_joints).
void check_joint_servos(const robot_model& model, const robot_config& config);

/// The servo model of each joint of `model`, by model joint: the last config.joint_servos entry
/// naming the joint, else config.servo (passive joints too; they do not use it).
std::vector<servo_config> servo_models(const robot_model& model, const robot_config& config);

}  // namespace stride::robot
