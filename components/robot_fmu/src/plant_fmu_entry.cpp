// The generated plant FMU's entry point: its interface is read from resources/plant.xml.
#include "stride/robot/plant_fmu.hpp"

namespace {
std::shared_ptr<const stride::sdk::fmu_definition> load(const std::string& resource_dir) {
  return stride::robot::load_plant_fmu(resource_dir);
}
}  // namespace

STRIDE_FMU_FROM_RESOURCES(load)
