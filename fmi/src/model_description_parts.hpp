// Parts of modelDescription.xml written alike for FMI 2.0 and FMI 3.0.
#pragma once

#include <set>
#include <sstream>
#include <string>

#include "stride/sdk/fmu.hpp"

namespace stride::sdk {

/// %.17g: a double written so that it reads back exactly.
std::string xml_number(double x);
/// <UnitDefinitions> with one <Unit> per name; nothing when `units` is empty.
void write_unit_definitions(std::ostringstream& xml, const std::set<std::string>& units);
/// <LogCategories>: the standard categories of the glue and the component's own.
void write_log_categories(std::ostringstream& xml, const model_info& info);
/// <DefaultExperiment> from the component's info.
void write_default_experiment(std::ostringstream& xml, const model_info& info);

}  // namespace stride::sdk
