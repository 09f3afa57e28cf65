// The robot plant: a URDF robot on a floor plane, simulated with ODE.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "stride/robot/robot_config.hpp"
#include "stride/robot/robot_model.hpp"

namespace stride::robot {

/// Everything the plant reports; refreshed by reset(), step() and restore_state().
/// "Root" is the URDF root link of a floating-base model; for a fixed-base model (root link named
/// "world") it is the first body after the world, and `fallen` stays false.
struct robot_outputs {
  /// Simulated time, s (a whole number of physics steps since reset()).
  double time = 0.0;
  /// Joint positions by servo ID − 1, rad (m for prismatic); IDs without a joint read 0.
  std::vector<double> joint_angles;
  std::vector<double> joint_velocities;
  /// Torque the joint's motor applied to the joint's child body about the joint axis in the last
  /// physics step, by servo ID − 1, N·m (N along the axis for prismatic); positive drives the
  /// joint position up. Includes the joint-limit stops' reaction, not servo_config::damping.
  /// IDs without a joint and welded servos (rigid_servos) read 0.
  std::vector<double> joint_torques;
  /// Angular velocity of the IMU link in its own frame (x forward, y left, z up), rad/s,
  /// saturated at imu_config::gyro_range (darwin::board_gyro converts it to CM-730 counts).
  std::array<double, 3> gyro{0.0, 0.0, 0.0};
  /// Specific force (acceleration minus gravity) at the IMU in the IMU frame, m/s²; reads
  /// (0, 0, +9.81) for an upright robot at rest.
  std::array<double, 3> acc{0.0, 0.0, 0.0};
  /// Root link origin in the world, m, and its orientation as roll/pitch/yaw
  /// (R = Rz(yaw)·Ry(pitch)·Rx(roll)), rad; pitch > 0 leans forward.
  std::array<double, 3> base_position{0.0, 0.0, 0.0};
  double roll = 0.0;
  double pitch = 0.0;
  double yaw = 0.0;
  /// Velocity of the root link origin and angular velocity of the root link, world axes, m/s and
  /// rad/s.
  std::array<double, 3> base_velocity{0.0, 0.0, 0.0};
  std::array<double, 3> base_angular_velocity{0.0, 0.0, 0.0};
  /// Whole-body centre of mass in the world, m.
  std::array<double, 3> com{0.0, 0.0, 0.0};
  /// Total floor force on each foot in world axes during the last physics step, N
  /// (z = normal force).
  std::array<double, 3> left_foot_force{0.0, 0.0, 0.0};
  std::array<double, 3> right_foot_force{0.0, 0.0, 0.0};
  /// Total floor force on each of robot_config::contact_links (same order), world axes, N.
  std::vector<std::array<double, 3>> link_forces;
  /// Deepest floor penetration of any collision shape in the last physics step, m.
  double max_penetration = 0.0;
  /// Latched until reset(): tilt beyond fall_tilt or root link below fall_height (is_fallen).
  bool fallen = false;
};

/// A robot (from robot_config::urdf_path) on an infinite floor plane z = 0.
///
/// Each instance owns its own ODE world and threading implementation, so instances may be
/// stepped concurrently from different threads (one instance per thread). With
/// physics_solver::world_step identical inputs give bit-identical outputs, in any thread.
class robot_sim {
 public:
  /// Loads the URDF and builds the world; the robot is then in the reset() state.
  /// Throws model_error for model problems and std::invalid_argument for bad settings.
  explicit robot_sim(robot_config config);
  ~robot_sim();
  robot_sim(const robot_sim&) = delete;
  robot_sim& operator=(const robot_sim&) = delete;
  robot_sim(robot_sim&&) noexcept;
  robot_sim& operator=(robot_sim&&) noexcept;

  [[nodiscard]] const robot_config& config() const;
  [[nodiscard]] const robot_model& model() const;
  /// Number of entries of joint target / angle vectors (the largest servo ID).
  [[nodiscard]] int servo_count() const;

  /// Places the robot in config().initial_pose at the origin: feet levelled and touching the
  /// floor, all velocities zero, targets = initial pose, push off, time 0, fallen cleared.
  void reset();

  /// Joint targets by servo ID − 1 (size servo_count()), rad. Held until changed.
  void set_joint_targets(std::span<const double> targets);
  /// Horizontal force on the root body's centre of mass, world axes, N. Held until changed.
  void set_push(double fx, double fy);

  /// Advances by h seconds in fixed physics steps. The plant keeps the requested time and runs
  /// every physics step that ends at or before it (1e-9·step tolerance); the remainder is carried
  /// over, so physics time never lags requested time by a full step and never runs ahead.
  /// Throws std::runtime_error if the simulation produces non-finite values.
  void step(double h);

  [[nodiscard]] const robot_outputs& outputs() const;

  /// Complete dynamic state (bodies, servo memory, targets, push, time) as bytes.
  [[nodiscard]] std::vector<std::uint8_t> save_state() const;
  /// Restores a save_state() image of a plant built from the same model and config; the
  /// continuation is bit-identical to the one from the saved moment. Throws std::invalid_argument
  /// for an image of another model or a damaged image.
  void restore_state(std::span<const std::uint8_t> image);

 private:
  struct impl;
  std::unique_ptr<impl> impl_;
};

}  // namespace stride::robot
