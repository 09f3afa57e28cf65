// The follower's motor is a stiff velocity servo: the master's velocity fed forward plus a position
// correction that halves the error every physics step (a gain of 1/dt would remove it in one step
// but overshoots when the master accelerates during the step).
#include "mimic.hpp"

namespace stride::robot {

namespace {

constexpr double k_error_fraction_per_step = 0.5;

}  // namespace

void drive_mimic_joints(ode_world& world, double dt, double force_limit,
                        const std::vector<double>& servo_velocity) {
  for (std::size_t j = 0; j < world.joints.size(); ++j) {
    const model_joint& mj = world.model.joints[j];
    if (mj.mimic_joint < 0) continue;
    const auto master = static_cast<std::size_t>(mj.mimic_joint);
    const double target = mj.mimic_multiplier * world.joint_position(master) + mj.mimic_offset;
    // a servo master ends the step at its motor command unless its torque limit holds it back;
    // its rate now would lag by one step of its acceleration
    const double master_v =
        world.model.joints[master].servo_id > 0 ? servo_velocity[master] : world.joint_rate(master);
    const double v = mj.mimic_multiplier * master_v +
                     k_error_fraction_per_step * (target - world.joint_position(j)) / dt;
    world.set_motor(j, v, force_limit);
  }
}

}  // namespace stride::robot
