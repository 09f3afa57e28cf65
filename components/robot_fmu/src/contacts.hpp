// Contacts of one physics step: robot geoms against the floor, against each other and against
// fixed-base world shapes, collided pair by pair in a fixed order (reproducible runs); the floor
// force on chosen bodies (feet, robot_config::contact_links); the deepest floor penetration.
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
  /// Floor forces are summed for `force_bodies` (body indices; -1 entries are ignored).
  contacts(const ode_world& world, const contact_config& config,
           const std::vector<int>& force_bodies);

  /// Creates this step's contact joints in world.contact_group. Returns the deepest floor
  /// penetration, m (0 without floor contact).
  double collide(ode_world& world);
  /// After the world step: total floor force on each body, by body index, world axes, N; zero for
  /// bodies not in force_bodies.
  [[nodiscard]] std::vector<Eigen::Vector3d> floor_forces() const;
  /// Removes the contact joints.
  void clear(ode_world& world);

 private:
  void add_contacts(ode_world& world, int n, dBodyID b1, dBodyID b2, int measured_body);

  contact_config config_;
  std::vector<char> measured_;                    // by body: its floor force is summed
  std::vector<std::pair<int, int>> self_pairs_;   // indices into world.geoms
  std::vector<std::pair<int, int>> world_pairs_;  // (geom, world geom)
  std::vector<dContact> buffer_;
  std::vector<dJointFeedback> feedback_;             // one per possible measured contact
  std::vector<std::pair<int, int>> feedback_owner_;  // (slot, body) this step
};

}  // namespace stride::robot
