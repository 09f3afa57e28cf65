// Where reset() puts a floating-base robot: feet level, lowest collision point at a clearance.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "stride/robot/robot_model.hpp"

namespace stride::robot {

/// A foot that reset() levels: its body and its link frame's rotation in that body.
struct foot_frame {
  int body = -1;
  Eigen::Matrix3d in_body = Eigen::Matrix3d::Identity();
};

/// Root body pose for joint positions `q` (by model joint): turned so that the mean orientation
/// of the two feet is level (left.body < 0: upright), then placed above the origin so that the
/// lowest collision point of the robot is at height `clearance`.
pose standing_root(const robot_model& model, const std::vector<double>& q, const foot_frame& left,
                   const foot_frame& right, double clearance);

}  // namespace stride::robot
