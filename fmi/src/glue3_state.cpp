// FMI 3.0 FMU state: the same state image as FMI 2.0 (glue_common.cpp), so an image taken through
// either standard restores through the other.
#include <cstring>
#include <string>

#include "glue3.hpp"

using namespace stride::sdk;
using namespace stride::sdk::glue;

extern "C" {

fmi3Status fmi3GetFMUState(fmi3Instance i, fmi3FMUState* FMUState) {
  instance3* inst = enter3(i, function3::fmu_state, "fmi3GetFMUState");
  if (inst == nullptr) return fmi3Error;
  const std::string problem = take_state(*inst, FMUState);
  return problem.empty() ? fmi3OK : fail3(*inst, "fmi3GetFMUState: " + problem);
}

fmi3Status fmi3SetFMUState(fmi3Instance i, fmi3FMUState FMUState) {
  instance3* inst = enter3(i, function3::fmu_state, "fmi3SetFMUState");
  if (inst == nullptr) return fmi3Error;
  saved_state* s = find_state(*inst, FMUState);
  if (s == nullptr) return fail3(*inst, "fmi3SetFMUState: unknown FMUState");
  try {
    restore(*inst, s->bytes);
  } catch (const std::exception& e) {
    return failed3(*inst, "fmi3SetFMUState", e);
  }
  return fmi3OK;
}

fmi3Status fmi3FreeFMUState(fmi3Instance i, fmi3FMUState* FMUState) {
  instance3* inst = enter3(i, function3::fmu_state, "fmi3FreeFMUState");
  if (inst == nullptr) return fmi3Error;
  if (FMUState == nullptr) return fail3(*inst, "fmi3FreeFMUState: null FMUState pointer");
  if (*FMUState == nullptr) return fmi3OK;
  saved_state* s = find_state(*inst, *FMUState);
  if (s == nullptr) return fail3(*inst, "fmi3FreeFMUState: unknown FMUState");
  inst->saved_states.erase(s);
  delete s;
  *FMUState = nullptr;
  return fmi3OK;
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance i, fmi3FMUState FMUState, size_t* size) {
  instance3* inst = enter3(i, function3::fmu_state, "fmi3SerializedFMUStateSize");
  if (inst == nullptr) return fmi3Error;
  saved_state* s = find_state(*inst, FMUState);
  if (s == nullptr || size == nullptr) {
    return fail3(*inst, "fmi3SerializedFMUStateSize: unknown FMUState or null size");
  }
  *size = s->bytes.size();
  return fmi3OK;
}

fmi3Status fmi3SerializeFMUState(fmi3Instance i, fmi3FMUState FMUState, fmi3Byte serializedState[],
                                 size_t size) {
  instance3* inst = enter3(i, function3::fmu_state, "fmi3SerializeFMUState");
  if (inst == nullptr) return fmi3Error;
  saved_state* s = find_state(*inst, FMUState);
  if (s == nullptr || serializedState == nullptr) {
    return fail3(*inst, "fmi3SerializeFMUState: unknown FMUState or null buffer");
  }
  if (size != s->bytes.size()) {
    return fail3(*inst, "fmi3SerializeFMUState: buffer of " + std::to_string(size) +
                            " bytes, the state needs " + std::to_string(s->bytes.size()));
  }
  std::memcpy(serializedState, s->bytes.data(), size);
  return fmi3OK;
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance i, const fmi3Byte serializedState[], size_t size,
                                   fmi3FMUState* FMUState) {
  instance3* inst = enter3(i, function3::fmu_state, "fmi3DeserializeFMUState");
  if (inst == nullptr) return fmi3Error;
  const std::string problem = load_state(*inst, serializedState, size, FMUState);
  return problem.empty() ? fmi3OK : fail3(*inst, "fmi3DeserializeFMUState: " + problem);
}

}  // extern "C"
