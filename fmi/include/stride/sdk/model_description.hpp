// modelDescription.xml and GUID, generated from a component's definition.
#pragma once

#include <string>

#include "stride/sdk/fmu.hpp"

namespace stride::sdk {

/// A GUID derived from everything that defines the FMU's interface, so the XML generated at
/// build time and the binary always agree, and any interface change yields a new GUID.
std::string compute_guid(const fmu_definition& fmu);

/// The complete modelDescription.xml. `generation_time` is an xs:dateTime string or empty.
std::string write_model_description(const fmu_definition& fmu, const std::string& generation_time);

}  // namespace stride::sdk
