// The ODE objects of one plant, built from its robot_model: bodies, joints, collision geoms and
// the floor. bodies[b] simulates robot_model::bodies[b], joints[j] robot_model::joints[j].
#pragma once

#include <ode/ode.h>

#include <Eigen/Geometry>
#include <array>
#include <memory>
#include <vector>

#include "plant_state.hpp"
#include "stride/robot/robot_config.hpp"
#include "stride/robot/robot_model.hpp"

namespace stride::robot {

/// ODE's data for the calling thread; every thread that calls ODE needs it once.
void ensure_thread_data();

/// Welds config.rigid_servos into `model` at their initial_pose angles (clamped into the joint
/// limits). Returns the weld angle by servo ID − 1, NaN for the servos not welded.
std::vector<double> weld_rigid_servos(robot_model& model, const robot_config& config);

/// Rotation of a body (of its body frame) in the world.
Eigen::Matrix3d body_rotation(dBodyID b);
Eigen::Vector3d vec(const dReal* v);

/// A collision geometry and the body it moves with (-1: the world).
struct geom_entry {
  dGeomID id;
  int body;
};

/// The world of one plant; owns every ODE object in it.
struct ode_world {
  /// Builds the world with every body in the model's zero pose, root frame at the world origin.
  /// `model` must outlive the world. Throws model_error for mass parameters ODE rejects.
  ode_world(const robot_model& model, const robot_config& config);
  ~ode_world();
  ode_world(const ode_world&) = delete;
  ode_world& operator=(const ode_world&) = delete;

  /// Puts every body at its frame (robot_model::forward_kinematics), at rest.
  void place_bodies(const std::vector<pose>& frames);
  /// Sets every orientation once more to the value ODE holds (see the .cpp file).
  void renormalize();

  [[nodiscard]] double joint_position(std::size_t j) const;
  [[nodiscard]] double joint_rate(std::size_t j) const;
  /// Motor of joint j for the next step: target velocity and the force (torque) it may use.
  void set_motor(std::size_t j, double velocity, double fmax);
  /// Force (torque) on joint j for the next step.
  void add_joint_effort(std::size_t j, double effort);

  /// The root link's origin in the world (bodies[0] is placed at its centre of mass).
  [[nodiscard]] Eigen::Vector3d root_origin() const;
  /// Every body's state; the orientation is the quaternion last set (quat_set).
  [[nodiscard]] std::vector<body_state> body_states() const;
  /// Sets every body's state (as body_states() returned it) with no force or torque pending.
  void set_body_states(const std::vector<body_state>& states);

  const robot_model& model;
  dWorldID world = nullptr;
  /// The contact joints of the current physics step.
  dJointGroupID contact_group = nullptr;
  dThreadingImplementationID threading = nullptr;
  /// The plane z = 0.
  dGeomID floor = nullptr;
  std::vector<dBodyID> bodies;
  /// Last quaternion given to dBodySetQuaternion, by body.
  std::vector<std::array<dReal, 4>> quat_set;
  std::vector<dJointID> joints;
  /// Constraint forces of joints[j] in the last step (attached by set_up_joint_motors).
  std::vector<dJointFeedback> feedback;
  /// Robot geoms in canonical order (body by body, shape by shape).
  std::vector<geom_entry> geoms;
  /// Collision shapes welded to the world (fixed-base models).
  std::vector<geom_entry> world_geoms;
  /// ODE's data of every mesh geom, and the triangles it points into (ODE does not copy them).
  std::vector<dTriMeshDataID> mesh_data;
  std::vector<std::shared_ptr<const triangle_mesh>> meshes;

 private:
  void build(const robot_config& config);
  /// The ODE geom of one shape, in no space and on no body.
  dGeomID make_geom(const collision_shape& s);
  void destroy();
};

}  // namespace stride::robot
