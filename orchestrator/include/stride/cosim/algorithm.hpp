// The master algorithm: how values travel between components and in which order (or on which
// threads) they step. It drives components that the execution owns.
#ifndef STRIDE_COSIM_ALGORITHM_HPP
#define STRIDE_COSIM_ALGORITHM_HPP

#include <any>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "stride/cosim/component.hpp"
#include "stride/cosim/connection_graph.hpp"
#include "stride/cosim/step_group.hpp"
#include "stride/cosim/time.hpp"

namespace stride::cosim {

/// How values travel between components within a macro step.
enum class algorithm_kind {
  /// components step in dependency order; each sees the outputs its upstream components
  /// produced in the same macro step
  gauss_seidel,
  /// every component sees the outputs of the previous communication point
  jacobi,
};

std::string_view to_string(algorithm_kind kind) noexcept;

/// Values given to a component before initialization (parameters, start values of inputs).
struct start_values {
  variable_refs refs;
  value_block values;
};

/// Components that step as one unit (step_group.hpp).
struct group_wiring {
  std::vector<std::size_t> members;  ///< component indices, ascending: the group's member list
  step_group* stepper = nullptr;
};

/// What the execution hands to its algorithm when it freezes: the components it owns (alive as
/// long as the algorithm), their step multiples, the validated connections, the start values and
/// the step groups.
struct system_wiring {
  std::vector<component*> components;
  std::vector<int> step_multiples;
  std::vector<connection> connections;
  std::vector<start_values> starts;  ///< per component
  std::vector<group_wiring> groups;  ///< disjoint
};

/// Why `step()` ended.
struct step_outcome {
  bool terminated = false;        ///< a component asked to end the simulation
  std::size_t terminated_by = 0;  ///< which one, when `terminated`
};

/// A master algorithm.
///
/// Call order: setup → observe… → initialize → step…. After a step that reports termination,
/// no further step.
class algorithm {
 public:
  virtual ~algorithm() = default;

  /// Communication step of the execution.
  virtual duration base_step() const noexcept = 0;
  /// "gauss-seidel", "jacobi": for reports.
  virtual std::string describe() const = 0;
  /// The stepping order the algorithm derives from the wiring (component indices).
  virtual std::vector<std::size_t> stepping_order(const system_wiring& wiring) const = 0;

  /// Takes the wiring; `order` is stepping_order(wiring).
  virtual void setup(system_wiring wiring, std::vector<std::size_t> order) = 0;
  /// Makes a variable readable after every step; returns the handle for value(). Allowed until
  /// initialize().
  virtual std::size_t observe(variable_id var) = 0;
  /// setup of every component → start values → initialization mode → initial value exchange in
  /// stepping order → exit initialization.
  virtual void initialize(time_point start, std::optional<time_point> stop) = 0;
  /// One base step from `t`. \throws component_error naming component, function and time.
  virtual step_outcome step(time_point t) = 0;

  /// What the algorithm holds between steps (cached values, component times), to be given back
  /// to restore_state() of the same algorithm; see execution::save_state().
  virtual std::any save_state() const = 0;
  virtual void restore_state(const std::any& state) = 0;
  /// A save_state() image as bytes (a run's checkpoint file), and back: only for an algorithm
  /// set up with the same wiring. \throws validation_error for a state of another algorithm or
  /// damaged bytes.
  virtual std::vector<std::byte> state_to_bytes(const std::any& state) const = 0;
  virtual std::any state_from_bytes(std::span<const std::byte> bytes) const = 0;

  /// Current value of an observed variable (the latest value of its component at a time ≤ the
  /// execution's time).
  virtual double real_value(std::size_t observed) const = 0;
  virtual int integer_value(std::size_t observed) const = 0;
  virtual bool boolean_value(std::size_t observed) const = 0;
  virtual const std::string& string_value(std::size_t observed) const = 0;
};

/// Fixed base step with per-component step multiples (decimation), Gauss-Seidel or Jacobi
/// transfer. Components that share no value within a macro step step concurrently on `threads`
/// threads; any thread count gives bit-identical results (each component reads exactly the
/// values it would read stepping alone, in stepping order). A step group steps as one unit at the
/// place of its first member; its members keep their own order among themselves.
class fixed_step_algorithm final : public algorithm {
 public:
  /// \pre base_step > 0, threads ≥ 1. \throws validation_error otherwise.
  explicit fixed_step_algorithm(duration base_step,
                                algorithm_kind kind = algorithm_kind::gauss_seidel,
                                int threads = 1);
  ~fixed_step_algorithm() override;
  fixed_step_algorithm(const fixed_step_algorithm&) = delete;
  fixed_step_algorithm& operator=(const fixed_step_algorithm&) = delete;

  algorithm_kind kind() const noexcept;
  int threads() const noexcept;

  duration base_step() const noexcept override;
  std::string describe() const override;
  std::vector<std::size_t> stepping_order(const system_wiring& wiring) const override;
  void setup(system_wiring wiring, std::vector<std::size_t> order) override;
  std::size_t observe(variable_id var) override;
  void initialize(time_point start, std::optional<time_point> stop) override;
  step_outcome step(time_point t) override;
  std::any save_state() const override;
  void restore_state(const std::any& state) override;
  std::vector<std::byte> state_to_bytes(const std::any& state) const override;
  std::any state_from_bytes(std::span<const std::byte> bytes) const override;
  double real_value(std::size_t observed) const override;
  int integer_value(std::size_t observed) const override;
  bool boolean_value(std::size_t observed) const override;
  const std::string& string_value(std::size_t observed) const override;

 private:
  class impl;
  std::unique_ptr<impl> pimpl_;
};

/// The machine's hardware threads (at least 1): the default of `stride run --threads`.
int default_thread_count() noexcept;

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_ALGORITHM_HPP
