// The fall rule (models/darwin-op/README.md, "fall detection").
#include "stride/robot/fall.hpp"

#include <algorithm>
#include <cmath>

namespace stride::robot {

bool is_fallen(const pose& root, const robot_config& config) {
  // the world z component of the root's z axis is the cosine of its tilt from the vertical
  const double tilt = std::acos(std::clamp(root.rotation[8], -1.0, 1.0));
  return tilt > config.fall_tilt || root.position[2] < config.fall_height;
}

}  // namespace stride::robot
