// What evolves in a plant: the state ODE holds for every body, and the plant's own memory.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace stride::robot {

/// One body as ODE holds it: centre of mass, orientation (w, x, y, z) and velocities, world axes.
struct body_state {
  std::array<double, 3> position{};
  std::array<double, 4> quaternion{};
  std::array<double, 3> linear_velocity{};
  std::array<double, 3> angular_velocity{};
};

/// Everything that evolves and that ODE does not hold.
struct plant_state {
  double time = 0.0;
  double requested_time = 0.0;
  std::int64_t steps = 0;
  std::vector<double> targets;         // by servo ID − 1
  std::vector<double> servo_velocity;  // last velocity command, by model joint
  double push_x = 0.0;
  double push_y = 0.0;
  bool fallen = false;
  // the last physics step's sensor values that need the step itself to be measured
  Eigen::Vector3d acc = Eigen::Vector3d::Zero();
  Eigen::Vector3d left_force = Eigen::Vector3d::Zero();
  Eigen::Vector3d right_force = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> link_forces;  // by robot_config::contact_links entry
  std::vector<double> joint_torques;         // by servo ID − 1
  double max_penetration = 0.0;
};

}  // namespace stride::robot
