// Run-constant configuration of the robot plant (physics, contacts, servos, sensors).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace stride::robot {

enum class physics_solver {
  /// dWorldStep: direct LCP solve; bit-reproducible, stable at large steps (default).
  world_step,
  /// dWorldQuickStep: iterative; faster with many contacts but NOT reproducible (ODE reorders
  /// constraints with a process-global random generator).
  quick_step,
};

/// Robot-floor and robot-robot contact surface (defaults: Webots defaults, docs/robot-model.md
/// §4.3).
struct contact_config {
  /// Coulomb friction coefficient (ODE dContactApprox1: friction scales with the normal force).
  double mu = 1.0;
  double bounce = 0.5;
  /// Minimum incoming velocity for a bounce, m/s.
  double bounce_velocity = 0.01;
  double soft_erp = 0.2;
  double soft_cfm = 0.001;
  /// Contact points kept per geometry pair.
  int max_contacts = 10;
  /// Collisions between bodies of the robot that are not connected by a joint.
  bool self_collision = true;
};

/// Position servo modelled like a Webots RotationalMotor (docs/robot-model.md §4.2): per physics
/// step v = p_gain·(target − q), |v| ≤ max_velocity, |v − v_prev| ≤ max_acceleration·dt,
/// applied as the ODE joint motor velocity with force limit max(torque_limit, static_friction).
/// Linear joints use the same numbers in SI linear units.
struct servo_config {
  double p_gain = 10.0;
  /// rad/s
  double max_velocity = 12.26;
  /// rad/s²; 0 disables the acceleration limit.
  double max_acceleration = 55.0;
  /// N·m
  double torque_limit = 2.5;
  /// Motor compliance as a viscous coefficient, N·m·s/rad: the motor torque is
  /// compliance·(v − ω) instead of whatever holds ω = v (ODE motor CFM = 1/compliance).
  /// 0 = rigid velocity servo (Webots).
  double compliance = 0.0;
  /// N·m·s/rad, applied as an explicit viscous torque.
  double damping = 0.002;
  /// N·m; only matters when torque_limit is smaller (Webots takes the larger of the two).
  double static_friction = 0.025;
  /// Clamp targets into the URDF joint limits (Webots clamps to its soft limits).
  bool clamp_to_limits = true;
};

/// IMU saturation (docs/robot-model.md §1.4: Webots lookup tables of the CM-730 board).
struct imu_config {
  /// Saturation of the gyro, rad/s.
  double gyro_range = 27.925;
  /// Saturation of the accelerometer, m/s².
  double acc_range = 39.24;
};

/// Everything that does not change during a run.
struct robot_config {
  /// URDF file to load (required).
  std::string urdf_path;
  /// Folders searched for package://NAME/... file names in the URDF, before ROS_PACKAGE_PATH:
  /// each the package folder itself (last component NAME) or a folder holding NAME/.
  std::vector<std::string> package_path;
  /// Also search ROS_PACKAGE_PATH (off for a packaged FMU: it finds its files in its resources).
  bool use_ros_package_path = true;
  /// Force (N·m, N for prismatic joints) a <mimic> joint's motor may use to follow its master:
  /// generous, so the follower never gives way before the master's servo does.
  double mimic_force_limit = 1000.0;

  physics_solver solver = physics_solver::world_step;
  /// Fixed internal physics step, s.
  double physics_step = 0.008;
  /// Iterations for physics_solver::quick_step.
  int quick_step_iterations = 20;
  double gravity = 9.81;
  /// World ERP / CFM (Webots WorldInfo defaults).
  double erp = 0.2;
  double cfm = 1e-5;
  contact_config contact;
  /// Servo model of every servo not named in joint_servos.
  servo_config servo;
  imu_config imu;

  /// Servos by URDF joint name: servo ID i + 1 drives joint servo_joints[i]; every movable joint
  /// not listed is passive and the URDF's own <servo id="N"/> tags are ignored. Names must be
  /// movable joints of the URDF, each listed once. Empty = servos from the URDF's <servo> tags.
  std::vector<std::string> servo_joints;
  /// Servo model of named servo joints instead of `servo` (a later entry for the same joint
  /// wins). Names must be servo-driven joints of the URDF.
  std::vector<std::pair<std::string, servo_config>> joint_servos;

  /// Joint targets after reset(), rad (m for prismatic), indexed by servo ID − 1; empty = all 0.
  std::vector<double> initial_pose;
  /// Servo IDs simulated as rigid welds at their initial_pose angle: a performance option (each
  /// removes one body and six rows from ODE's LCP) for servos whose target never changes, e.g.
  /// the DARwIn arms 3..6 and head 19, 20 while walking. Their targets are ignored and their
  /// angles read the weld angle.
  std::vector<int> rigid_servos;
  /// Lowest collision point above the floor after reset(), m.
  double reset_clearance = 0.0;

  /// Link carrying the IMU (gyro, accelerometer); empty = the root link.
  std::string imu_link;
  /// Feet: contact forces are reported for them and reset() levels them on the floor.
  /// Empty = not reported, base placed upright.
  std::string left_foot_link;
  std::string right_foot_link;
  /// Links whose floor force is reported in robot_outputs::link_forces, in this order. A link's
  /// force is that of the rigid body it belongs to (the link and everything welded to it).
  std::vector<std::string> contact_links;

  /// `fallen` latches when the root link's z axis tilts more than this from vertical, rad ...
  double fall_tilt = 0.8;
  /// ... or when the root link origin is lower than this, m.
  double fall_height = 0.18;
};

}  // namespace stride::robot
