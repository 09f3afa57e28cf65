// Contacts of one physics step: robot geoms against the floor, against each other and against
// fixed-base world shapes, collided pair by pair in a fixed order (reproducible runs); the floor
// force on each foot; the deepest floor penetration.
#pragma once

#include <ode/ode.h>

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "ode_world.hpp"
#include "stride/robot/robot_config.hpp"

namespace stride::robot {

class contacts {
 public:
  /// Collision pairs of `world`: every robot geom with the floor; with config.self_collision,
  /// geoms of bodies not joined by a joint; world shapes with bodies not jointed to the world.
  /// Floor forces are summed for the two foot bodies (-1: none).
  contacts(const ode_world& world, const contact_config& config, int left_foot_body,
           int right_foot_body);

  /// Creates this step's contact joints in world.contact_group. Returns the deepest floor
  /// penetration, m (0 without floor contact).
  double collide(ode_world& world);
  /// After the world step: total floor force on each foot (left, right), world axes, N.
  [[nodiscard]] std::pair<Eigen::Vector3d, Eigen::Vector3d> foot_forces() const;
  /// Removes the contact joints.
  void clear(ode_world& world);

 private:
  void add_contacts(ode_world& world, int n, dBodyID b1, dBodyID b2, int foot);

  contact_config config_;
  int left_foot_body_ = -1;
  int right_foot_body_ = -1;
  std::vector<std::pair<int, int>> self_pairs_;   // indices into world.geoms
  std::vector<std::pair<int, int>> world_pairs_;  // (geom, world geom)
  std::vector<dContact> buffer_;
  std::vector<dJointFeedback> feedback_;             // one per possible foot contact
  std::vector<std::pair<int, int>> feedback_owner_;  // (slot, foot: 0 left, 1 right) this step
};

}  // namespace stride::robot
