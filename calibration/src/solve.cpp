#include "solve.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace stride::calibration::detail {

namespace {

// An offset that would have to change by more than this (mm or deg) to move the residuals by one
// sigma is, in practice, not determined by the target.
constexpr double k_relevant_range = 10.0;
// Singular values of the column-scaled Jacobian below this fraction of the largest span a null
// space: only a combination of the offsets involved is determined.
constexpr double k_null_ratio = 1e-6;

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string key(std::size_t index) {
  return std::string(offset_table()[index].key);
}

std::string unit(std::size_t index) {
  return std::string(offset_table()[index].unit);
}

}  // namespace

std::vector<std::size_t> selection(const fit_options& options,
                                   const std::vector<std::size_t>& fallback) {
  std::vector<std::size_t> fit = options.fit.empty() ? fallback : options.fit;
  std::sort(fit.begin(), fit.end());
  fit.erase(std::unique(fit.begin(), fit.end()), fit.end());
  for (std::size_t i : fit)
    if (i >= offset_count) throw std::invalid_argument("offset index out of range");
  if (fit.empty()) throw std::invalid_argument("no offset to fit");
  return fit;
}

void check_start(const offset_values& start, const std::vector<std::size_t>& fit,
                 const offset_bounds& bounds) {
  for (std::size_t i : fit) {
    if (!(start[i] >= bounds.lower[i] && start[i] <= bounds.upper[i]))
      throw std::invalid_argument(key(i) + " = " + fmt("%g", start[i]) + " " + unit(i) +
                                  " (the start value) is outside " + "its fit bounds [" +
                                  fmt("%g", bounds.lower[i]) + ", " + fmt("%g", bounds.upper[i]) +
                                  "]; widen them with --bound " + key(i) + "=LO:HI");
  }
}

calibration_report start_report(const std::string& mode, const std::string& source,
                                gait::ik_mode ik, const gait::walking_params& start,
                                const std::vector<std::size_t>& fit) {
  calibration_report r;
  r.mode = mode;
  r.target_source = source;
  r.ik = ik;
  r.fitted = start;
  const offset_values v = get_offsets(start);
  for (std::size_t i = 0; i < offset_count; ++i) {
    offset_result o;
    o.index = i;
    o.before = o.after = v[i];
    o.fitted = std::find(fit.begin(), fit.end(), i) != fit.end();
    r.offsets.push_back(o);
  }
  return r;
}

ceres::Solver::Options levenberg_marquardt(int max_iterations) {
  ceres::Solver::Options so;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = max_iterations;
  so.logging_type = ceres::SILENT;
  so.num_threads = 1;
  return so;
}

void configure_block(ceres::Problem& problem, double* block, const std::vector<std::size_t>& fit,
                     const offset_bounds& bounds) {
  std::vector<int> constant;
  for (std::size_t i = 0; i < offset_count; ++i)
    if (std::find(fit.begin(), fit.end(), i) == fit.end()) constant.push_back(static_cast<int>(i));
  if (!constant.empty())
    problem.SetManifold(block, new ceres::SubsetManifold(static_cast<int>(offset_count), constant));
  for (std::size_t i : fit) {
    problem.SetParameterLowerBound(block, static_cast<int>(i), bounds.lower[i]);
    problem.SetParameterUpperBound(block, static_cast<int>(i), bounds.upper[i]);
  }
}

void store_solution(calibration_report& report, const double* block,
                    const std::vector<std::size_t>& fit, const offset_bounds& bounds, int decimals,
                    const ceres::Solver::Summary& summary) {
  const double scale = std::pow(10.0, decimals);
  offset_values values = get_offsets(report.fitted);
  for (std::size_t i : fit) {
    double v = std::round(block[i] * scale) / scale;
    v = std::clamp(v, bounds.lower[i], bounds.upper[i]) + 0.0;  // + 0.0: no "-0"
    values[i] = v;
    report.offsets[i].after = v;
  }
  set_offsets(report.fitted, values);
  report.initial_cost = summary.initial_cost;
  report.final_cost = summary.final_cost;
  report.iterations = static_cast<int>(summary.iterations.size()) - 1;
  report.termination = summary.message;
  report.converged = summary.termination_type == ceres::CONVERGENCE ||
                     summary.termination_type == ceres::USER_SUCCESS;
  if (!report.converged)
    report.warnings.push_back("the solver did not converge: " + summary.message);
}

void analyse(ceres::Problem& problem, double* block, const std::vector<std::size_t>& fit,
             const offset_bounds& bounds, double residual_sigma, calibration_report& report) {
  const auto n = static_cast<Eigen::Index>(fit.size());

  // Jacobian at the solution, robust loss applied, in sigmas per unit of each fitted offset
  ceres::Problem::EvaluateOptions eo;
  eo.parameter_blocks = {block};
  eo.apply_loss_function = true;
  double cost = 0;
  ceres::CRSMatrix crs;
  Eigen::MatrixXd j;
  if (problem.Evaluate(eo, &cost, nullptr, nullptr, &crs)) {
    Eigen::MatrixXd full = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
    for (int r = 0; r < crs.num_rows; ++r)
      for (int k = crs.rows[static_cast<std::size_t>(r)];
           k < crs.rows[static_cast<std::size_t>(r) + 1]; ++k)
        full(r, crs.cols[static_cast<std::size_t>(k)]) = crs.values[static_cast<std::size_t>(k)];
    if (full.cols() == n) {
      j = full;  // tangent space of the subset manifold: the fitted entries only
    } else {
      j.resize(full.rows(), n);
      for (Eigen::Index c = 0; c < n; ++c)
        j.col(c) = full.col(static_cast<Eigen::Index>(fit[static_cast<std::size_t>(c)]));
    }
    j /= residual_sigma;
  } else {
    report.warnings.push_back("the Jacobian at the solution could not be evaluated");
  }

  std::vector<bool> identifiable(fit.size(), true);
  if (j.size() > 0) {
    Eigen::VectorXd norm = j.colwise().norm().transpose();
    // 1. no effect on the target at all
    std::vector<Eigen::Index> effective;
    for (Eigen::Index c = 0; c < n; ++c) {
      const std::size_t i = fit[static_cast<std::size_t>(c)];
      if (norm(c) * k_relevant_range < 1.0) {
        identifiable[static_cast<std::size_t>(c)] = false;
        // irrelevant to the target: keep the start value rather than what the solver drifted to
        report.offsets[i].after = report.offsets[i].before;
        block[i] = report.offsets[i].before;
        offset_values values = get_offsets(report.fitted);
        values[i] = report.offsets[i].before;
        set_offsets(report.fitted, values);
        report.offsets[i].note = "no effect on the target (a change of " +
                                 fmt("%g", k_relevant_range) +
                                 " mm or deg moves the residuals "
                                 "by less than 1 sigma)";
      } else {
        effective.push_back(c);
      }
    }
    // 2. combinations: null space of the column-scaled Jacobian
    if (effective.size() > 1) {
      Eigen::MatrixXd js(j.rows(), static_cast<Eigen::Index>(effective.size()));
      for (std::size_t k = 0; k < effective.size(); ++k)
        js.col(static_cast<Eigen::Index>(k)) = j.col(effective[k]) / norm(effective[k]);
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(js, Eigen::ComputeFullV);
      const Eigen::VectorXd& s = svd.singularValues();
      const Eigen::MatrixXd& v = svd.matrixV();
      for (Eigen::Index k = 0; k < v.cols(); ++k) {
        const double sk = k < s.size() ? s(k) : 0.0;
        if (sk >= k_null_ratio * s(0)) continue;
        std::vector<std::size_t> involved;
        for (Eigen::Index r = 0; r < v.rows(); ++r)
          if (std::abs(v(r, k)) > 0.1) involved.push_back(static_cast<std::size_t>(r));
        std::string names;
        for (std::size_t r : involved)
          names += (names.empty() ? "" : ", ") + key(fit[static_cast<std::size_t>(effective[r])]);
        for (std::size_t r : involved) {
          const auto c = static_cast<std::size_t>(effective[r]);
          if (!identifiable[c]) continue;
          identifiable[c] = false;
          report.offsets[fit[c]].note =
              "rank deficient: only a combination of " + names + " is determined";
        }
      }
    }
  }

  // 3. covariance (pseudo-inverse where rank deficient) for the standard deviations
  ceres::Covariance::Options co;
  co.algorithm_type = ceres::DENSE_SVD;
  co.null_space_rank = -1;
  co.min_reciprocal_condition_number = k_null_ratio * k_null_ratio;
  co.apply_loss_function = true;
  ceres::Covariance covariance(co);
  std::vector<std::pair<const double*, const double*>> blocks = {{block, block}};
  std::vector<double> c(static_cast<std::size_t>(n * n), std::numeric_limits<double>::quiet_NaN());
  const bool have_covariance = covariance.Compute(blocks, &problem) &&
                               covariance.GetCovarianceBlockInTangentSpace(block, block, c.data());
  if (!have_covariance) report.warnings.push_back("the covariance could not be computed");

  std::vector<std::size_t> unidentified;
  for (Eigen::Index a = 0; a < n; ++a) {
    const std::size_t i = fit[static_cast<std::size_t>(a)];
    offset_result& o = report.offsets[i];
    const double var = c[static_cast<std::size_t>(a * n + a)];
    o.stddev = have_covariance ? residual_sigma * std::sqrt(std::max(var, 0.0))
                               : std::numeric_limits<double>::quiet_NaN();
    o.identifiable = identifiable[static_cast<std::size_t>(a)];
    if (o.identifiable && !(o.stddev <= k_relevant_range)) {
      o.identifiable = false;
      o.note = "poorly determined (1 sigma = " + fmt("%.3g", o.stddev) + " " + unit(i) + ")";
    }
    if (!o.identifiable) unidentified.push_back(i);
    const double tol = 1e-6 * std::max(1.0, std::abs(o.after));
    if (std::abs(o.after - bounds.lower[i]) <= tol || std::abs(o.after - bounds.upper[i]) <= tol) {
      o.at_bound = true;
      if (o.note.empty()) o.note = "at its bound";
      report.warnings.push_back(key(i) + " stopped at its bound " + fmt("%g", o.after) + " " +
                                unit(i) + "; the uncertainty there is not meaningful (--bound " +
                                key(i) + "=LO:HI widens it)");
    }
  }

  // one warning per reason, naming every offset it concerns
  std::vector<bool> done(offset_count, false);
  for (std::size_t i : unidentified) {
    if (done[i]) continue;
    std::string names;
    int count = 0;
    for (std::size_t k : unidentified) {
      if (done[k] || report.offsets[k].note != report.offsets[i].note) continue;
      done[k] = true;
      names += (names.empty() ? "" : ", ") + key(k);
      ++count;
    }
    const std::string& note = report.offsets[i].note;
    std::string advice;
    if (note.rfind("rank deficient", 0) == 0)
      advice =
          "; the written values reproduce the target, but how it is split between them is "
          "arbitrary (the solver stays near the start values): hold one of them (leave it "
          "out of --fit)";
    else if (note.rfind("no effect", 0) == 0)
      advice = "; the start value is kept";
    else
      advice = "; its fitted value is unreliable";
    report.warnings.push_back((count > 1 ? names + " are" : names + " is") +
                              " not identifiable from this target: " + note + advice);
  }
}

}  // namespace stride::calibration::detail
