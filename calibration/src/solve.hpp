// Shared parts of the two fits (private): the parameter block, the solve and the covariance /
// identifiability analysis.
#pragma once

#include <ceres/ceres.h>

#include <string>
#include <vector>

#include "stride/calibration/calibrate.hpp"

namespace stride::calibration::detail {

/// The fitted selection, or `fallback` when options.fit is empty; throws std::invalid_argument
/// for an index out of range.
std::vector<std::size_t> selection(const fit_options& options,
                                   const std::vector<std::size_t>& fallback);

/// Throws std::invalid_argument naming an offset whose start value lies outside its bounds.
void check_start(const offset_values& start, const std::vector<std::size_t>& fit,
                 const offset_bounds& bounds);

/// A report with the offsets' "before" values and which are fitted.
calibration_report start_report(const std::string& mode, const std::string& source,
                                gait::ik_mode ik, const gait::walking_params& start,
                                const std::vector<std::size_t>& fit);

/// Levenberg-Marquardt with a dense QR step, silent and on one thread (so that every run gives
/// the same result); each fit sets its own tolerances.
ceres::Solver::Options levenberg_marquardt(int max_iterations);

/// Bounds on the fitted entries of the 7-value block; the others held constant.
void configure_block(ceres::Problem& problem, double* block, const std::vector<std::size_t>& fit,
                     const offset_bounds& bounds);

/// Rounds the fitted values to `decimals` (inside the bounds) and stores them in the report
/// (offsets[].after, fitted) together with the solver summary.
void store_solution(calibration_report& report, const double* block,
                    const std::vector<std::size_t>& fit, const offset_bounds& bounds, int decimals,
                    const ceres::Solver::Summary& summary);

/// Uncertainty of every fitted offset from the Ceres covariance at `block` (residuals scaled by
/// `residual_sigma`), flags offsets the target does not determine and offsets at a bound, and
/// adds a warning for each.
void analyse(ceres::Problem& problem, double* block, const std::vector<std::size_t>& fit,
             const offset_bounds& bounds, double residual_sigma, calibration_report& report);

}  // namespace stride::calibration::detail
