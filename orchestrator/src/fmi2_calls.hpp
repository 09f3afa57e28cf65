// The FMI 2.0 value and state calls, written once for the Co-Simulation component (fmu.cpp) and
// the Model Exchange instance (fmi2_me_instance.cpp). `fn` is either one's table of resolved
// functions; `check(function, status)` throws for a status that is not OK or Warning.
#ifndef STRIDE_COSIM_FMI2_CALLS_HPP
#define STRIDE_COSIM_FMI2_CALLS_HPP

#include <cstddef>
#include <span>
#include <vector>

#include "stride/cosim/component.hpp"
#include "stride/fmi2/fmi2_api.h"

namespace stride::cosim::detail {

/// Conversion buffers for Booleans and strings, kept between calls.
struct fmi2_scratch {
  std::vector<fmi2Boolean> booleans;
  std::vector<fmi2String> strings;
};

template <class Functions, class Check>
void fmi2_set_values(const Functions& fn, fmi2Component c, const variable_refs& refs,
                     const value_block& values, fmi2_scratch& scratch, Check&& check) {
  if (!refs.reals.empty()) {
    check("fmi2SetReal",
          fn.fmi2SetReal(c, refs.reals.data(), refs.reals.size(), values.reals.data()));
  }
  if (!refs.integers.empty()) {
    check("fmi2SetInteger",
          fn.fmi2SetInteger(c, refs.integers.data(), refs.integers.size(), values.integers.data()));
  }
  if (!refs.booleans.empty()) {
    scratch.booleans.resize(refs.booleans.size());
    for (std::size_t i = 0; i < scratch.booleans.size(); ++i) {
      scratch.booleans[i] = values.booleans[i] ? fmi2True : fmi2False;
    }
    check("fmi2SetBoolean", fn.fmi2SetBoolean(c, refs.booleans.data(), refs.booleans.size(),
                                              scratch.booleans.data()));
  }
  if (!refs.strings.empty()) {
    scratch.strings.resize(refs.strings.size());
    for (std::size_t i = 0; i < scratch.strings.size(); ++i) {
      scratch.strings[i] = values.strings[i].c_str();
    }
    check("fmi2SetString",
          fn.fmi2SetString(c, refs.strings.data(), refs.strings.size(), scratch.strings.data()));
  }
}

/// Reads `refs` into `values` (resized); the caller decides what a non-finite real means.
template <class Functions, class Check>
void fmi2_get_values(const Functions& fn, fmi2Component c, const variable_refs& refs,
                     value_block& values, fmi2_scratch& scratch, Check&& check) {
  values.resize_for(refs);
  if (!refs.reals.empty()) {
    check("fmi2GetReal",
          fn.fmi2GetReal(c, refs.reals.data(), refs.reals.size(), values.reals.data()));
  }
  if (!refs.integers.empty()) {
    check("fmi2GetInteger",
          fn.fmi2GetInteger(c, refs.integers.data(), refs.integers.size(), values.integers.data()));
  }
  if (!refs.booleans.empty()) {
    scratch.booleans.resize(refs.booleans.size());
    check("fmi2GetBoolean", fn.fmi2GetBoolean(c, refs.booleans.data(), refs.booleans.size(),
                                              scratch.booleans.data()));
    for (std::size_t i = 0; i < scratch.booleans.size(); ++i) {
      values.booleans[i] = scratch.booleans[i] != fmi2False;
    }
  }
  if (!refs.strings.empty()) {
    scratch.strings.resize(refs.strings.size());
    check("fmi2GetString",
          fn.fmi2GetString(c, refs.strings.data(), refs.strings.size(), scratch.strings.data()));
    for (std::size_t i = 0; i < scratch.strings.size(); ++i) {
      values.strings[i] = scratch.strings[i] ? scratch.strings[i] : "";
    }
  }
}

/// The FMU's state, serialized (the FMU state itself is freed on every path).
template <class Functions, class Check>
std::vector<std::byte> fmi2_save_state(const Functions& fn, fmi2Component c, Check&& check) {
  fmi2FMUstate state = nullptr;
  check("fmi2GetFMUstate", fn.fmi2GetFMUstate(c, &state));
  std::vector<std::byte> bytes;
  try {
    size_t size = 0;
    check("fmi2SerializedFMUstateSize", fn.fmi2SerializedFMUstateSize(c, state, &size));
    bytes.resize(size);
    check("fmi2SerializeFMUstate",
          fn.fmi2SerializeFMUstate(c, state, reinterpret_cast<fmi2Byte*>(bytes.data()), size));
  } catch (...) {
    fn.fmi2FreeFMUstate(c, &state);
    throw;
  }
  check("fmi2FreeFMUstate", fn.fmi2FreeFMUstate(c, &state));
  return bytes;
}

template <class Functions, class Check>
void fmi2_restore_state(const Functions& fn, fmi2Component c, std::span<const std::byte> bytes,
                        Check&& check) {
  fmi2FMUstate state = nullptr;
  check("fmi2DeSerializeFMUstate",
        fn.fmi2DeSerializeFMUstate(c, reinterpret_cast<const fmi2Byte*>(bytes.data()), bytes.size(),
                                   &state));
  const fmi2Status set = fn.fmi2SetFMUstate(c, state);
  fn.fmi2FreeFMUstate(c, &state);
  check("fmi2SetFMUstate", set);
}

}  // namespace stride::cosim::detail

#endif  // STRIDE_COSIM_FMI2_CALLS_HPP
