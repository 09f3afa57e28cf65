// The component seam: what the master algorithm drives, wherever the component runs. An FMU
// instance in this process is one implementation (fmu.hpp); a proxy for a component in another
// process implements the same interface and nothing above it changes; tests use a mock.
#ifndef STRIDE_COSIM_COMPONENT_HPP
#define STRIDE_COSIM_COMPONENT_HPP

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "stride/cosim/model_description.hpp"
#include "stride/cosim/time.hpp"

namespace stride::cosim {

/// How a step ended.
enum class step_result {
  complete,   ///< the component advanced to t + dt
  terminate,  ///< the component asks to end the simulation (FMI: fmi2Discard + fmi2Terminated)
};

/// The value references of one batch, by exchange type (enumerations travel as integers).
struct variable_refs {
  std::vector<value_reference> reals;
  std::vector<value_reference> integers;
  std::vector<value_reference> booleans;
  std::vector<value_reference> strings;

  bool empty() const noexcept {
    return reals.empty() && integers.empty() && booleans.empty() && strings.empty();
  }
  std::size_t size() const noexcept {
    return reals.size() + integers.size() + booleans.size() + strings.size();
  }
  /// Appends `var` of `type` to its type's list; returns its position there.
  std::size_t add(variable_type type, value_reference var);
};

/// The values of one batch, in the order of its variable_refs.
struct value_block {
  std::vector<double> reals;
  std::vector<int> integers;
  std::vector<bool> booleans;
  std::vector<std::string> strings;

  /// Sizes every list like `refs` (new values are zero, false or "").
  void resize_for(const variable_refs& refs);
};

/// One simulation unit with FMI 2.0 Co-Simulation semantics.
///
/// Call order (the execution and its algorithm guarantee it):
///   1. `setup(start, stop)`                                      FMI: fmi2SetupExperiment
///   2. `set_values` of parameters and start values
///   3. `expose(inputs, outputs)`: the variables every step sets and returns, declared once
///   4. `enter_initialization()`                                  fmi2EnterInitializationMode
///   5. `set_values` / `get_values`                               initial value exchange
///   6. `exit_initialization()`                                   fmi2ExitInitializationMode
///   7. repeated: `step(t, dt, inputs, outputs)` — ONE call per communication step, carrying
///      every exposed input of every type and returning every exposed output
///   8. `terminate()` (once, only after 4)                        fmi2Terminate
/// `save_state`/`restore_state` are allowed after 4. Errors are thrown as component_error naming
/// the component and the function.
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
  virtual void terminate() = 0;

  /// Writes `values` (ordered like `refs`) to the component, all types in one call.
  virtual void set_values(const variable_refs& refs, const value_block& values) = 0;
  /// Reads the variables of `refs` into `values` (resized to fit).
  virtual void get_values(const variable_refs& refs, value_block& values) = 0;

  /// Declares which variables every step() sets (`inputs`) and returns (`outputs`).
  virtual void expose(const variable_refs& inputs, const variable_refs& outputs) = 0;
  /// One communication step: sets the exposed inputs to `inputs`, advances from `t` by `dt`
  /// (> 0) and, when the step completes, writes the exposed outputs at t + dt into `outputs`
  /// (sized by the caller with resize_for).
  virtual step_result step(time_point t, duration dt, const value_block& inputs,
                           value_block& outputs) = 0;

  /// The complete state of the component as bytes (FMI: fmi2GetFMUstate + serialization).
  virtual std::vector<std::byte> save_state() = 0;
  /// Restores a save_state() image: the continuation is the one from the saved moment.
  virtual void restore_state(std::span<const std::byte> state) = 0;
};

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_COMPONENT_HPP
