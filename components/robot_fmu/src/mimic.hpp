// URDF <mimic> joints: each follows its master, q = multiplier · q_master + offset, through its
// own ODE joint motor (the follower is never a servo).
#pragma once

#include <vector>

#include "ode_world.hpp"

namespace stride::robot {

/// Before every physics step of length dt, after drive_joints: the motor of every mimic joint
/// gets the velocity that carries its master's velocity over and closes the position error,
/// with force limit `force_limit`. `servo_velocity`: this step's servo motor commands by model
/// joint (drive_joints). Reads nothing else but the ODE state, so a restored plant continues
/// bit-identically.
void drive_mimic_joints(ode_world& world, double dt, double force_limit,
                        const std::vector<double>& servo_velocity);

}  // namespace stride::robot
