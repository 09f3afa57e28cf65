// Sensor readings from the ODE bodies and joints.
#include "sensors.hpp"

#include <algorithm>
#include <cmath>

#include "frames.hpp"

namespace stride::robot {

Eigen::Vector3d imu_velocity(const ode_world& world, const sensor_mounts& m) {
  dBodyID b = world.bodies[static_cast<std::size_t>(m.imu_body)];
  const Eigen::Vector3d p = m.imu_in_body.translation() -
                            to_eigen(world.model.bodies[static_cast<std::size_t>(m.imu_body)].com);
  dVector3 v;
  dBodyGetRelPointVel(b, p.x(), p.y(), p.z(), v);
  return vec(v);
}

Eigen::Matrix3d imu_rotation(const ode_world& world, const sensor_mounts& m) {
  return body_rotation(world.bodies[static_cast<std::size_t>(m.imu_body)]) * m.imu_in_body.linear();
}

Eigen::Vector3d specific_force(const Eigen::Matrix3d& imu_rotation, const Eigen::Vector3d& a,
                               double gravity) {
  return imu_rotation.transpose() * (a + Eigen::Vector3d(0, 0, gravity));
}

void read_sensors(const ode_world& world, const sensor_mounts& m, const imu_config& imu,
                  const plant_state& state, robot_outputs& o) {
  const std::size_t servo_n = m.joint_of_servo.size();
  o.time = state.time;
  o.joint_angles.assign(servo_n, 0.0);
  o.joint_velocities.assign(servo_n, 0.0);
  for (std::size_t i = 0; i < servo_n; ++i) {
    if (!std::isnan(m.weld_angle[i])) o.joint_angles[i] = m.weld_angle[i];
    const int j = m.joint_of_servo[i];
    if (j < 0) continue;
    o.joint_angles[i] = world.joint_position(static_cast<std::size_t>(j));
    o.joint_velocities[i] = world.joint_rate(static_cast<std::size_t>(j));
  }
  dBodyID imu_body = world.bodies[static_cast<std::size_t>(m.imu_body)];
  const Eigen::Matrix3d r_imu = imu_rotation(world, m);
  Eigen::Vector3d w = r_imu.transpose() * vec(dBodyGetAngularVel(imu_body));
  w = w.cwiseMax(-imu.gyro_range).cwiseMin(imu.gyro_range);
  o.gyro = {w.x(), w.y(), w.z()};
  const double ar = imu.acc_range;
  const Eigen::Vector3d acc = state.acc.cwiseMax(-ar).cwiseMin(ar);
  o.acc = {acc.x(), acc.y(), acc.z()};

  const Eigen::Matrix3d r = body_rotation(world.bodies[0]);
  const Eigen::Vector3d origin = world.root_origin();
  o.base_position = {origin.x(), origin.y(), origin.z()};
  dVector3 v;
  dBodyGetPointVel(world.bodies[0], origin.x(), origin.y(), origin.z(), v);
  o.base_velocity = {v[0], v[1], v[2]};
  const dReal* omega = dBodyGetAngularVel(world.bodies[0]);
  o.base_angular_velocity = {omega[0], omega[1], omega[2]};
  o.pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  o.roll = std::atan2(r(2, 1), r(2, 2));
  o.yaw = std::atan2(r(1, 0), r(0, 0));

  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  double mass = 0.0;
  for (std::size_t b = 0; b < world.bodies.size(); ++b) {
    c += world.model.bodies[b].mass * vec(dBodyGetPosition(world.bodies[b]));
    mass += world.model.bodies[b].mass;
  }
  c /= mass;
  o.com = {c.x(), c.y(), c.z()};
  o.left_foot_force = {state.left_force.x(), state.left_force.y(), state.left_force.z()};
  o.right_foot_force = {state.right_force.x(), state.right_force.y(), state.right_force.z()};
  o.link_forces.resize(state.link_forces.size());
  for (std::size_t k = 0; k < state.link_forces.size(); ++k) {
    const Eigen::Vector3d& f = state.link_forces[k];
    o.link_forces[k] = {f.x(), f.y(), f.z()};
  }
  o.joint_torques = state.joint_torques;
  o.max_penetration = state.max_penetration;
  o.fallen = state.fallen;
}

}  // namespace stride::robot
