// The FMI 2.0 Co-Simulation functions, written once for every Stride component. Each function
// checks the calling sequence against the lifecycle table, then dispatches through the
// component's variable table or to its model. Nothing here knows any particular component.
#include <cmath>
#include <cstring>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "glue_common.hpp"
#include "lifecycle.hpp"
#include "start_value.hpp"
#include "stride/fmi2/fmi2_api.h"
#include "stride/sdk/model_description.hpp"

namespace stride::sdk::glue {
namespace {

// Returns the instance when `f` may be called in its current state, otherwise logs and
// returns nullptr (the caller answers fmi2Error; the state does not change).
instance* enter(fmi2Component c, function f, const char* name) {
  auto* inst = static_cast<instance*>(c);
  if (inst == nullptr) return nullptr;
  if ((inst->state & allowed_states(f)) == 0) {
    inst->log.error(std::string(name) + ": illegal call in state " + state_name(inst->state) +
                    " (allowed in: " + state_list(allowed_states(f)) + ")");
    return nullptr;
  }
  if (inst->log.calls_enabled()) inst->log.info("logCalls", name);
  return inst;
}

fmi2Status fail(instance& inst, const std::string& message) {
  inst.log.error(message);
  return fmi2Error;
}

// A component threw: the instance can no longer be trusted.
fmi2Status failed(instance& inst, const char* function_name, const std::exception& e) {
  component_failed(inst, function_name, e);
  return fmi2Error;
}

// Looks up vr as a variable of `type`; logs and returns nullptr otherwise.
const variable* lookup(instance& inst, const char* function_name, fmi2ValueReference vr,
                       value_type type) {
  const variable* v = inst.fmu.table.find(vr);
  if (v == nullptr || v->type != type) {
    inst.log.error(std::string(function_name) + ": no " + std::string(to_string(type)) +
                   " variable has value reference " + std::to_string(vr));
    return nullptr;
  }
  return v;
}

bool null_arguments(instance& inst, const char* function_name, size_t n, const void* a,
                    const void* b) {
  if (n > 0 && (a == nullptr || b == nullptr)) {
    inst.log.error(std::string(function_name) + ": null array argument");
    return true;
  }
  return false;
}

template <class Stored, class FmiValue, class Convert>
fmi2Status get_values(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, FmiValue value[],
                      value_type type, const char* name, Convert convert) {
  instance* inst = enter(c, function::get_value, name);
  if (inst == nullptr || null_arguments(*inst, name, nvr, vr, value)) return fmi2Error;
  if (nvr > 0 && !refresh_values(*inst, name)) return fmi2Error;
  for (size_t i = 0; i < nvr; ++i) {
    const variable* v = lookup(*inst, name, vr[i], type);
    if (v == nullptr) return fmi2Error;
    value[i] = convert(read_value<Stored>(inst->data, v->offset));
  }
  return fmi2OK;
}

// The four fmi2Set* functions; T is the stored type (std::string_view for String). Each value is
// checked (settable in this state, numbers in range) before it is written, and the component
// hears of it through on_set; the first refused value ends the call.
template <class T, class FmiValue>
fmi2Status set_values(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                      const FmiValue value[], function f, value_type type, const char* name) {
  instance* inst = enter(c, f, name);
  if (inst == nullptr || null_arguments(*inst, name, nvr, vr, value)) return fmi2Error;
  for (size_t i = 0; i < nvr; ++i) {
    const variable* v = lookup(*inst, name, vr[i], type);
    if (v == nullptr) return fmi2Error;
    T x;
    if constexpr (std::is_same_v<T, std::string_view>) {
      if (value[i] == nullptr) {
        return fail(*inst, std::string(name) + ": '" + v->name + "': null string");
      }
      x = value[i];
    } else if constexpr (std::is_same_v<T, bool>) {
      x = value[i] != fmi2False;
    } else {
      x = value[i];
    }
    const std::string problem = store_value<T>(*inst, *v, x, state_name(inst->state));
    if (!problem.empty()) return fail(*inst, std::string(name) + ": " + problem);
  }
  return fmi2OK;
}

// "file:///a/b", "file://host/a/b" or "file:/a/b" → "/a/b", with %XX decoded; throws
// std::invalid_argument naming the location when it cannot be read.
std::string path_from_uri(const char* uri) {
  if (uri == nullptr) return {};
  std::string s(uri);
  const auto bad = [&](const std::string& why) {
    return std::invalid_argument("resource location '" + std::string(uri) + "': " + why);
  };
  if (s.rfind("file://", 0) == 0) {
    s = s.substr(7);
    if (!s.empty() && s[0] != '/') {  // an authority part (host) before the path
      const auto slash = s.find('/');
      if (slash == std::string::npos) throw bad("no path after the host");
      s = s.substr(slash);
    }
  } else if (s.rfind("file:", 0) == 0) {
    s = s.substr(5);
  }
  const auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '%') {
      out += s[i];
      continue;
    }
    const int high = i + 1 < s.size() ? hex(s[i + 1]) : -1;
    const int low = i + 2 < s.size() ? hex(s[i + 2]) : -1;
    if (high < 0 || low < 0) throw bad("'" + s.substr(i, 3) + "' is not a percent-encoded byte");
    out += static_cast<char>(high * 16 + low);
    i += 2;
  }
  while (out.size() > 1 && out.back() == '/') out.pop_back();
  return out;
}

// The FMI 2.0 logger takes the message as a printf format: '%' is escaped.
log_sink fmi2_sink(const fmi2CallbackFunctions& functions, const std::string& instance_name) {
  if (functions.logger == nullptr) return {};
  return [callback = functions.logger, environment = functions.componentEnvironment, instance_name](
             log_level level, const char* category, const std::string& message) {
    std::string escaped;
    escaped.reserve(message.size());
    for (char c : message) {
      escaped += c;
      if (c == '%') escaped += '%';
    }
    const fmi2Status status = level == log_level::error     ? fmi2Error
                              : level == log_level::warning ? fmi2Warning
                                                            : fmi2OK;
    callback(environment, instance_name.c_str(), status, category, escaped.c_str());
  };
}

fmi2Status unsupported(fmi2Component c, function f, const char* name, const char* why) {
  instance* inst = enter(c, f, name);
  if (inst == nullptr) return fmi2Error;
  return fail(*inst, std::string(name) + ": not supported (" + why + ")");
}

}  // namespace

}  // namespace stride::sdk::glue

using namespace stride::sdk;
using namespace stride::sdk::glue;

extern "C" {

const char* fmi2GetTypesPlatform(void) {
  return STRIDE_FMI2_TYPES_PLATFORM;
}

const char* fmi2GetVersion(void) {
  return STRIDE_FMI2_VERSION;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions* functions, fmi2Boolean visible,
                              fmi2Boolean loggingOn) {
  (void)visible;
  if (functions == nullptr) return nullptr;
  const std::string name = instanceName ? instanceName : "";
  fmi_logger early(fmi2_sink(*functions, name));
  if (instanceName == nullptr || name.empty()) {
    early.error("fmi2Instantiate: missing instance name");
    return nullptr;
  }
  if (fmuType != fmi2CoSimulation) {
    early.error("fmi2Instantiate: only Co-Simulation is supported");
    return nullptr;
  }
  try {
    const std::string resource_dir = path_from_uri(fmuResourceLocation);
    const loaded_fmu& fmu = definition_for(resource_dir);
    if (fmuGUID == nullptr || fmu.guid != fmuGUID) {
      early.error(std::string("fmi2Instantiate: wrong GUID ") + (fmuGUID ? fmuGUID : "(null)") +
                  ", this binary is " + fmu.guid);
      return nullptr;
    }
    auto inst = std::make_unique<instance>(fmu, name, resource_dir, fmi2_sink(*functions, name));
    inst->log.enable_all(loggingOn != fmi2False);
    inst->create_component();
    inst->log.info("logEvents", "instantiated (resources: " + inst->context.resource_dir + ")");
    return inst.release();
  } catch (const std::exception& e) {
    early.error(std::string("fmi2Instantiate: ") + e.what());
    return nullptr;
  }
}

void fmi2FreeInstance(fmi2Component c) {
  instance* inst = enter(c, function::free_instance, "fmi2FreeInstance");
  if (inst == nullptr) return;
  for (saved_state* s : inst->saved_states) delete s;
  delete inst;
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
  instance* inst = enter(c, function::set_debug_logging, "fmi2SetDebugLogging");
  if (inst == nullptr) return fmi2Error;
  if (nCategories > 0 && categories == nullptr) {
    return fail(*inst, "fmi2SetDebugLogging: null categories");
  }
  std::vector<std::string> names;
  for (size_t i = 0; i < nCategories; ++i) {
    if (categories[i] == nullptr) return fail(*inst, "fmi2SetDebugLogging: null category");
    names.emplace_back(categories[i]);
  }
  const std::string unknown =
      inst->log.set_debug_logging(loggingOn != fmi2False, names, known_log_categories(inst->fmu));
  if (!unknown.empty()) {
    return fail(*inst, "fmi2SetDebugLogging: unknown log category '" + unknown + "'");
  }
  return fmi2OK;
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
  (void)toleranceDefined;
  (void)tolerance;
  instance* inst = enter(c, function::setup_experiment, "fmi2SetupExperiment");
  if (inst == nullptr) return fmi2Error;
  if (!std::isfinite(startTime) || (stopTimeDefined && !(stopTime >= startTime))) {
    return fail(*inst, "fmi2SetupExperiment: invalid start/stop time");
  }
  inst->time = to_time_ns(startTime);
  inst->stop_time.reset();
  if (stopTimeDefined) inst->stop_time = to_time_ns(stopTime);
  return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
  instance* inst = enter(c, function::enter_initialization_mode, "fmi2EnterInitializationMode");
  if (inst == nullptr) return fmi2Error;
  try {
    inst->component->enter_initialization();
  } catch (const std::exception& e) {
    return failed(*inst, "fmi2EnterInitializationMode", e);
  }
  inst->state = initialization_mode;
  return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
  instance* inst = enter(c, function::exit_initialization_mode, "fmi2ExitInitializationMode");
  if (inst == nullptr) return fmi2Error;
  try {
    inst->component->exit_initialization();
    inst->values_dirty = false;
  } catch (const std::exception& e) {
    return failed(*inst, "fmi2ExitInitializationMode", e);
  }
  inst->state = step_complete;
  return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c) {
  instance* inst = enter(c, function::terminate, "fmi2Terminate");
  if (inst == nullptr) return fmi2Error;
  try {
    inst->component->terminate();
  } catch (const std::exception& e) {
    return failed(*inst, "fmi2Terminate", e);
  }
  inst->state = terminated;
  return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c) {
  instance* inst = enter(c, function::reset, "fmi2Reset");
  if (inst == nullptr) return fmi2Error;
  try {
    inst->component.reset();
    inst->create_component();
  } catch (const std::exception& e) {
    return failed(*inst, "fmi2Reset", e);
  }
  inst->state = instantiated;
  inst->time = 0;
  inst->stop_time.reset();
  inst->terminate_requested = false;
  return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[]) {
  return get_values<double>(c, vr, nvr, value, value_type::real, "fmi2GetReal",
                            [](double x) { return x; });
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Integer value[]) {
  return get_values<int>(c, vr, nvr, value, value_type::integer, "fmi2GetInteger",
                         [](int x) { return x; });
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Boolean value[]) {
  return get_values<bool>(c, vr, nvr, value, value_type::boolean, "fmi2GetBoolean",
                          [](bool x) { return x ? fmi2True : fmi2False; });
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[]) {
  instance* inst = enter(c, function::get_value, "fmi2GetString");
  if (inst == nullptr || null_arguments(*inst, "fmi2GetString", nvr, vr, value)) return fmi2Error;
  if (nvr > 0 && !refresh_values(*inst, "fmi2GetString")) return fmi2Error;
  for (size_t i = 0; i < nvr; ++i) {
    const variable* v = lookup(*inst, "fmi2GetString", vr[i], value_type::string);
    if (v == nullptr) return fmi2Error;
    value[i] = string_at(inst->data, v->offset);
  }
  return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[]) {
  return set_values<double>(c, vr, nvr, value, function::set_real, value_type::real, "fmi2SetReal");
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Integer value[]) {
  return set_values<int>(c, vr, nvr, value, function::set_other, value_type::integer,
                         "fmi2SetInteger");
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Boolean value[]) {
  return set_values<bool>(c, vr, nvr, value, function::set_other, value_type::boolean,
                          "fmi2SetBoolean");
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[]) {
  return set_values<std::string_view>(c, vr, nvr, value, function::set_other, value_type::string,
                                      "fmi2SetString");
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
  instance* inst = enter(c, function::fmu_state, "fmi2GetFMUstate");
  if (inst == nullptr) return fmi2Error;
  const std::string problem = take_state(*inst, FMUstate);
  return problem.empty() ? fmi2OK : fail(*inst, "fmi2GetFMUstate: " + problem);
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
  instance* inst = enter(c, function::fmu_state, "fmi2SetFMUstate");
  if (inst == nullptr) return fmi2Error;
  saved_state* s = find_state(*inst, FMUstate);
  if (s == nullptr) return fail(*inst, "fmi2SetFMUstate: unknown FMUstate");
  try {
    restore(*inst, s->bytes);
  } catch (const std::exception& e) {
    return failed(*inst, "fmi2SetFMUstate", e);
  }
  return fmi2OK;
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
  instance* inst = enter(c, function::fmu_state, "fmi2FreeFMUstate");
  if (inst == nullptr) return fmi2Error;
  if (FMUstate == nullptr) return fail(*inst, "fmi2FreeFMUstate: null FMUstate pointer");
  if (*FMUstate == nullptr) return fmi2OK;
  saved_state* s = find_state(*inst, *FMUstate);
  if (s == nullptr) return fail(*inst, "fmi2FreeFMUstate: unknown FMUstate");
  inst->saved_states.erase(s);
  delete s;
  *FMUstate = nullptr;
  return fmi2OK;
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t* size) {
  instance* inst = enter(c, function::fmu_state, "fmi2SerializedFMUstateSize");
  if (inst == nullptr) return fmi2Error;
  saved_state* s = find_state(*inst, FMUstate);
  if (s == nullptr || size == nullptr) {
    return fail(*inst, "fmi2SerializedFMUstateSize: unknown FMUstate or null size");
  }
  *size = s->bytes.size();
  return fmi2OK;
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[],
                                 size_t size) {
  instance* inst = enter(c, function::fmu_state, "fmi2SerializeFMUstate");
  if (inst == nullptr) return fmi2Error;
  saved_state* s = find_state(*inst, FMUstate);
  if (s == nullptr || serializedState == nullptr) {
    return fail(*inst, "fmi2SerializeFMUstate: unknown FMUstate or null buffer");
  }
  if (size != s->bytes.size()) {
    return fail(*inst, "fmi2SerializeFMUstate: buffer of " + std::to_string(size) +
                           " bytes, the state needs " + std::to_string(s->bytes.size()));
  }
  std::memcpy(serializedState, s->bytes.data(), size);
  return fmi2OK;
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate* FMUstate) {
  instance* inst = enter(c, function::fmu_state, "fmi2DeSerializeFMUstate");
  if (inst == nullptr) return fmi2Error;
  const std::string problem = load_state(*inst, serializedState, size, FMUstate);
  return problem.empty() ? fmi2OK : fail(*inst, "fmi2DeSerializeFMUstate: " + problem);
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference[], size_t,
                                        const fmi2ValueReference[], size_t, const fmi2Real[],
                                        fmi2Real[]) {
  return unsupported(c, function::get_directional_derivative, "fmi2GetDirectionalDerivative",
                     "providesDirectionalDerivative is false");
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                       const fmi2Integer[], const fmi2Real[]) {
  return unsupported(c, function::set_real_input_derivatives, "fmi2SetRealInputDerivatives",
                     "canInterpolateInputs is false");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                        const fmi2Integer[], fmi2Real[]) {
  return unsupported(c, function::get_real_output_derivatives, "fmi2GetRealOutputDerivatives",
                     "maxOutputDerivativeOrder is 0");
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
  (void)noSetFMUStatePriorToCurrentPoint;
  instance* inst = enter(c, function::do_step, "fmi2DoStep");
  if (inst == nullptr) return fmi2Error;
  if (!std::isfinite(currentCommunicationPoint) || !(communicationStepSize > 0) ||
      !std::isfinite(communicationStepSize)) {
    return fail(*inst, "fmi2DoStep: invalid communication point or step size");
  }
  const time_ns t = to_time_ns(currentCommunicationPoint);
  const time_ns h = to_time_ns(communicationStepSize);
  if (past_stop_time(*inst, t + h)) {
    return fail(*inst, "fmi2DoStep: " + past_stop_message(*inst, t + h));
  }
  step_result result;
  try {
    result = inst->component->do_step(t, h);
  } catch (const std::exception& e) {
    return failed(*inst, "fmi2DoStep", e);
  }
  inst->time = t + h;
  inst->values_dirty = true;
  if (result == step_result::terminate) {
    inst->terminate_requested = true;
    inst->state = step_failed;
    inst->log.info("logEvents", "the component asks to end the simulation");
    return fmi2Discard;
  }
  return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component c) {
  return unsupported(c, function::cancel_step, "fmi2CancelStep", "steps are synchronous");
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status* value) {
  (void)s;
  instance* inst = enter(c, function::get_status, "fmi2GetStatus");
  if (inst == nullptr) return fmi2Error;
  if (value == nullptr) return fail(*inst, "fmi2GetStatus: null value pointer");
  return fmi2Discard;  // no status kind of this type applies to synchronous steps
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real* value) {
  instance* inst = enter(c, function::get_status, "fmi2GetRealStatus");
  if (inst == nullptr) return fmi2Error;
  if (value == nullptr) return fail(*inst, "fmi2GetRealStatus: null value pointer");
  if (s != fmi2LastSuccessfulTime) return fmi2Discard;
  *value = to_seconds(inst->time);
  return fmi2OK;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer* value) {
  (void)s;
  instance* inst = enter(c, function::get_status, "fmi2GetIntegerStatus");
  if (inst == nullptr) return fmi2Error;
  if (value == nullptr) return fail(*inst, "fmi2GetIntegerStatus: null value pointer");
  return fmi2Discard;
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean* value) {
  instance* inst = enter(c, function::get_status, "fmi2GetBooleanStatus");
  if (inst == nullptr) return fmi2Error;
  if (value == nullptr) return fail(*inst, "fmi2GetBooleanStatus: null value pointer");
  if (s != fmi2Terminated) return fmi2Discard;
  *value = inst->terminate_requested ? fmi2True : fmi2False;
  return fmi2OK;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String* value) {
  (void)s;
  instance* inst = enter(c, function::get_status, "fmi2GetStringStatus");
  if (inst == nullptr) return fmi2Error;
  if (value == nullptr) return fail(*inst, "fmi2GetStringStatus: null value pointer");
  return fmi2Discard;
}

}  // extern "C"
