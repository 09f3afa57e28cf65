// The integrator seam of the Model Exchange runner: an ODE system with event indicators, and a
// solver that advances it one internal step at a time and stops at sign changes of the
// indicators. CVODE (cvode_solver.hpp) and explicit Euler (euler_solver.hpp) implement it.
#ifndef STRIDE_COSIM_ODE_SOLVER_HPP
#define STRIDE_COSIM_ODE_SOLVER_HPP

#include <cstddef>
#include <span>
#include <stdexcept>

namespace stride::cosim::detail {

/// dx/dt = f(t, x) and the event indicators z(t, x). Failures are thrown; a solver carries them
/// across its C code and rethrows them.
class ode_system {
 public:
  virtual ~ode_system() = default;
  virtual std::size_t state_count() const noexcept = 0;
  virtual std::size_t indicator_count() const noexcept = 0;
  virtual void derivatives(double t, std::span<const double> x, std::span<double> dx) = 0;
  virtual void indicators(double t, std::span<const double> x, std::span<double> z) = 0;
};

/// Where one internal step ended.
struct ode_step {
  double t = 0;
  bool root = false;  ///< an event indicator changed sign; `t` is where
};

/// Why a solver gave up (too much work, no convergence, divergence): the text says which.
class solver_failure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ode_solver {
 public:
  virtual ~ode_solver() = default;
  /// (Re)starts at `t` from `x`: at a communication point and after every event.
  virtual void reset(double t, std::span<const double> x) = 0;
  /// One internal step towards `t_stop`, never past it; `x` receives the state at the
  /// returned time. \throws solver_failure, or what the system threw.
  virtual ode_step step(double t_stop, std::span<double> x) = 0;
};

}  // namespace stride::cosim::detail

#endif  // STRIDE_COSIM_ODE_SOLVER_HPP
