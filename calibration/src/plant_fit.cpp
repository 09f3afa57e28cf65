// Plant mode: the settled gait + robot plant against a plant target, central differences.
#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "solve.hpp"
#include "stride/calibration/calibrate.hpp"
#include "stride/cosim/error.hpp"

namespace stride::calibration {

namespace {

// residuals in sigmas, in plant_result order
std::vector<double> residuals_of(const plant_target& t, const plant_posture& p) {
  std::vector<double> r;
  if (t.pitch_deg) r.push_back((p.pitch_deg - *t.pitch_deg) / t.pitch_sigma_deg);
  if (t.roll_deg) r.push_back((p.roll_deg - *t.roll_deg) / t.roll_sigma_deg);
  if (t.height_m) r.push_back((p.height_m - *t.height_m) / t.height_sigma_m);
  if (t.com_over_support) {
    r.push_back((p.com_x - p.support_x) / t.com_sigma_m);
    r.push_back((p.com_y - p.support_y) / t.com_sigma_m);
  }
  return r;
}

std::vector<plant_result> results_of(const plant_target& t, const plant_posture& before,
                                     const plant_posture& after) {
  std::vector<plant_result> out;
  if (t.pitch_deg)
    out.push_back(
        {"pitch_deg", *t.pitch_deg, before.pitch_deg, after.pitch_deg, t.pitch_sigma_deg});
  if (t.roll_deg)
    out.push_back({"roll_deg", *t.roll_deg, before.roll_deg, after.roll_deg, t.roll_sigma_deg});
  if (t.height_m)
    out.push_back({"height_m", *t.height_m, before.height_m, after.height_m, t.height_sigma_m});
  if (t.com_over_support) {
    out.push_back({"com_dx_m", 0.0, before.com_x - before.support_x, after.com_x - after.support_x,
                   t.com_sigma_m});
    out.push_back({"com_dy_m", 0.0, before.com_y - before.support_y, after.com_y - after.support_y,
                   t.com_sigma_m});
  }
  return out;
}

// Settles, remembering every point (Ceres and the covariance revisit points).
class posture_cache {
 public:
  explicit posture_cache(plant_simulator& sim) : sim_(sim) {}

  /// nullopt when the settle fails (IK out of reach, component error) or the robot falls. The
  /// offsets are rounded to the 1e-4 grid of the written values first: the plant cannot tell
  /// such points apart (its resolution is a servo count), and the solver's nearly equal trial
  /// points then cost one settle.
  std::optional<plant_posture> at(offset_values x) {
    for (double& v : x) v = std::round(v * 1e4) / 1e4 + 0.0;
    if (const auto it = cache_.find(x); it != cache_.end()) return it->second;
    std::optional<plant_posture> p;
    try {
      p = sim_.settle(x);
      if (p->fallen) p.reset();
    } catch (const std::domain_error&) {
    } catch (const cosim::error&) {
    }
    cache_.emplace(x, p);
    return p;
  }

 private:
  plant_simulator& sim_;
  std::map<offset_values, std::optional<plant_posture>> cache_;
};

class plant_cost final : public ceres::CostFunction {
 public:
  plant_cost(posture_cache& cache, const plant_target& target, std::vector<std::size_t> fit)
      : cache_(cache), target_(target), fit_(std::move(fit)) {
    set_num_residuals(target.residual_count());
    mutable_parameter_block_sizes()->push_back(static_cast<int>(offset_count));
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    offset_values x;
    std::copy(parameters[0], parameters[0] + offset_count, x.begin());
    const auto p = cache_.at(x);
    if (!p) return false;
    const std::vector<double> r = residuals_of(target_, *p);
    const int m = num_residuals();
    std::copy(r.begin(), r.end(), residuals);
    if (jacobians == nullptr || jacobians[0] == nullptr) return true;

    double* jac = jacobians[0];  // m x 7, row-major
    std::fill(jac, jac + m * static_cast<int>(offset_count), 0.0);
    for (std::size_t i : fit_) {
      const double h = offset_table()[i].fd_step;
      offset_values lo = x, hi = x;
      lo[i] -= h;
      hi[i] += h;
      const auto pl = cache_.at(lo);
      const auto ph = cache_.at(hi);
      std::vector<double> rl, rh;
      double span = 0;
      if (pl && ph) {
        rl = residuals_of(target_, *pl);
        rh = residuals_of(target_, *ph);
        span = 2 * h;
      } else if (ph) {
        rl = r;
        rh = residuals_of(target_, *ph);
        span = h;
      } else if (pl) {
        rl = residuals_of(target_, *pl);
        rh = r;
        span = h;
      } else {
        return false;
      }
      for (int k = 0; k < m; ++k)
        jac[k * static_cast<int>(offset_count) + static_cast<int>(i)] =
            (rh[static_cast<std::size_t>(k)] - rl[static_cast<std::size_t>(k)]) / span;
    }
    return true;
  }

 private:
  posture_cache& cache_;
  const plant_target& target_;
  std::vector<std::size_t> fit_;
};

// Stops as soon as the settled posture is within half a sigma of the target.
class close_enough final : public ceres::IterationCallback {
 public:
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    return s.cost <= 0.5 * 0.25 ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }
};

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace

std::vector<std::size_t> default_plant_selection(const plant_target& target) {
  std::vector<std::size_t> fit;
  const auto add = [&](const char* key) {
    const std::size_t i = *find_offset(key);
    if (std::find(fit.begin(), fit.end(), i) == fit.end()) fit.push_back(i);
  };
  // torso roll has no driver: every offset moves the two legs as mirror images
  if (target.pitch_deg) add("hip_pitch_offset");
  if (target.height_m) add("z_offset");
  if (target.com_over_support) add("x_offset");
  std::sort(fit.begin(), fit.end());
  return fit;
}

calibration_report fit_plant_posture(const plant_target& target, const gait::walking_params& start,
                                     const fit_options& options, plant_options plant) {
  if (options.fit.empty() && default_plant_selection(target).empty())
    throw std::invalid_argument(
        target.source +
        ": no offset drives the torso roll (all seven move the legs as mirror images); add "
        "another target or choose offsets with --fit");
  const std::vector<std::size_t> fit = detail::selection(options, default_plant_selection(target));
  const offset_values start_values = get_offsets(start);
  detail::check_start(start_values, fit, options.bounds);

  plant.settle_s = target.settle_s;
  plant.average_s = target.average_s;
  plant_simulator sim(plant, start, options.ik);
  posture_cache cache(sim);

  const auto before = cache.at(start_values);
  if (!before) {
    plant_posture p;
    try {
      p = sim.settle(start_values);
    } catch (const std::exception& e) {
      throw std::runtime_error("the plant cannot be settled with the start offsets: " +
                               std::string(e.what()));
    }
    throw std::runtime_error("the robot falls with the start offsets (torso pitch " +
                             fmt("%.1f", p.pitch_deg) + " deg, height " + fmt("%.3f", p.height_m) +
                             " m)");
  }

  calibration_report report = detail::start_report("plant", target.source, options.ik, start, fit);
  std::array<double, offset_count> block = start_values;
  ceres::Problem problem;
  problem.AddResidualBlock(new plant_cost(cache, target, fit), nullptr, block.data());
  detail::configure_block(problem, block.data(), fit, options.bounds);

  close_enough stop;
  ceres::Solver::Options so = detail::levenberg_marquardt(target.max_iterations);
  so.function_tolerance = 1e-6;
  so.gradient_tolerance = 1e-10;
  so.parameter_tolerance = 1e-4;
  so.callbacks.push_back(&stop);
  // no projected line search inside the trust region: it needs a Jacobian (2 settles per fitted
  // offset) at every trial point and cannot gain anything on the plant's count-sized plateaus
  so.max_num_line_search_step_size_iterations = 0;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  if (summary.termination_type == ceres::FAILURE)
    throw std::runtime_error(target.source + ": the fit failed: " + summary.message);

  detail::store_solution(report, block.data(), fit, options.bounds, options.decimals, summary);
  detail::analyse(problem, block.data(), fit, options.bounds, 1.0, report);

  const auto after = cache.at(get_offsets(report.fitted));
  if (!after)
    throw std::runtime_error("the robot falls with the fitted offsets; try narrower --bound");
  report.plant = results_of(target, *before, *after);
  for (const plant_result& r : report.plant) {
    const double off = (r.after - r.target) / r.sigma;
    if (std::abs(off) > 1.0)
      report.warnings.push_back(r.name + ": settled at " + fmt("%.4g", r.after) + ", target " +
                                fmt("%.4g", r.target) + " (" + fmt("%.1f", off) + " sigma off)");
  }
  report.evaluations = sim.evaluations();
  return report;
}

}  // namespace stride::calibration
