// modelDescription.xml (FMI 2.0 and 3.0) and GUID, generated from a component's definition.
#pragma once

#include <string>

#include "stride/sdk/fmu.hpp"

namespace stride::sdk {

/// A GUID derived from everything that defines the FMU's interface, so the XML generated at
/// build time and the binary always agree, and any interface change yields a new GUID.
std::string compute_guid(const fmu_definition& fmu);

/// The complete FMI 2.0 modelDescription.xml. `generation_time` is an xs:dateTime string or empty.
std::string write_model_description(const fmu_definition& fmu, const std::string& generation_time);

/// The complete FMI 3.0 modelDescription.xml: arrays as one variable with a <Dimension>, the
/// independent variable `time`, the GUID as instantiationToken.
std::string write_model_description3(const fmu_definition& fmu, const std::string& generation_time);

}  // namespace stride::sdk
