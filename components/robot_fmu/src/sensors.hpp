// What the plant reports, read from the ODE world: joint encoders, IMU, root pose, centre of
// mass, and the step's contact values kept in the plant state.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "ode_world.hpp"
#include "plant_state.hpp"
#include "stride/robot/robot_config.hpp"
#include "stride/robot/robot_sim.hpp"

namespace stride::robot {

/// Where the sensors sit.
struct sensor_mounts {
  int imu_body = 0;
  Eigen::Isometry3d imu_in_body = Eigen::Isometry3d::Identity();
  /// Model joint of each servo, by servo ID − 1; -1: welded or not in the model.
  std::vector<int> joint_of_servo;
  /// Angle of each welded servo, by servo ID − 1; NaN: not welded.
  std::vector<double> weld_angle;
};

/// World velocity of the IMU's origin.
Eigen::Vector3d imu_velocity(const ode_world& world, const sensor_mounts& m);
/// Orientation of the IMU frame in the world.
Eigen::Matrix3d imu_rotation(const ode_world& world, const sensor_mounts& m);
/// What the accelerometer reads for the IMU's world acceleration `a`: the specific force in the
/// IMU frame, m/s².
Eigen::Vector3d specific_force(const Eigen::Matrix3d& imu_rotation, const Eigen::Vector3d& a,
                               double gravity);

/// Refreshes every field of `out`; gyro and accelerometer saturate at the ranges of `imu`.
void read_sensors(const ode_world& world, const sensor_mounts& m, const imu_config& imu,
                  const plant_state& state, robot_outputs& out);

}  // namespace stride::robot
