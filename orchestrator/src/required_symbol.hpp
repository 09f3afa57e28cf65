// The check every resolved FMI function goes through, written once: the FMI 2.0 and 3.0 loaders
// and the Model Exchange runner resolve dozens of functions each, and a copy of the message code
// per function (as a macro would make it) bloats the binary for a path taken at most once.
#pragma once

#include <string>

namespace stride::cosim::detail {

/// `address` when it is not null. \throws fmu_import_error "<binary> does not export <name>".
void* required_symbol(void* address, const char* name, const std::string& binary);

}  // namespace stride::cosim::detail
