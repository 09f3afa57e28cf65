// The FMI 3.0 Co-Simulation functions, written once for every Stride component beside the 2.0
// ones (glue.cpp) and over the same instance, variable table and state image. Every function is
// checked against the lifecycle table (lifecycle3.hpp); Event Mode, clocks, configuration, Model
// Exchange, Scheduled Execution and derivatives are not offered: their functions answer
// fmi3Error with a message saying so (docs/fmi3-rules.md §4).
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "glue3.hpp"

namespace stride::sdk::glue {

void refuse3(instance3& inst, function3 f, const char* name) {
  inst.log.error(std::string(name) + ": illegal call in state " + state_name3(inst.state) +
                 " (allowed in: " + state_list3(allowed_states3(f)) + ")");
}

fmi3Status fail3(instance& inst, const std::string& message) {
  inst.log.error(message);
  return fmi3Error;
}

fmi3Status failed3(instance& inst, const char* function_name, const std::exception& e) {
  component_failed(inst, function_name, e);
  return fmi3Error;
}

fmi3Status not_offered(fmi3Instance i, const char* name, const char* why) {
  instance3* inst = enter3(i, function3::unsupported, name);
  if (inst == nullptr) return fmi3Error;
  return fail3(*inst, std::string(name) + ": not supported (" + why + ")");
}

}  // namespace stride::sdk::glue

using namespace stride::sdk;
using namespace stride::sdk::glue;

namespace {

log_sink fmi3_sink(fmi3LogMessageCallback callback, fmi3InstanceEnvironment environment) {
  if (callback == nullptr) return {};
  return [callback, environment](log_level level, const char* category, const std::string& text) {
    const fmi3Status status = level == log_level::error     ? fmi3Error
                              : level == log_level::warning ? fmi3Warning
                                                            : fmi3OK;
    callback(environment, status, category, text.c_str());
  };
}

// resourcePath is a native path with a trailing separator; the definition cache keys folders
// without it, as the 2.0 glue does.
std::string resource_folder(const char* path) {
  std::string out = path ? path : "";
  while (out.size() > 1 && out.back() == '/') out.pop_back();
  return out;
}

}  // namespace

extern "C" {

const char* fmi3GetVersion(void) {
  return fmi3Version;
}

fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
    fmi3Boolean earlyReturnAllowed, const fmi3ValueReference requiredIntermediateVariables[],
    size_t nRequiredIntermediateVariables, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3IntermediateUpdateCallback intermediateUpdate) {
  (void)visible;
  (void)earlyReturnAllowed;  // steps never return early, allowed or not
  (void)requiredIntermediateVariables;
  (void)intermediateUpdate;
  fmi_logger early(fmi3_sink(logMessage, instanceEnvironment));
  const std::string name = instanceName ? instanceName : "";
  if (name.empty()) {
    early.error("fmi3InstantiateCoSimulation: missing instance name");
    return nullptr;
  }
  if (eventModeUsed) {
    early.error(
        "fmi3InstantiateCoSimulation: eventModeUsed, but the FMU has no Event Mode "
        "(hasEventMode=\"false\")");
    return nullptr;
  }
  if (nRequiredIntermediateVariables > 0) {
    early.error(
        "fmi3InstantiateCoSimulation: intermediate variables requested, but the FMU "
        "provides no intermediate update");
    return nullptr;
  }
  try {
    const std::string resource_dir = resource_folder(resourcePath);
    const loaded_fmu& fmu = definition_for(resource_dir);
    if (instantiationToken == nullptr || fmu.guid != instantiationToken) {
      early.error(std::string("fmi3InstantiateCoSimulation: wrong instantiationToken ") +
                  (instantiationToken ? instantiationToken : "(null)") + ", this binary is " +
                  fmu.guid);
      return nullptr;
    }
    auto inst = std::make_unique<instance3>(fmu, name, resource_dir,
                                            fmi3_sink(logMessage, instanceEnvironment));
    inst->log.enable_all(loggingOn);
    inst->create_component();
    inst->log.info("logEvents", "instantiated (resources: " + inst->context.resource_dir + ")");
    return inst.release();
  } catch (const std::exception& e) {
    early.error(std::string("fmi3InstantiateCoSimulation: ") + e.what());
    return nullptr;
  }
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String, fmi3String, fmi3String, fmi3Boolean,
                                          fmi3Boolean, fmi3InstanceEnvironment environment,
                                          fmi3LogMessageCallback logMessage) {
  fmi_logger(fmi3_sink(logMessage, environment))
      .error("fmi3InstantiateModelExchange: the FMU offers Co-Simulation only");
  return nullptr;
}

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String, fmi3String, fmi3String, fmi3Boolean,
                                               fmi3Boolean, fmi3InstanceEnvironment environment,
                                               fmi3LogMessageCallback logMessage,
                                               fmi3ClockUpdateCallback, fmi3LockPreemptionCallback,
                                               fmi3UnlockPreemptionCallback) {
  fmi_logger(fmi3_sink(logMessage, environment))
      .error("fmi3InstantiateScheduledExecution: the FMU offers Co-Simulation only");
  return nullptr;
}

void fmi3FreeInstance(fmi3Instance i) {
  instance3* inst = enter3(i, function3::free_instance, "fmi3FreeInstance");
  if (inst == nullptr) return;
  for (saved_state* s : inst->saved_states) delete s;
  delete inst;
}

fmi3Status fmi3SetDebugLogging(fmi3Instance i, fmi3Boolean loggingOn, size_t nCategories,
                               const fmi3String categories[]) {
  instance3* inst = enter3(i, function3::set_debug_logging, "fmi3SetDebugLogging");
  if (inst == nullptr) return fmi3Error;
  if (nCategories > 0 && categories == nullptr) {
    return fail3(*inst, "fmi3SetDebugLogging: null categories");
  }
  std::vector<std::string> names;
  for (size_t k = 0; k < nCategories; ++k) {
    if (categories[k] == nullptr) return fail3(*inst, "fmi3SetDebugLogging: null category");
    names.emplace_back(categories[k]);
  }
  const std::string unknown =
      inst->log.set_debug_logging(loggingOn, names, known_log_categories(inst->fmu));
  if (!unknown.empty()) {
    return fail3(*inst, "fmi3SetDebugLogging: unknown log category '" + unknown + "'");
  }
  return fmi3OK;
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance i, fmi3Boolean toleranceDefined,
                                       fmi3Float64 tolerance, fmi3Float64 startTime,
                                       fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
  (void)toleranceDefined;  // no integrator inside that would use it
  (void)tolerance;
  const char* name = "fmi3EnterInitializationMode";
  instance3* inst = enter3(i, function3::enter_initialization_mode, name);
  if (inst == nullptr) return fmi3Error;
  if (!std::isfinite(startTime) || (stopTimeDefined && !(stopTime >= startTime))) {
    return fail3(*inst, std::string(name) + ": invalid start/stop time");
  }
  inst->time = to_time_ns(startTime);
  inst->stop_time.reset();
  if (stopTimeDefined) inst->stop_time = to_time_ns(stopTime);
  try {
    inst->component->enter_initialization();
  } catch (const std::exception& e) {
    return failed3(*inst, name, e);
  }
  inst->state = initialization_mode;
  return fmi3OK;
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance i) {
  instance3* inst = enter3(i, function3::exit_initialization_mode, "fmi3ExitInitializationMode");
  if (inst == nullptr) return fmi3Error;
  try {
    inst->component->exit_initialization();
    inst->values_dirty = false;
  } catch (const std::exception& e) {
    return failed3(*inst, "fmi3ExitInitializationMode", e);
  }
  inst->state = step_complete;  // Step Mode: eventModeUsed is always false
  return fmi3OK;
}

fmi3Status fmi3Terminate(fmi3Instance i) {
  instance3* inst = enter3(i, function3::terminate, "fmi3Terminate");
  if (inst == nullptr) return fmi3Error;
  try {
    inst->component->terminate();
  } catch (const std::exception& e) {
    return failed3(*inst, "fmi3Terminate", e);
  }
  inst->state = terminated;
  return fmi3OK;
}

fmi3Status fmi3Reset(fmi3Instance i) {
  instance3* inst = enter3(i, function3::reset, "fmi3Reset");
  if (inst == nullptr) return fmi3Error;
  try {
    inst->component.reset();
    inst->create_component();
  } catch (const std::exception& e) {
    return failed3(*inst, "fmi3Reset", e);
  }
  inst->state = instantiated;
  inst->time = 0;
  inst->stop_time.reset();
  inst->terminate_requested = false;
  return fmi3OK;
}

fmi3Status fmi3DoStep(fmi3Instance i, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize,
                      fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean* eventHandlingNeeded, fmi3Boolean* terminateSimulation,
                      fmi3Boolean* earlyReturn, fmi3Float64* lastSuccessfulTime) {
  (void)noSetFMUStatePriorToCurrentPoint;
  const char* name = "fmi3DoStep";
  instance3* inst = enter3(i, function3::do_step, name);
  if (inst == nullptr) return fmi3Error;
  if (eventHandlingNeeded == nullptr || terminateSimulation == nullptr || earlyReturn == nullptr ||
      lastSuccessfulTime == nullptr) {
    return fail3(*inst, std::string(name) + ": null out argument");
  }
  if (!std::isfinite(currentCommunicationPoint) || !(communicationStepSize > 0) ||
      !std::isfinite(communicationStepSize)) {
    return fail3(*inst, std::string(name) + ": invalid communication point or step size");
  }
  if (inst->terminate_requested) {
    return fail3(*inst, std::string(name) + ": the component has asked to end the simulation");
  }
  const time_ns t = to_time_ns(currentCommunicationPoint);
  const time_ns h = to_time_ns(communicationStepSize);
  if (past_stop_time(*inst, t + h)) {
    return fail3(*inst, std::string(name) + ": " + past_stop_message(*inst, t + h));
  }
  step_result result;
  try {
    result = inst->component->do_step(t, h);
  } catch (const std::exception& e) {
    return failed3(*inst, name, e);
  }
  inst->time = t + h;
  inst->values_dirty = true;
  *eventHandlingNeeded = fmi3False;
  *earlyReturn = fmi3False;
  *lastSuccessfulTime = to_seconds(inst->time);
  *terminateSimulation = result == step_result::terminate;
  if (*terminateSimulation) {
    inst->terminate_requested = true;
    inst->log.info("logEvents", "the component asks to end the simulation");
  }
  return fmi3OK;
}

}  // extern "C"
