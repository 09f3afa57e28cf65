// The execution: owns the algorithm, advances time and notifies observers.
#ifndef STRIDE_COSIM_EXECUTION_HPP
#define STRIDE_COSIM_EXECUTION_HPP

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stride/cosim/algorithm.hpp"
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

/// How a run ended.
struct run_result {
  time_point end_time{};
  std::int64_t steps = 0;
  bool terminated_by_component = false;
  std::string terminated_by;  ///< component name when terminated_by_component
};

/// Time loop over one fixed_step_algorithm.
class execution {
 public:
  /// \pre algo is not null.
  execution(std::unique_ptr<fixed_step_algorithm> algo, time_point start);
  ~execution();
  execution(const execution&) = delete;
  execution& operator=(const execution&) = delete;

  fixed_step_algorithm& algorithm() noexcept { return *algo_; }
  const fixed_step_algorithm& algorithm() const noexcept { return *algo_; }

  /// \throws validation_error after initialize().
  void add_observer(std::shared_ptr<observer> obs);

  /// Freezes and initializes the algorithm; `stop` is passed to the components.
  void initialize(std::optional<time_point> stop);
  bool initialized() const noexcept { return initialized_; }

  /// Steps until `stop` (ends at the last communication point ≤ stop) or until a component
  /// requests termination. Initializes first if needed; may be called again with a later stop.
  /// On an error or a termination request the execution ends: observers are told (recorders
  /// flush), components are terminated, and an error is rethrown.
  run_result simulate_until(time_point stop);
  /// Ends the run: observers are told, components terminated. Also done by the destructor.
  void end() noexcept;
  bool ended() const noexcept { return finished_; }

  time_point start_time() const noexcept { return start_; }
  time_point current_time() const noexcept;

 private:
  void finish(time_point t, const std::string& error) noexcept;

  std::unique_ptr<fixed_step_algorithm> algo_;
  std::vector<std::shared_ptr<observer>> observers_;
  time_point start_;
  bool initialized_ = false;
  bool finished_ = false;
};

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_EXECUTION_HPP
