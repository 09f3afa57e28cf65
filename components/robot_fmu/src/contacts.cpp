// Collision of explicit geom pairs, contact joints with the configured surface, floor forces on
// chosen bodies from joint feedback.
#include "contacts.hpp"

#include <algorithm>

namespace stride::robot {

contacts::contacts(const ode_world& world, const contact_config& config,
                   const std::vector<int>& force_bodies)
    : config_(config), measured_(world.bodies.size(), 0) {
  for (int b : force_bodies) {
    if (b >= 0) measured_[static_cast<std::size_t>(b)] = 1;
  }
  const std::vector<geom_entry>& geoms = world.geoms;
  auto connected = [&](int a, int b) {
    for (const model_joint& mj : world.model.joints) {
      if ((mj.parent_body == a && mj.child_body == b) ||
          (mj.parent_body == b && mj.child_body == a)) {
        return true;
      }
    }
    return false;
  };
  if (config.self_collision) {
    for (std::size_t a = 0; a < geoms.size(); ++a) {
      for (std::size_t b = a + 1; b < geoms.size(); ++b) {
        if (geoms[a].body == geoms[b].body || connected(geoms[a].body, geoms[b].body)) continue;
        self_pairs_.push_back({static_cast<int>(a), static_cast<int>(b)});
      }
    }
  }
  for (std::size_t a = 0; a < geoms.size(); ++a) {
    for (std::size_t w = 0; w < world.world_geoms.size(); ++w) {
      if (connected(geoms[a].body, -1)) continue;
      world_pairs_.push_back({static_cast<int>(a), static_cast<int>(w)});
    }
  }
  buffer_.resize(static_cast<std::size_t>(config.max_contacts));
  std::size_t measured_geoms = 0;
  for (const geom_entry& g : geoms) {
    if (g.body >= 0 && measured_[static_cast<std::size_t>(g.body)] != 0) ++measured_geoms;
  }
  feedback_.resize(measured_geoms * static_cast<std::size_t>(config.max_contacts) * 2 + 1);
}

void contacts::add_contacts(ode_world& world, int n, dBodyID b1, dBodyID b2, int measured_body) {
  for (int k = 0; k < n; ++k) {
    dContact& c = buffer_[static_cast<std::size_t>(k)];
    c.surface.mode = dContactApprox1 | dContactSoftERP | dContactSoftCFM;
    if (config_.bounce > 0.0) c.surface.mode |= dContactBounce;
    c.surface.mu = config_.mu;
    c.surface.bounce = config_.bounce;
    c.surface.bounce_vel = config_.bounce_velocity;
    c.surface.soft_erp = config_.soft_erp;
    c.surface.soft_cfm = config_.soft_cfm;
    dJointID id = dJointCreateContact(world.world, world.contact_group, &c);
    dJointAttach(id, b1, b2);
    const std::size_t slot = feedback_owner_.size();
    if (measured_body >= 0 && slot < feedback_.size()) {
      dJointSetFeedback(id, &feedback_[slot]);
      feedback_owner_.push_back({static_cast<int>(slot), measured_body});
    }
  }
}

double contacts::collide(ode_world& world) {
  const int max_c = config_.max_contacts;
  const int stride = static_cast<int>(sizeof(dContact));
  feedback_owner_.clear();
  double max_penetration = 0.0;
  for (const geom_entry& g : world.geoms) {
    const int n = dCollide(g.id, world.floor, max_c, &buffer_[0].geom, stride);
    if (n <= 0) continue;
    for (int k = 0; k < n; ++k) {
      max_penetration = std::max(max_penetration, buffer_[static_cast<std::size_t>(k)].geom.depth);
    }
    const int measured = measured_[static_cast<std::size_t>(g.body)] != 0 ? g.body : -1;
    add_contacts(world, n, world.bodies[static_cast<std::size_t>(g.body)], nullptr, measured);
  }
  // robot pairs are collided only when their bounding boxes overlap
  auto overlap = [](dGeomID a, dGeomID b) {
    dReal aa[6];
    dReal bb[6];
    dGeomGetAABB(a, aa);
    dGeomGetAABB(b, bb);
    return aa[0] <= bb[1] && bb[0] <= aa[1] && aa[2] <= bb[3] && bb[2] <= aa[3] && aa[4] <= bb[5] &&
           bb[4] <= aa[5];
  };
  for (const auto& [a, b] : self_pairs_) {
    const geom_entry& ga = world.geoms[static_cast<std::size_t>(a)];
    const geom_entry& gb = world.geoms[static_cast<std::size_t>(b)];
    if (!overlap(ga.id, gb.id)) continue;
    const int n = dCollide(ga.id, gb.id, max_c, &buffer_[0].geom, stride);
    if (n > 0) {
      add_contacts(world, n, world.bodies[static_cast<std::size_t>(ga.body)],
                   world.bodies[static_cast<std::size_t>(gb.body)], -1);
    }
  }
  for (const auto& [a, w] : world_pairs_) {
    const geom_entry& ga = world.geoms[static_cast<std::size_t>(a)];
    const geom_entry& gw = world.world_geoms[static_cast<std::size_t>(w)];
    if (!overlap(ga.id, gw.id)) continue;
    const int n = dCollide(ga.id, gw.id, max_c, &buffer_[0].geom, stride);
    if (n > 0) add_contacts(world, n, world.bodies[static_cast<std::size_t>(ga.body)], nullptr, -1);
  }
  return max_penetration;
}

std::vector<Eigen::Vector3d> contacts::floor_forces() const {
  std::vector<Eigen::Vector3d> forces(measured_.size(), Eigen::Vector3d::Zero());
  for (const auto& [slot, body] : feedback_owner_) {
    forces[static_cast<std::size_t>(body)] += vec(feedback_[static_cast<std::size_t>(slot)].f1);
  }
  return forces;
}

void contacts::clear(ode_world& world) {
  dJointGroupEmpty(world.contact_group);
  feedback_owner_.clear();
}

}  // namespace stride::robot
