// The plant FMU of any URDF robot: its interface comes from the URDF and a plant profile found in
// the FMU's resources/ (docs/plant-profile.md). `stride robot-fmu` and the build's robot.fmu
// write those resources; the FMU binary reads them in fmi2Instantiate.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "stride/sdk/fmu.hpp"

namespace stride::robot {

/// resources/plant.xml: what the generator wrote for the binary to find.
struct plant_manifest {
  std::string model_name;
  std::string model_identifier;
  std::string description;
  std::string urdf = "robot.urdf";        ///< file in resources/
  std::string profile;                    ///< file in resources/, "" = none
  double default_step = 0.008;            ///< s
  std::vector<std::string> package_path;  ///< folders in resources/ for package:// URIs
};

/// Name of the manifest in resources/.
inline constexpr const char* k_plant_manifest = "plant.xml";

std::string write_plant_manifest(const plant_manifest& manifest);
/// Throws sdk::model_error naming the file for anything missing or malformed.
plant_manifest read_plant_manifest(const std::string& path);

/// The FMU definition of the plant whose resources are in `resource_dir`; warnings (defaults
/// the profile had to guess) go to `warnings` when given.
std::shared_ptr<const sdk::fmu_definition> load_plant_fmu(
    const std::string& resource_dir, std::vector<std::string>* warnings = nullptr);

}  // namespace stride::robot
