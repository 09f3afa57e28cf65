// The FMI 2.0 Co-Simulation calling-sequence state machine, written once as a table: for each
// API function, the set of instance states in which it may be called.
#pragma once

#include <cstdint>
#include <string>

namespace stride::sdk::glue {

enum state : std::uint32_t {
  instantiated = 1u << 0,
  initialization_mode = 1u << 1,
  step_complete = 1u << 2,
  step_in_progress = 1u << 3,  // asynchronous stepping only; never entered by Stride FMUs
  step_failed = 1u << 4,
  step_canceled = 1u << 5,
  terminated = 1u << 6,
  error = 1u << 7,
  fatal = 1u << 8,
};

enum class function : std::uint8_t {
  set_debug_logging,
  free_instance,
  setup_experiment,
  enter_initialization_mode,
  exit_initialization_mode,
  terminate,
  reset,
  get_value,  // fmi2GetReal/Integer/Boolean/String
  set_real,
  set_other,  // fmi2SetInteger/Boolean/String
  fmu_state,  // fmi2Get/Set/FreeFMUstate, (de)serialisation
  get_directional_derivative,
  set_real_input_derivatives,
  get_real_output_derivatives,
  do_step,
  cancel_step,
  get_status,  // fmi2Get*Status
};

/// Allowed states per function (FMI 2.0 specification, co-simulation state machine).
constexpr std::uint32_t allowed_states(function f) {
  constexpr std::uint32_t any_but_fatal = instantiated | initialization_mode | step_complete |
                                          step_in_progress | step_failed | step_canceled |
                                          terminated | error;
  constexpr std::uint32_t alive = instantiated | initialization_mode | step_complete | step_failed |
                                  step_canceled | terminated | error;
  constexpr std::uint32_t readable =
      initialization_mode | step_complete | step_failed | step_canceled | terminated | error;
  switch (f) {
    case function::set_debug_logging:
      return any_but_fatal;
    case function::free_instance:
      return alive;
    case function::setup_experiment:
      return instantiated;
    case function::enter_initialization_mode:
      return instantiated;
    case function::exit_initialization_mode:
      return initialization_mode;
    case function::terminate:
      return step_complete | step_failed;
    case function::reset:
      return alive;
    case function::get_value:
      return readable;
    case function::set_real:
      return instantiated | initialization_mode | step_complete;
    case function::set_other:
      return instantiated | initialization_mode | step_complete;
    case function::fmu_state:
      return alive;
    case function::get_directional_derivative:
      return readable;
    case function::set_real_input_derivatives:
      return instantiated | initialization_mode | step_complete;
    case function::get_real_output_derivatives:
      return step_complete | step_failed | step_canceled | terminated | error;
    case function::do_step:
      return step_complete;
    case function::cancel_step:
      return step_in_progress;
    case function::get_status:
      return step_complete | step_in_progress | step_failed | terminated;
  }
  return 0;
}

const char* state_name(std::uint32_t s);

/// "instantiated, initializationMode" — for error messages.
std::string state_list(std::uint32_t mask);

}  // namespace stride::sdk::glue
