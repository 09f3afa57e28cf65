// The component interface: what the master algorithm drives. An FMU instance is one
// implementation (fmu.hpp); tests use a mock.
#ifndef STRIDE_COSIM_COMPONENT_HPP
#define STRIDE_COSIM_COMPONENT_HPP

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "stride/cosim/model_description.hpp"
#include "stride/cosim/time.hpp"

namespace stride::cosim {

/// How a step ended.
enum class step_result {
  complete,   ///< the component advanced to t + dt
  terminate,  ///< the component asks to end the simulation (FMI: fmi2Discard + fmi2Terminated)
};

/// One simulation unit with FMI 2.0 Co-Simulation semantics.
///
/// Call order (the algorithm guarantees it):
///   1. `setup(start, stop)`                        — FMI: fmi2SetupExperiment
///   2. `set_*` of parameters and start values
///   3. `enter_initialization()`                    — FMI: fmi2EnterInitializationMode
///   4. `set_*` of inputs, `get_*` of outputs        (initial value exchange)
///   5. `exit_initialization()`                     — FMI: fmi2ExitInitializationMode
///   6. repeated: `set_*` inputs, `do_step`, `get_*` outputs
///   7. `terminate()`                               — FMI: fmi2Terminate (once, only after 1)
/// All get/set calls are batched: one span of value references and one span of values of the
/// same length. Errors are thrown as component_error naming the component and the function.
class component {
 public:
  virtual ~component() = default;

  /// Instance name, unique within a system.
  virtual const std::string& name() const noexcept = 0;
  /// What this component declares; valid for the component's whole life.
  virtual const stride::cosim::model_description& model_description() const noexcept = 0;

  virtual void setup(time_point start, std::optional<time_point> stop) = 0;
  virtual void enter_initialization() = 0;
  virtual void exit_initialization() = 0;
  /// Advances from `t` by `dt` (> 0).
  virtual step_result do_step(time_point t, duration dt) = 0;
  virtual void terminate() = 0;

  virtual void get_real(std::span<const value_reference> vr, std::span<double> out) = 0;
  virtual void get_integer(std::span<const value_reference> vr, std::span<int> out) = 0;
  virtual void get_boolean(std::span<const value_reference> vr, std::span<bool> out) = 0;
  virtual void get_string(std::span<const value_reference> vr, std::span<std::string> out) = 0;

  virtual void set_real(std::span<const value_reference> vr, std::span<const double> in) = 0;
  virtual void set_integer(std::span<const value_reference> vr, std::span<const int> in) = 0;
  virtual void set_boolean(std::span<const value_reference> vr, std::span<const bool> in) = 0;
  virtual void set_string(std::span<const value_reference> vr, std::span<const std::string> in) = 0;
};

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_COMPONENT_HPP
