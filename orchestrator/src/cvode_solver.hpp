// SUNDIALS CVODE (BDF or Adams, dense Newton for BDF) with root finding on the event
// indicators, behind the ode_solver seam.
#ifndef STRIDE_COSIM_CVODE_SOLVER_HPP
#define STRIDE_COSIM_CVODE_SOLVER_HPP

#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "ode_solver.hpp"
#include "stride/cosim/model_exchange.hpp"

namespace stride::cosim::detail {

struct cvode_settings {
  model_exchange_options::method_kind method = model_exchange_options::method_kind::bdf;
  double rtol = 1e-6;
  std::vector<double> atol;  ///< one per state
  std::optional<double> max_step;
};

class cvode_solver final : public ode_solver {
 public:
  cvode_solver(ode_system& system, const cvode_settings& settings);
  ~cvode_solver() override;
  cvode_solver(const cvode_solver&) = delete;
  cvode_solver& operator=(const cvode_solver&) = delete;

  void reset(double t, std::span<const double> x) override;
  ode_step step(double t_stop, std::span<double> x) override;

  struct handles;

 private:
  [[noreturn]] void fail(int flag, const char* function);

  ode_system& system_;
  cvode_settings settings_;
  handles* h_ = nullptr;
  bool initialised_ = false;
  std::exception_ptr pending_;  // thrown by the system inside CVODE's callbacks
  std::string message_;         // CVODE's last error text
  std::vector<double> scratch_;
};

}  // namespace stride::cosim::detail

#endif  // STRIDE_COSIM_CVODE_SOLVER_HPP
