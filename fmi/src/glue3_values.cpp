// fmi3Get{Type} and fmi3Set{Type}. Stride components store Float64, Int32, Boolean and String
// values; an array variable travels as all its elements in a row (nValues counts elements). The
// other FMI 3.0 types exist in no Stride FMU, so their functions find no variable.
#include <string>
#include <string_view>
#include <type_traits>

#include "glue3.hpp"
#include "start_value.hpp"

using namespace stride::sdk;
using namespace stride::sdk::glue;

namespace {

// Resolves one value reference of the call; nullptr (logged) when it is no variable of `type`.
const fmi3_variable* lookup3(instance3& inst, const char* name, fmi3ValueReference vr,
                             value_type type, const char* type_name) {
  const fmi3_variable* v = inst.vars.find(vr);
  const bool type_matches =
      v != nullptr && (v->is_time() ? type == value_type::real : v->element(0).type == type);
  if (!type_matches) {
    inst.log.error(std::string(name) + ": no " + type_name + " variable has value reference " +
                   std::to_string(vr));
    return nullptr;
  }
  return v;
}

// The checks every getter and setter starts with; false when the call must end with fmi3Error.
bool arguments_ok(instance3& inst, const char* name, std::size_t nvr, const void* vrs,
                  std::size_t n_values, const void* values) {
  if ((nvr > 0 && vrs == nullptr) || (n_values > 0 && values == nullptr)) {
    inst.log.error(std::string(name) + ": null array argument");
    return false;
  }
  return true;
}

// nValues must be exactly the number of elements the value references name.
bool count_ok(instance3& inst, const char* name, std::size_t needed, std::size_t n_values) {
  if (needed == n_values) return true;
  inst.log.error(std::string(name) + ": nValues is " + std::to_string(n_values) +
                 ", the value references name " + std::to_string(needed) + " values");
  return false;
}

// The number of values the value references name (for the message of a wrong nValues).
std::size_t values_named(instance3& inst, const fmi3ValueReference vrs[], std::size_t nvr) {
  std::size_t n = 0;
  for (std::size_t r = 0; r < nvr; ++r) {
    const fmi3_variable* v = inst.vars.find(vrs[r]);
    n += v != nullptr ? v->count : 1;
  }
  return n;
}

// One pass: the values written before an error is found are allowed, an errored getter's
// outputs are undefined (docs/fmi3-rules.md §1).
template <class Stored, class Fmi>
fmi3Status get3(fmi3Instance i, const fmi3ValueReference vrs[], std::size_t nvr, Fmi values[],
                std::size_t n_values, value_type type, const char* type_name, const char* name) {
  instance3* inst = enter3(i, function3::get_value, name);
  if (inst == nullptr || !arguments_ok(*inst, name, nvr, vrs, n_values, values)) return fmi3Error;
  if (nvr > 0 && !refresh_values(*inst, name)) return fmi3Error;
  std::size_t at = 0, r = 0;
  for (; r < nvr; ++r) {
    const fmi3_variable* v = lookup3(*inst, name, vrs[r], type, type_name);
    if (v == nullptr) return fmi3Error;
    if (at + v->count > n_values) break;
    for (std::size_t k = 0; k < v->count; ++k, ++at) {
      if constexpr (std::is_same_v<Stored, const char*>) {
        values[at] = string_at(inst->data, v->element(k).offset);
      } else if (v->is_time()) {
        values[at] = static_cast<Fmi>(to_seconds(inst->time));
      } else {
        values[at] = static_cast<Fmi>(read_value<Stored>(inst->data, v->element(k).offset));
      }
    }
  }
  if (r == nvr && at == n_values) return fmi3OK;
  count_ok(*inst, name, values_named(*inst, vrs, nvr), n_values);
  return fmi3Error;
}

template <class Stored, class Fmi>
fmi3Status set3(fmi3Instance i, const fmi3ValueReference vrs[], std::size_t nvr, const Fmi values[],
                std::size_t n_values, value_type type, const char* type_name, const char* name) {
  instance3* inst = enter3(i, function3::set_value, name);
  if (inst == nullptr || !arguments_ok(*inst, name, nvr, vrs, n_values, values)) return fmi3Error;
  // sizes first: a call with the wrong nValues changes nothing; the variables of the first few
  // references are kept for the second pass
  constexpr std::size_t k_kept = 8;
  const fmi3_variable* kept[k_kept];
  std::size_t needed = 0;
  for (std::size_t r = 0; r < nvr; ++r) {
    const fmi3_variable* v = lookup3(*inst, name, vrs[r], type, type_name);
    if (v == nullptr) return fmi3Error;
    if (v->is_time()) {
      return fail3(*inst, std::string(name) + ": the independent variable 'time' cannot be set");
    }
    if (r < k_kept) kept[r] = v;
    needed += v->count;
  }
  if (!count_ok(*inst, name, needed, n_values)) return fmi3Error;
  std::size_t at = 0;
  for (std::size_t r = 0; r < nvr; ++r) {
    const fmi3_variable& v = r < k_kept ? *kept[r] : *inst->vars.find(vrs[r]);
    for (std::size_t k = 0; k < v.count; ++k, ++at) {
      Stored x;
      if constexpr (std::is_same_v<Stored, std::string_view>) {
        if (values[at] == nullptr) {
          return fail3(*inst, std::string(name) + ": '" + v.element(k).name + "': null string");
        }
        x = values[at];
      } else {
        x = static_cast<Stored>(values[at]);
      }
      const std::string problem =
          store_value<Stored>(*inst, v.element(k), x, state_name3(inst->state));
      if (!problem.empty()) return fail3(*inst, std::string(name) + ": " + problem);
    }
  }
  return fmi3OK;
}

// A type no Stride component stores: every value reference is unknown.
fmi3Status none_of_type(fmi3Instance i, function3 f, const fmi3ValueReference vrs[],
                        std::size_t nvr, const char* type_name, const char* name) {
  instance3* inst = enter3(i, f, name);
  if (inst == nullptr) return fmi3Error;
  if (nvr == 0) return fmi3OK;
  if (vrs == nullptr) return fail3(*inst, std::string(name) + ": null array argument");
  return fail3(*inst, std::string(name) + ": no " + type_name + " variable has value reference " +
                          std::to_string(vrs[0]));
}

}  // namespace

extern "C" {

fmi3Status fmi3GetFloat64(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Float64 values[], size_t n) {
  return get3<double>(i, vr, nvr, values, n, value_type::real, "Float64", "fmi3GetFloat64");
}
fmi3Status fmi3GetInt32(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                        fmi3Int32 values[], size_t n) {
  return get3<int>(i, vr, nvr, values, n, value_type::integer, "Int32", "fmi3GetInt32");
}
fmi3Status fmi3GetBoolean(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Boolean values[], size_t n) {
  return get3<bool>(i, vr, nvr, values, n, value_type::boolean, "Boolean", "fmi3GetBoolean");
}
fmi3Status fmi3GetString(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                         fmi3String values[], size_t n) {
  return get3<const char*>(i, vr, nvr, values, n, value_type::string, "String", "fmi3GetString");
}

fmi3Status fmi3SetFloat64(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Float64 values[], size_t n) {
  return set3<double>(i, vr, nvr, values, n, value_type::real, "Float64", "fmi3SetFloat64");
}
fmi3Status fmi3SetInt32(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                        const fmi3Int32 values[], size_t n) {
  return set3<int>(i, vr, nvr, values, n, value_type::integer, "Int32", "fmi3SetInt32");
}
fmi3Status fmi3SetBoolean(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Boolean values[], size_t n) {
  return set3<bool>(i, vr, nvr, values, n, value_type::boolean, "Boolean", "fmi3SetBoolean");
}
fmi3Status fmi3SetString(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                         const fmi3String values[], size_t n) {
  return set3<std::string_view>(i, vr, nvr, values, n, value_type::string, "String",
                                "fmi3SetString");
}

// the types no Stride component has
#define STRIDE_FMI3_NO_TYPE(Type)                                                     \
  fmi3Status fmi3Get##Type(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, \
                           fmi3##Type[], size_t) {                                    \
    return none_of_type(i, function3::get_value, vr, nvr, #Type, "fmi3Get" #Type);    \
  }                                                                                   \
  fmi3Status fmi3Set##Type(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, \
                           const fmi3##Type[], size_t) {                              \
    return none_of_type(i, function3::set_value, vr, nvr, #Type, "fmi3Set" #Type);    \
  }
STRIDE_FMI3_NO_TYPE(Float32)
STRIDE_FMI3_NO_TYPE(Int8)
STRIDE_FMI3_NO_TYPE(UInt8)
STRIDE_FMI3_NO_TYPE(Int16)
STRIDE_FMI3_NO_TYPE(UInt16)
STRIDE_FMI3_NO_TYPE(UInt32)
STRIDE_FMI3_NO_TYPE(Int64)
STRIDE_FMI3_NO_TYPE(UInt64)
#undef STRIDE_FMI3_NO_TYPE

fmi3Status fmi3GetBinary(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, size_t[],
                         fmi3Binary[], size_t) {
  return none_of_type(i, function3::get_value, vr, nvr, "Binary", "fmi3GetBinary");
}
fmi3Status fmi3SetBinary(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, const size_t[],
                         const fmi3Binary[], size_t) {
  return none_of_type(i, function3::set_value, vr, nvr, "Binary", "fmi3SetBinary");
}
fmi3Status fmi3GetClock(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, fmi3Clock[]) {
  return none_of_type(i, function3::unsupported, vr, nvr, "Clock", "fmi3GetClock");
}
fmi3Status fmi3SetClock(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                        const fmi3Clock[]) {
  return none_of_type(i, function3::unsupported, vr, nvr, "Clock", "fmi3SetClock");
}

}  // extern "C"
