// The master algorithm: fixed base step, per-component step multiples (decimation), sequential
// Gauss-Seidel (default) or Jacobi value transfer.
//
// Build → validate → freeze: components and connections are added first; `freeze()` checks
// every connection (causality, type, unit, inputs driven twice), finds direct-feedthrough loops
// from the ModelStructure dependencies and fixes the stepping order. After that the topology
// cannot change.
#ifndef STRIDE_COSIM_ALGORITHM_HPP
#define STRIDE_COSIM_ALGORITHM_HPP

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "stride/cosim/component.hpp"
#include "stride/cosim/log.hpp"
#include "stride/cosim/time.hpp"

namespace stride::cosim {

/// How values travel between components within a macro step.
enum class algorithm_kind {
  /// components step one after the other in dependency order; each sees the outputs its
  /// upstream components produced in the same macro step
  gauss_seidel,
  /// every component sees the outputs of the previous communication point
  jacobi,
};

std::string_view to_string(algorithm_kind kind) noexcept;

/// A variable of a component added to an algorithm.
struct variable_id {
  std::size_t component = 0;  ///< index returned by add_component
  std::size_t variable = 0;   ///< index into the component's model_description().variables
  friend bool operator==(const variable_id&, const variable_id&) = default;
};

/// A value of any FMI type (enumerations travel as int).
using scalar_value = std::variant<double, int, bool, std::string>;

/// Parses text as a value of `type` ("1.5", "-3", "true"/"false"/"1"/"0", any string).
/// \throws std::invalid_argument with a message naming the expected type.
scalar_value parse_scalar(variable_type type, std::string_view text);
/// Text of a value, parseable again by parse_scalar (doubles in shortest round-trip form).
std::string format_scalar(const scalar_value& value);

/// Extra information about a connection.
struct connection_options {
  /// the target reads the source value of the previous communication point (breaks loops)
  bool delayed = false;
  /// where the connection was declared ("walk.xml:12"), quoted in error messages
  std::string origin;
};

/// A resolved connection.
struct connection {
  variable_id from;
  variable_id to;
  connection_options options;
};

/// A handle to read a variable's current value; see fixed_step_algorithm::observe.
struct observed_variable {
  variable_id id;
  variable_type type = variable_type::real;  ///< exchange type (never enumeration)
  std::size_t slot = 0;
};

/// Why `step()` ended.
struct step_outcome {
  bool terminated = false;        ///< a component asked to end the simulation
  std::size_t terminated_by = 0;  ///< which one, when `terminated`
};

/// Fixed-step master algorithm over owned components. Not thread-safe; runs sequentially.
class fixed_step_algorithm {
 public:
  /// \pre base_step > 0. `log` receives validation warnings (e.g. unit mismatches).
  explicit fixed_step_algorithm(duration base_step,
                                algorithm_kind kind = algorithm_kind::gauss_seidel,
                                log_sink log = {});
  ~fixed_step_algorithm();
  fixed_step_algorithm(const fixed_step_algorithm&) = delete;
  fixed_step_algorithm& operator=(const fixed_step_algorithm&) = delete;

  /// Adds a component that steps every `step_multiple` base steps; returns its index.
  /// \throws validation_error after freeze(), for a duplicate name or a multiple < 1.
  std::size_t add_component(std::unique_ptr<component> c, int step_multiple = 1);
  /// Connects an output to an input (or parameter). Checked in freeze().
  void connect(variable_id from, variable_id to, connection_options options = {});
  /// Value set before initialization (parameters, start values of inputs).
  /// \throws validation_error if the variable cannot be set or the value has the wrong type.
  void set_start_value(variable_id var, scalar_value value, const std::string& origin = {});
  /// Makes a variable readable after every step; allowed until initialize().
  observed_variable observe(variable_id var);

  /// Validates and fixes the topology. \throws validation_error with every message naming
  /// components, variables and connection origins; an algebraic loop is spelled out.
  void freeze();
  bool frozen() const noexcept;

  /// setup → start values → initialization mode → initial value exchange in stepping order →
  /// exit initialization. Freezes first if needed.
  void initialize(time_point start, std::optional<time_point> stop);
  /// One base step from current_time(). \throws component_error naming component, function
  /// and time if a component fails.
  step_outcome step();
  /// Terminates every component once (after initialize()); errors are reported to the log.
  void terminate_all() noexcept;

  time_point current_time() const noexcept;
  std::int64_t step_count() const noexcept;
  duration base_step() const noexcept;
  algorithm_kind kind() const noexcept;

  std::size_t component_count() const noexcept;
  component& component_at(std::size_t index);
  const component& component_at(std::size_t index) const;
  int step_multiple(std::size_t index) const;
  /// Index of the component called `name`, or nullopt.
  std::optional<std::size_t> find_component(std::string_view name) const noexcept;
  /// Stepping order (component indices), valid after freeze().
  const std::vector<std::size_t>& order() const noexcept;
  const std::vector<connection>& connections() const noexcept;
  /// "comp.var" of a variable.
  std::string full_name(variable_id var) const;

  /// Current values (the latest value of each component at a time ≤ current_time()).
  double real_value(const observed_variable& v) const;
  int integer_value(const observed_variable& v) const;
  bool boolean_value(const observed_variable& v) const;
  const std::string& string_value(const observed_variable& v) const;

 private:
  class impl;
  std::unique_ptr<impl> pimpl_;
};

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_ALGORITHM_HPP
