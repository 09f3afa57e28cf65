// Helpers of the FMI 3.0 glue (glue3.cpp: lifecycle, stepping, state; glue3_values.cpp: the
// typed getters and setters).
#pragma once

#include <exception>
#include <string>

#include "fmi3_variables.hpp"
#include "glue_common.hpp"
#include "lifecycle3.hpp"
#include "stride/fmi3/fmi3_api.h"

namespace stride::sdk::glue {

/// An FMI 3.0 instance: the shared instance plus the table's FMI 3.0 view.
struct instance3 : instance {
  instance3(const loaded_fmu& definition, std::string name, std::string resource_dir, log_sink sink)
      : instance(definition, std::move(name), std::move(resource_dir), std::move(sink)),
        vars(definition.fmu->table) {}
  fmi3_variables vars;
};

/// Logs that `name` may not be called in the instance's state (the cold half of enter3).
void refuse3(instance3& inst, function3 f, const char* name);

/// The instance when `f` may be called in its state; otherwise logs and returns nullptr (the
/// caller answers fmi3Error, the state is unchanged). Inline: every call of the API starts here.
inline instance3* enter3(fmi3Instance i, function3 f, const char* name) {
  auto* inst = static_cast<instance3*>(i);
  if (inst == nullptr) return nullptr;
  if ((inst->state & allowed_states3(f)) == 0) {
    refuse3(*inst, f, name);
    return nullptr;
  }
  if (inst->log.calls_enabled()) inst->log.info("logCalls", name);
  return inst;
}

/// Logs `message` as an error and returns fmi3Error.
fmi3Status fail3(instance& inst, const std::string& message);

/// The component threw: error state, message logged, fmi3Error.
fmi3Status failed3(instance& inst, const char* function_name, const std::exception& e);

/// A function of a feature the FMU does not offer: fmi3Error, logged with `why`.
fmi3Status not_offered(fmi3Instance i, const char* name, const char* why);

}  // namespace stride::sdk::glue
