// Servo model applied each physics step: P velocity command with speed and acceleration limits,
// torque-limited ODE motor, viscous damping.
#include "servos.hpp"

#include <algorithm>

namespace stride::robot {

namespace {

// v = p·(target − q), |v| ≤ max_velocity, |v − previous| ≤ max_acceleration·dt
double velocity_command(const servo_config& c, double target, double q, double previous,
                        double dt) {
  double v = c.p_gain * (target - q);
  v = std::clamp(v, -c.max_velocity, c.max_velocity);
  if (c.max_acceleration > 0.0) {
    const double dv = c.max_acceleration * dt;
    v = std::clamp(v, previous - dv, previous + dv);
  }
  return v;
}

}  // namespace

double clamp_target(const servo_config& c, const model_joint& j, double target) {
  if (c.clamp_to_limits && j.limited) return std::clamp(target, j.lower, j.upper);
  return target;
}

void set_up_joint_motors(ode_world& world, const std::vector<servo_config>& servos) {
  // sized once: ODE keeps pointers into it
  world.feedback.assign(world.joints.size(), dJointFeedback{});
  for (std::size_t j = 0; j < world.joints.size(); ++j) {
    dJointSetFeedback(world.joints[j], &world.feedback[j]);
    const model_joint& mj = world.model.joints[j];
    const servo_config& c = servos[j];
    // passive joints: Coulomb friction through a zero-velocity motor
    if (mj.servo_id == 0) {
      world.set_motor(j, 0.0, mj.friction);
    } else if (c.compliance > 0.0) {
      // motor row λ = (v − ω)/CFM: a viscous, back-EMF-like servo instead of a rigid one
      if (mj.type == joint_type::prismatic) {
        dJointSetSliderParam(world.joints[j], dParamCFM, 1.0 / c.compliance);
      } else {
        dJointSetHingeParam(world.joints[j], dParamCFM, 1.0 / c.compliance);
      }
    }
  }
}

void drive_joints(ode_world& world, const std::vector<servo_config>& servos, double dt,
                  const std::vector<double>& targets, std::vector<double>& servo_velocity) {
  for (std::size_t j = 0; j < world.joints.size(); ++j) {
    const model_joint& mj = world.model.joints[j];
    const servo_config& c = servos[j];
    const double rate = world.joint_rate(j);
    if (mj.servo_id > 0) {
      const double target = clamp_target(c, mj, targets[static_cast<std::size_t>(mj.servo_id - 1)]);
      const double v = velocity_command(c, target, world.joint_position(j), servo_velocity[j], dt);
      servo_velocity[j] = v;
      // Webots takes the larger of torque limit and static friction
      world.set_motor(j, v, std::max(c.torque_limit, c.static_friction));
      if (c.damping > 0.0) world.add_joint_effort(j, -c.damping * rate);
    } else if (mj.damping > 0.0) {
      world.add_joint_effort(j, -mj.damping * rate);
    }
  }
}

double motor_effort(const ode_world& world, std::size_t j) {
  const dJointFeedback& fb = world.feedback[j];
  const Eigen::Vector3d force = vec(fb.f1);
  dVector3 axis;
  if (world.model.joints[j].type == joint_type::prismatic) {
    dJointGetSliderAxis(world.joints[j], axis);
    return vec(axis).dot(force);
  }
  // fb.t1 is about the child's centre of mass; the anchor's force adds (anchor − com) × f there.
  // Anchor and axis are those after the step, the forces those of the step: for a turning joint
  // they differ by its turn in one step, nothing at rest
  dVector3 anchor;
  dJointGetHingeAnchor(world.joints[j], anchor);
  dJointGetHingeAxis(world.joints[j], axis);
  const Eigen::Vector3d arm =
      vec(anchor) - vec(dBodyGetPosition(dJointGetBody(world.joints[j], 0)));
  return vec(axis).dot(vec(fb.t1) - arm.cross(force));
}

}  // namespace stride::robot
