#include "euler_solver.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "stride/common/text.hpp"

namespace stride::cosim::detail {

euler_solver::euler_solver(ode_system& system, double step)
    : system_(system),
      h_(step),
      x_(system.state_count()),
      dx_(system.state_count()),
      z_(system.indicator_count()),
      z_next_(system.indicator_count()) {}

void euler_solver::reset(double t, std::span<const double> x) {
  t_ = t;
  std::copy(x.begin(), x.end(), x_.begin());
  if (!z_.empty()) system_.indicators(t_, x_, z_);
}

ode_step euler_solver::step(double t_stop, std::span<double> x) {
  // the last step lands exactly on t_stop
  const bool last = t_stop - t_ <= h_;
  const double h = last ? t_stop - t_ : h_;
  system_.derivatives(t_, x_, dx_);
  for (std::size_t i = 0; i < x_.size(); ++i) {
    x_[i] += h * dx_[i];
    if (!std::isfinite(x_[i])) {
      throw solver_failure("explicit Euler diverged: state " + std::to_string(i) + " became " +
                           (std::isnan(x_[i]) ? "NaN" : "infinite") + " (the step " +
                           text::format_double(h_) +
                           " s is too large for this system, which may be stiff; use "
                           "solver=\"cvode\" or a smaller max_step)");
    }
  }
  t_ = last ? t_stop : t_ + h;
  std::copy(x_.begin(), x_.end(), x.begin());
  ode_step result{t_, false};
  if (!z_.empty()) {
    system_.indicators(t_, x_, z_next_);
    for (std::size_t i = 0; i < z_.size(); ++i) {
      // a sign change, or a move onto zero, is an event (located at the step's end)
      if ((z_[i] > 0 && z_next_[i] <= 0) || (z_[i] < 0 && z_next_[i] >= 0)) result.root = true;
    }
    z_.swap(z_next_);
  }
  return result;
}

}  // namespace stride::cosim::detail
