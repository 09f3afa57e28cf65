// The FMI 2.0 logger callback's work, shared by the Co-Simulation and Model Exchange runners:
// format the printf-style message and hand it to the instance's log sink.
#pragma once

#include <cstdarg>
#include <string>

#include "stride/cosim/log.hpp"
#include "stride/fmi2/fmi2_api.h"

namespace stride::cosim::detail {

// Never throws: it runs inside a C callback, where an exception must not unwind.
void forward_fmi2_log(const log_sink& sink, const std::string& component, fmi2Status status,
                      fmi2String category, fmi2String message, std::va_list args) noexcept;

}  // namespace stride::cosim::detail
