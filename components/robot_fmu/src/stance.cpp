// The reset stance: levelled feet, lowest point at the clearance.
#include "stance.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "frames.hpp"

namespace stride::robot {

namespace {

// lowest world z of a shape placed at `t`
double lowest_point(const collision_shape& s, const Eigen::Isometry3d& t) {
  const Eigen::Vector3d c = t.translation();
  const Eigen::Matrix3d& r = t.linear();
  switch (s.type) {
    case shape_type::box:
      return c.z() - 0.5 * (std::abs(r(2, 0)) * s.size[0] + std::abs(r(2, 1)) * s.size[1] +
                            std::abs(r(2, 2)) * s.size[2]);
    case shape_type::sphere:
      return c.z() - s.size[0];
    case shape_type::cylinder: {
      const double az = std::abs(r(2, 2));
      return c.z() - 0.5 * az * s.size[1] - s.size[0] * std::sqrt(std::max(0.0, 1.0 - az * az));
    }
    case shape_type::capsule:
      return c.z() - 0.5 * std::abs(r(2, 2)) * s.size[1] - s.size[0];
    case shape_type::mesh: {
      double lowest = std::numeric_limits<double>::infinity();
      const std::vector<double>& v = s.mesh->vertices;
      for (std::size_t k = 0; k + 2 < v.size(); k += 3) {
        lowest = std::min(lowest, r(2, 0) * v[k] + r(2, 1) * v[k + 1] + r(2, 2) * v[k + 2]);
      }
      return c.z() + lowest;
    }
  }
  return c.z();
}

}  // namespace

pose standing_root(const robot_model& model, const std::vector<double>& q, const foot_frame& left,
                   const foot_frame& right, double clearance) {
  Eigen::Isometry3d root = Eigen::Isometry3d::Identity();
  // level the feet: the root orientation undoes the mean foot orientation
  if (left.body >= 0) {
    const auto frames = model.forward_kinematics(pose{}, q);
    const Eigen::Isometry3d l = to_eigen(frames[static_cast<std::size_t>(left.body)]);
    const Eigen::Isometry3d r = to_eigen(frames[static_cast<std::size_t>(right.body)]);
    const Eigen::Quaterniond ql(l.linear() * left.in_body);
    const Eigen::Quaterniond qr(r.linear() * right.in_body);
    root.linear() = ql.slerp(0.5, qr).normalized().toRotationMatrix().transpose();
  }
  // drop the robot so its lowest collision point is at the clearance
  const auto frames = model.forward_kinematics(to_pose(root), q);
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    for (const collision_shape& s : model.bodies[b].shapes) {
      lowest = std::min(lowest, lowest_point(s, to_eigen(frames[b]) * to_eigen(s.origin)));
    }
  }
  if (std::isfinite(lowest)) root.translation().z() = clearance - lowest;
  return to_pose(root);
}

}  // namespace stride::robot
