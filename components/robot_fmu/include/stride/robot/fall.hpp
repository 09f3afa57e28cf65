// The plant's fall rule, a pure function of the root link's pose.
#pragma once

#include "stride/robot/robot_config.hpp"
#include "stride/robot/robot_model.hpp"

namespace stride::robot {

/// True when `root` (the root link frame in the world) has fallen by `config`'s rule: its z axis
/// tilted more than fall_tilt from the vertical, or its origin lower than fall_height. Either
/// condition alone is a fall; yaw does not count. robot_sim latches `fallen` on the first
/// physics step for which this holds (floating-base models only).
[[nodiscard]] bool is_fallen(const pose& root, const robot_config& config);

}  // namespace stride::robot
