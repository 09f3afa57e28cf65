// Private helpers: conversions between the plain public frame types and Eigen, joint motion.
#pragma once

#include <Eigen/Geometry>

#include "stride/robot/robot_model.hpp"

namespace stride::robot {

inline Eigen::Vector3d to_eigen(const vec3& v) {
  return {v[0], v[1], v[2]};
}

inline Eigen::Matrix3d to_eigen(const mat3& m) {
  Eigen::Matrix3d r;
  r << m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8];
  return r;
}

inline Eigen::Isometry3d to_eigen(const pose& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = to_eigen(p.rotation);
  t.translation() = to_eigen(p.position);
  return t;
}

inline vec3 to_vec3(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

inline pose to_pose(const Eigen::Isometry3d& t) {
  pose p;
  p.position = to_vec3(t.translation());
  const Eigen::Matrix3d& r = t.linear();
  p.rotation = {r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1), r(2, 2)};
  return p;
}

// child body frame relative to the joint frame at joint position q
inline Eigen::Isometry3d joint_motion(const model_joint& j, double q) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  if (j.type == joint_type::prismatic) {
    t.translation() = q * to_eigen(j.axis);
  } else {
    t.linear() = Eigen::AngleAxisd(q, to_eigen(j.axis)).toRotationMatrix();
  }
  return t;
}

}  // namespace stride::robot
