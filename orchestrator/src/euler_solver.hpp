// Explicit Euler at a fixed step: the plain reference integrator, for comparison with CVODE
// (docs/model-exchange.md). Events are detected at the end of the step that crosses them.
#ifndef STRIDE_COSIM_EULER_SOLVER_HPP
#define STRIDE_COSIM_EULER_SOLVER_HPP

#include <vector>

#include "ode_solver.hpp"

namespace stride::cosim::detail {

class euler_solver final : public ode_solver {
 public:
  euler_solver(ode_system& system, double step);
  void reset(double t, std::span<const double> x) override;
  ode_step step(double t_stop, std::span<double> x) override;

 private:
  ode_system& system_;
  double h_;
  double t_ = 0;
  std::vector<double> x_, dx_, z_, z_next_;
};

}  // namespace stride::cosim::detail

#endif  // STRIDE_COSIM_EULER_SOLVER_HPP
