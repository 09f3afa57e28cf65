// One Model Exchange instance as the runner (me_component.cpp) drives it: the calls of FMI 2.0
// and FMI 3.0 Model Exchange under one set of names, so that the integration and the event
// handling are written once. fmi2_me_instance.cpp and fmi3_me_instance.cpp are the two leaves.
#ifndef STRIDE_COSIM_ME_INSTANCE_HPP
#define STRIDE_COSIM_ME_INSTANCE_HPP

#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "stride/cosim/component.hpp"
#include "stride/cosim/model_description.hpp"

namespace stride::cosim::detail {

/// A call the FMU refused or answered with a value Stride does not pass on, e.g.
/// "fmi2GetDerivatives returned fmi2Error". The runner adds the component and the time.
class fmu_call_failure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What one pass of event iteration reported (fmi2NewDiscreteStates, fmi3UpdateDiscreteStates).
struct discrete_update {
  bool again = false;  ///< newDiscreteStatesNeeded / discreteStatesNeedUpdate
  bool terminate = false;
  bool next_time_defined = false;
  double next_time = 0;
};

/// What the FMU asked for after an accepted integrator step.
struct integrator_step_answer {
  bool enter_event_mode = false;
  bool terminate = false;
};

class me_instance {
 public:
  virtual ~me_instance() = default;

  virtual const model_description& description() const noexcept = 0;
  virtual const std::filesystem::path& file() const noexcept = 0;
  /// The function that returns the state derivatives, for messages.
  virtual const char* derivatives_function() const noexcept = 0;

  /// Start and stop time and the relative tolerance the runner integrates with.
  virtual void setup(double start, std::optional<double> stop, double tolerance) = 0;
  virtual void enter_initialization() = 0;
  /// Leaves the instance in event mode (both standards do).
  virtual void exit_initialization() = 0;
  virtual void terminate() = 0;

  virtual void enter_event_mode() = 0;
  virtual discrete_update update_discrete_states() = 0;
  virtual void enter_continuous_time_mode() = 0;
  /// Only called when the FMU declares that it needs it.
  virtual integrator_step_answer completed_integrator_step() = 0;
  virtual bool needs_completed_integrator_step() const noexcept = 0;

  virtual void set_time(double t) = 0;
  virtual void set_states(std::span<const double> x) = 0;
  virtual void get_states(std::span<double> x) = 0;
  virtual void get_derivatives(std::span<double> dx) = 0;
  virtual void get_indicators(std::span<double> z) = 0;
  virtual void get_nominals(std::span<double> nominals) = 0;

  virtual void set_values(const variable_refs& refs, const value_block& values) = 0;
  /// \throws fmu_call_failure for a non-finite real (it is never passed on)
  virtual void get_values(const variable_refs& refs, value_block& values) = 0;

  /// The FMU's own state, serialized; both need canGetAndSetFMUState and canSerializeFMUState.
  virtual std::vector<std::byte> save() = 0;
  virtual void restore(std::span<const std::byte> bytes) = 0;
};

/// \throws fmu_call_failure naming `function` and the first non-finite real of `values`.
void require_finite_reals(const variable_refs& refs, const value_block& values,
                          const char* function);

}  // namespace stride::cosim::detail

#endif  // STRIDE_COSIM_ME_INSTANCE_HPP
