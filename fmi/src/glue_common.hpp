// What the FMI 2.0 and FMI 3.0 glue share: loading a definition, the rules for setting a value,
// range checks, the FMU state image. Only the C API around these differs between the standards.
#pragma once

#include <cstddef>
#include <cstring>
#include <exception>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "instance.hpp"

namespace stride::sdk::glue {

/// The definition of the FMU unpacked at `resource_dir` and its GUID (the FMI 3.0
/// instantiationToken), loaded once per folder.
const loaded_fmu& definition_for(const std::string& resource_dir);

/// The standard log categories and the component's own.
std::vector<std::string> known_log_categories(const fmu_definition& fmu);

/// Whether `v` may be set in lifecycle `state` (instantiated and initialization mode: inputs and
/// exact/approx start values; stepping: inputs and tunable parameters). Same rule in 2.0 and 3.0.
bool settable(const variable& v, std::uint32_t state);

/// "'name' (causality, variability)", for messages.
std::string describe(const variable& v);

/// A numeric value against the variable's range and extra check; "" when acceptable.
std::string range_problem(const variable& v, double x);

/// The component threw: the instance is in the error state, the reason logged.
void component_failed(instance& inst, const char* function_name, const std::exception& e);

/// Brings feedthrough outputs up to date before a get; false (logged) when the component threw.
bool refresh_values(instance& inst, const char* function_name);

/// Whether a step ending at `end` computes past the stopTime the importer declared, which FMI
/// 2.0 (§4.2.1) and 3.0 (§2.3.2) answer with an error.
inline bool past_stop_time(const instance& inst, time_ns end) {
  return inst.stop_time && end > *inst.stop_time;
}
/// The message for such a step.
std::string past_stop_message(const instance& inst, time_ns end);

/// Checks and writes one value of `v` (T: double, int, bool or std::string_view) and tells the
/// component; "" on success, otherwise the reason (nothing written). `state_label` names the
/// current state in the standard's words.
template <class T>
std::string store_value(instance& inst, const variable& v, T x, std::string_view state_label);

/// The instance's complete state as bytes: header (magic, GUID, time, lifecycle) + component.
std::vector<std::byte> serialize(instance& inst);
/// "" when `bytes` are a state image of this FMU, otherwise the reason.
std::string state_problem(const instance& inst, const std::byte* bytes, std::size_t size);
/// Puts the instance back into the state of `image` (checked by state_problem before).
/// \throws what the component throws.
void restore(instance& inst, const std::vector<std::byte>& image);
/// The saved state behind a handle the importer passed, or nullptr when it is not one of ours.
saved_state* find_state(instance& inst, void* handle);
/// Get{FMU}State: the current state into `*handle` (a new saved state when it is null, else the
/// one it names); "" on success, otherwise the reason.
std::string take_state(instance& inst, void** handle);
/// Deserialize: a new saved state from `bytes` into `*handle`; "" or the reason.
std::string load_state(instance& inst, const void* bytes, std::size_t size, void** handle);

}  // namespace stride::sdk::glue
