// Packages the plant FMU of a URDF robot (`stride robot-fmu`): the URDF, its plant profile and
// the files they reference go into resources/, modelDescription.xml is generated from them and
// the binaries come from a built plant FMU (robot.fmu).
#pragma once

#include <string>
#include <vector>

namespace stride::robot {

struct plant_fmu_request {
  std::string urdf;     ///< URDF file
  std::string profile;  ///< plant profile file; "" = defaults, each one reported as guessed
  std::string output;   ///< the .fmu to write (replaced if it exists)
  /// modelName and modelIdentifier; "" = the output's file name without .fmu
  std::string model_name;
  std::string description;  ///< "" = "<name> (URDF) on ODE"
  /// a plant FMU built by Stride whose binaries/ are packaged (robot.fmu)
  std::string binaries_from;
  std::vector<std::string> package_path;  ///< for package:// URIs (plus $ROS_PACKAGE_PATH)
  /// modelDescription's generationDateAndTime; "" = SOURCE_DATE_EPOCH or now
  std::string generation_time;
};

struct plant_fmu_result {
  std::string guid;
  std::size_t variables = 0;
  std::size_t joints = 0;             ///< actuated joints
  std::vector<std::string> warnings;  ///< defaults the profile had to guess
};

/// \throws std::runtime_error (model_error, sdk::model_error) naming the file at fault.
plant_fmu_result write_plant_fmu(const plant_fmu_request& request);

/// `name` made a C identifier (FMI's modelIdentifier names the binary): other characters become
/// '_', a leading digit gets a '_' before it. \throws std::invalid_argument for "".
std::string model_identifier_from(const std::string& name);

}  // namespace stride::robot
