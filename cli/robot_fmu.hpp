// `stride robot-fmu ROBOT.urdf --profile FILE --output ROBOT.fmu`: the plant FMU of any URDF
// (stride/robot/plant_package.hpp, docs/plant-profile.md).
#ifndef STRIDE_CLI_ROBOT_FMU_HPP
#define STRIDE_CLI_ROBOT_FMU_HPP

#include <CLI/CLI.hpp>

#include "stride/robot/plant_package.hpp"

namespace stride::cli {

struct robot_fmu_arguments {
  robot::plant_fmu_request request;
  bool quiet = false;
};

/// Adds the `robot-fmu` subcommand filling `args`.
CLI::App* add_robot_fmu_command(CLI::App& app, robot_fmu_arguments& args);

/// Writes the FMU; returns the exit code.
int robot_fmu(robot_fmu_arguments args);

}  // namespace stride::cli

#endif  // STRIDE_CLI_ROBOT_FMU_HPP
