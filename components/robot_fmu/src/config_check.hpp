// Checks of a robot_config before a plant is built: every bad setting names its key.
#pragma once

#include <string>

#include "stride/robot/robot_config.hpp"

namespace stride::robot {

/// Throws std::invalid_argument "robot_config.<key>: <what>" unless `ok`.
void require(bool ok, const std::string& key, const std::string& what);

/// Checks the settings that do not depend on the model (ranges of numbers).
void check_config(const robot_config& c);

/// Checks config.initial_pose against the model's servo count.
void check_initial_pose(const robot_config& c, int servo_count);

}  // namespace stride::robot
