// The execution: owns the components and the algorithm that drives them, advances time and
// notifies observers.
//
// Build → validate → freeze: components, connections and start values are added first;
// `freeze()` checks every connection (causality, type, unit, inputs driven twice), finds
// direct-feedthrough loops (Gauss-Seidel) and hands the wiring to the algorithm. After that the
// topology cannot change.
#ifndef STRIDE_COSIM_EXECUTION_HPP
#define STRIDE_COSIM_EXECUTION_HPP

#include <any>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "stride/cosim/algorithm.hpp"
#include "stride/cosim/component.hpp"
#include "stride/cosim/connection_graph.hpp"
#include "stride/cosim/log.hpp"
#include "stride/cosim/scalar_value.hpp"
#include "stride/cosim/step_group.hpp"
#include "stride/cosim/time.hpp"

namespace stride::cosim {

class execution;

/// A read-only tap on an execution (recorders, progress displays). Callbacks must not throw
/// except from `attach`.
class observer {
 public:
  virtual ~observer() = default;
  /// Called once before initialization: observe the variables you need.
  virtual void attach(execution& /*ex*/) {}
  /// After initialization, at the start time.
  virtual void simulation_initialized(const execution& /*ex*/, time_point /*t*/) {}
  /// After every macro step; `t` is the new current time.
  virtual void step_complete(const execution& /*ex*/, std::int64_t /*step*/, time_point /*t*/) {}
  /// Once at the end, also when the run failed (`error` non-empty): flush what you have.
  virtual void simulation_ended(const execution& /*ex*/, time_point /*t*/,
                                const std::string& /*error*/) {}
};

/// A handle to read a variable's current value; see execution::observe.
struct observed_variable {
  variable_id id;
  variable_type type = variable_type::real;  ///< exchange type (never enumeration)
  std::size_t index = 0;                     ///< the algorithm's handle
};

/// How a run ended.
struct run_result {
  time_point end_time{};
  std::int64_t steps = 0;
  bool terminated_by_component = false;
  std::string terminated_by;  ///< component name when terminated_by_component
  bool interrupted = false;   ///< ended early because the interrupt flag was set
  /// "comp.var" of the stop condition (execution::stop_when) that ended the run; empty if none
  std::string stopped_by;
};

/// The complete state of an initialized execution: every component's FMU state and what the
/// algorithm holds between steps. Only for the execution that saved it.
struct execution_state {
  std::int64_t steps = 0;
  std::vector<std::vector<std::byte>> components;
  std::any algorithm;
};

/// One component's image in save_state_bytes().
struct saved_component {
  std::string name;
  std::vector<std::byte> image;
};

/// The components' images in execution::save_state_bytes(), restoring nothing (e.g. to see whose
/// images they are). \throws validation_error for damaged bytes.
std::vector<saved_component> saved_components(std::span<const std::byte> state_bytes);

/// Components, their connections and their algorithm, run over time.
class execution {
 public:
  /// \pre algo is not null. `log` receives validation warnings (e.g. unit mismatches).
  execution(std::unique_ptr<algorithm> algo, time_point start = {}, log_sink log = {});
  ~execution();
  execution(const execution&) = delete;
  execution& operator=(const execution&) = delete;

  /// Adds a component that steps every `step_multiple` base steps; returns its index.
  /// \throws validation_error after freeze(), for a duplicate name or a multiple < 1.
  std::size_t add_component(std::unique_ptr<component> c, int step_multiple = 1);
  /// Makes the components `members` (indices, at least two) step as one unit through `group`,
  /// which steps them where they run (step_group.hpp). \throws validation_error after freeze(),
  /// for an unknown index or a component already in a group.
  void add_group(std::vector<std::size_t> members, std::unique_ptr<step_group> group);
  /// The step groups' members (component indices, ascending), in the order they were added.
  const std::vector<std::vector<std::size_t>>& groups() const noexcept { return group_members_; }
  /// Connects an output to an input (or parameter). Checked in freeze().
  void connect(variable_id from, variable_id to, connection_options options = {});
  /// Value set before initialization (parameters, start values of inputs). `origin` ("file:line",
  /// "--set comp.var=value") prefixes errors, also freeze()'s when a connection drives the
  /// variable. \throws validation_error if the variable cannot be set or the value has the wrong
  /// type.
  void set_start_value(variable_id var, scalar_value value, const std::string& origin = {});

  /// Validates and fixes the topology. \throws validation_error with every message naming
  /// components, variables and connection origins; an algebraic loop is spelled out; a value
  /// given to a variable that a connection drives (the connection would overwrite it at
  /// initialization) is refused naming both.
  void freeze();
  bool frozen() const noexcept { return frozen_; }

  /// Makes a variable readable after every step; allowed until initialize().
  observed_variable observe(variable_id var);
  /// \throws validation_error after initialize().
  void add_observer(std::shared_ptr<observer> obs);
  /// A stop condition: simulate_until ends at the first communication point (the start time
  /// included) at which this output is true (Boolean) or non-zero (Integer, Real), and
  /// run_result::stopped_by names it. \throws validation_error after initialize(), or naming the
  /// variable when it is not an output of type Boolean, Integer, Enumeration or Real.
  void stop_when(variable_id var);

  /// Freezes if needed and initializes the components; `stop` is passed to them, and FMUs refuse
  /// steps past it (simulate_until initializes with its own stop when this was not called).
  void initialize(std::optional<time_point> stop);
  bool initialized() const noexcept { return initialized_; }

  /// One base step (initializes first if needed); observers are told.
  /// \throws component_error naming component, function and time.
  step_outcome step();
  /// Steps until `stop` (ends at the last communication point ≤ stop), until a component
  /// requests termination or until a stop condition (stop_when) holds. Initializes first if
  /// needed; may be called again with a later stop. On an error, a termination request or a stop
  /// condition the execution ends: observers are told (recorders flush), components are
  /// terminated, and an error is rethrown.
  /// `interrupt`, when given, is checked between steps: once set, the run ends there as at the
  /// stop time (set from a signal handler, for instance).
  run_result simulate_until(time_point stop, const std::atomic<bool>* interrupt = nullptr);
  /// Saves the whole system between two steps (components through their save_state).
  /// \throws component_error when a component cannot save its state.
  execution_state save_state() const;
  /// Puts the system back to a saved moment: the steps that follow repeat, bit for bit, those
  /// that followed the save. Observers are not told (a recorder keeps its rows).
  void restore_state(const execution_state& state);
  /// save_state() as bytes, for a file (a run's checkpoint): the step count, each component's
  /// name and state, the algorithm's state (docs/checkpoint-format.md).
  std::vector<std::byte> save_state_bytes() const;
  /// Restores save_state_bytes() of an execution of the same system (the same components in the
  /// same order, the same wiring). \throws validation_error naming what differs, or for damaged
  /// bytes.
  void restore_state_bytes(std::span<const std::byte> bytes);
  /// Ends the run: observers are told, components terminated. Also done by the destructor.
  void end() noexcept;
  bool ended() const noexcept { return finished_; }

  time_point start_time() const noexcept { return start_; }
  time_point current_time() const noexcept { return now_; }
  std::int64_t step_count() const noexcept { return steps_; }
  duration base_step() const noexcept { return algo_->base_step(); }
  /// The algorithm's name ("gauss-seidel", "jacobi") for reports.
  std::string algorithm_name() const { return algo_->describe(); }

  std::size_t component_count() const noexcept { return components_.size(); }
  component& component_at(std::size_t index) { return *components_.at(index); }
  const component& component_at(std::size_t index) const { return *components_.at(index); }
  int step_multiple(std::size_t index) const { return multiples_.at(index); }
  /// Index of the component called `name`, or nullopt.
  std::optional<std::size_t> find_component(std::string_view name) const noexcept;
  /// Stepping order (component indices), valid after freeze().
  const std::vector<std::size_t>& order() const noexcept { return order_; }
  const std::vector<connection>& connections() const noexcept { return connections_; }
  /// "comp.var" of a variable.
  std::string full_name(variable_id var) const;

  /// Current values (the latest value of each component at a time ≤ current_time()).
  double real_value(const observed_variable& v) const { return algo_->real_value(v.index); }
  int integer_value(const observed_variable& v) const { return algo_->integer_value(v.index); }
  bool boolean_value(const observed_variable& v) const { return algo_->boolean_value(v.index); }
  const std::string& string_value(const observed_variable& v) const {
    return algo_->string_value(v.index);
  }

 private:
  component_declarations declarations() const;
  void check_variable(variable_id id, const std::string& context) const;
  void finish(time_point t, const std::string& error) noexcept;
  void terminate_components() noexcept;
  /// the first stop condition that holds now, or nullptr
  const observed_variable* stop_condition_met() const;

  std::unique_ptr<stride::cosim::algorithm> algo_;
  log_sink log_;
  std::vector<std::unique_ptr<component>> components_;
  std::vector<std::vector<std::size_t>> group_members_;
  std::vector<std::unique_ptr<step_group>> groups_;
  std::vector<int> multiples_;
  std::vector<connection> connections_;
  std::vector<start_values> starts_;
  std::vector<std::pair<variable_id, std::string>> start_origins_;  ///< what set_start_value set
  std::vector<std::size_t> order_;
  std::vector<std::shared_ptr<observer>> observers_;
  std::vector<observed_variable> stop_conditions_;
  time_point start_;
  time_point now_;
  std::int64_t steps_ = 0;
  bool frozen_ = false;
  bool initialized_ = false;
  bool finished_ = false;
};

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_EXECUTION_HPP
