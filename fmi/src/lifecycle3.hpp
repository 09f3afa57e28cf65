// The FMI 3.0 Co-Simulation calling sequence as a table (docs/fmi3-rules.md §2), over the
// lifecycle states the 2.0 glue uses: Step Mode is `step_complete`. Stride FMUs offer neither
// Event Mode nor Configuration Mode, so those states are never entered.
#pragma once

#include <cstdint>
#include <string>

#include "lifecycle.hpp"

namespace stride::sdk::glue {

enum class function3 : std::uint8_t {
  set_debug_logging,
  free_instance,
  enter_initialization_mode,
  exit_initialization_mode,
  terminate,
  reset,
  get_value,
  set_value,
  fmu_state,
  do_step,
  unsupported,  // event mode, clocks, configuration, Model Exchange, derivatives, …
};

/// Allowed states per function.
constexpr std::uint32_t allowed_states3(function3 f) {
  constexpr std::uint32_t alive =
      instantiated | initialization_mode | step_complete | step_failed | terminated | error;
  switch (f) {
    case function3::set_debug_logging:
    case function3::free_instance:
    case function3::reset:
    case function3::fmu_state:
    case function3::unsupported:  // answered with a message saying what is not offered
      return alive;
    case function3::enter_initialization_mode:
      return instantiated;
    case function3::exit_initialization_mode:
      return initialization_mode;
    case function3::terminate:
      return step_complete | step_failed;
    case function3::get_value:
      return initialization_mode | step_complete | step_failed | terminated | error;
    case function3::set_value:
      return instantiated | initialization_mode | step_complete;
    case function3::do_step:
      return step_complete;
  }
  return 0;
}

/// The state's name in the FMI 3.0 standard's words ("Step Mode").
const char* state_name3(std::uint32_t s);

/// "Instantiated, Initialization Mode" — for error messages.
std::string state_list3(std::uint32_t mask);

}  // namespace stride::sdk::glue
