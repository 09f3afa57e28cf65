// Joint-posture mode: the only translation unit with Ceres autodiff (compile time).
#include <ceres/ceres.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "solve.hpp"
#include "stride/calibration/calibrate.hpp"
#include "stride/gait/walking.hpp"

namespace stride::calibration {

namespace {

// Servo IDs the offsets move: the 12 leg servos. Arms and head are constant in the gait.
bool is_leg_servo(int id) {
  return id >= 7 && id <= 18;
}

// One joint of one posture: the untruncated standing servo count of the gait with the offsets
// plus the posture's deltas, minus the target count.
struct joint_residual {
  int index;  // servo ID - 1
  double target;
  offset_values delta;
  gait::ik_mode mode;
  gait::walking_params base;

  template <class T>
  bool operator()(const T* const offsets, T* residual) const {
    gait::standing_params<T> p = gait::standing_params<T>::from(base);
    p.x_offset = offsets[0] + delta[0];
    p.y_offset = offsets[1] + delta[1];
    p.z_offset = offsets[2] + delta[2];
    p.roll_offset = offsets[3] + delta[3];
    p.pitch_offset = offsets[4] + delta[4];
    p.yaw_offset = offsets[5] + delta[5];
    p.hip_pitch_offset = offsets[6] + delta[6];
    std::array<T, gait::servo_total> counts;
    if (!gait::standing_servo_counts(p, mode, counts)) return false;
    residual[0] = counts[static_cast<std::size_t>(index)] - target;
    return true;
  }
};

using servo_counts = std::array<double, gait::servo_total>;

servo_counts model_counts(const gait::walking_params& p, gait::ik_mode mode) {
  servo_counts counts;
  if (!gait::standing_servo_counts(gait::standing_params<double>::from(p), mode, counts)) {
    std::string offsets;
    for (const offset_info& o : offset_table())
      offsets +=
          (offsets.empty() ? "" : ", ") + std::string(o.key) + " = " + std::to_string(p.*o.member);
    throw std::domain_error("the standing foot targets are out of the leg's reach with " + offsets);
  }
  return counts;
}

// the gait's standing output for every posture of the target at the offsets of `p`
std::vector<servo_counts> posture_counts(const joint_target& target, const gait::walking_params& p,
                                         gait::ik_mode mode) {
  std::vector<servo_counts> out;
  const offset_values base = get_offsets(p);
  for (const posture& q : target.postures) {
    gait::walking_params moved = p;
    offset_values v = base;
    for (std::size_t k = 0; k < offset_count; ++k) v[k] += q.delta[k];
    set_offsets(moved, v);
    out.push_back(model_counts(moved, mode));
  }
  return out;
}

std::string servo_name(int id) {
  static const char* const names[gait::servo_total] = {
      "r_sho_pitch", "l_sho_pitch", "r_sho_roll", "l_sho_roll", "r_el",
      "l_el",        "r_hip_yaw",   "l_hip_yaw",  "r_hip_roll", "l_hip_roll",
      "r_hip_pitch", "l_hip_pitch", "r_knee",     "l_knee",     "r_ank_pitch",
      "l_ank_pitch", "r_ank_roll",  "l_ank_roll", "head_pan",   "head_tilt"};
  return "servo " + std::to_string(id) + " (" + names[id - 1] + ")";
}

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace

calibration_report fit_joint_posture(const joint_target& target, const gait::walking_params& start,
                                     const fit_options& options) {
  std::vector<std::size_t> all(offset_count);
  for (std::size_t i = 0; i < offset_count; ++i) all[i] = i;
  const std::vector<std::size_t> fit = detail::selection(options, all);
  const offset_values start_values = get_offsets(start);
  detail::check_start(start_values, fit, options.bounds);
  const auto before = posture_counts(target, start, options.ik);
  if (!(options.loss_scale > 0)) throw std::invalid_argument("the loss scale must be positive");

  calibration_report report = detail::start_report("joints", target.source, options.ik, start, fit);
  report.postures = target.postures;

  std::array<double, offset_count> block = start_values;
  ceres::Problem problem;
  int legs = 0;
  for (const joint_reading& j : target.joints) {
    if (!is_leg_servo(j.id)) continue;
    ++legs;
    auto* cost = new ceres::AutoDiffCostFunction<joint_residual, 1, static_cast<int>(offset_count)>(
        new joint_residual{j.id - 1, j.count,
                           target.postures[static_cast<std::size_t>(j.posture)].delta, options.ik,
                           start});
    problem.AddResidualBlock(cost, new ceres::CauchyLoss(options.loss_scale), block.data());
  }
  if (legs == 0)
    throw std::invalid_argument(target.source +
                                ": the target has no leg servo (IDs 7..18); no offset changes the "
                                "arm and head servos, so there is nothing to fit");
  detail::configure_block(problem, block.data(), fit, options.bounds);

  ceres::Solver::Options so = detail::levenberg_marquardt(options.max_iterations);
  so.function_tolerance = 1e-12;
  so.gradient_tolerance = 1e-12;
  so.parameter_tolerance = 1e-10;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  if (summary.termination_type == ceres::FAILURE)
    throw std::runtime_error(target.source + ": the fit failed: " + summary.message);

  detail::store_solution(report, block.data(), fit, options.bounds, options.decimals, summary);

  // residual scale: 1 count (the servo resolution) unless the fit itself is worse
  const int dof = legs - static_cast<int>(fit.size());
  double sigma2 = 1.0;
  if (dof > 0) sigma2 = std::max(1.0, 2.0 * summary.final_cost / dof);
  detail::analyse(problem, block.data(), fit, options.bounds, std::sqrt(sigma2), report);

  const auto after = posture_counts(target, report.fitted, options.ik);
  for (const joint_reading& j : target.joints) {
    joint_result r;
    r.id = j.id;
    r.posture = j.posture;
    r.target = j.count;
    const auto p = static_cast<std::size_t>(j.posture);
    r.model_before = before[p][static_cast<std::size_t>(j.id - 1)];
    r.model_after = after[p][static_cast<std::size_t>(j.id - 1)];
    r.fitted = is_leg_servo(j.id);
    if (r.fitted && std::abs(r.residual_after()) > 3.0 * options.loss_scale) {
      r.outlier = true;
      report.warnings.push_back(servo_name(j.id) + " (line " + std::to_string(j.line) +
                                "): residual " + fmt("%+.1f", r.residual_after()) +
                                " counts after the fit: an outlier, down-weighted by the loss");
    }
    if (!r.fitted && std::abs(r.residual_after()) > 3.0) {
      report.warnings.push_back(servo_name(j.id) + " (line " + std::to_string(j.line) +
                                "): the target differs from the gait's constant value by " +
                                fmt("%+.0f", -r.residual_after()) +
                                " counts; no offset changes this servo (not fitted)");
    }
    report.joints.push_back(r);
  }
  return report;
}

}  // namespace stride::calibration
