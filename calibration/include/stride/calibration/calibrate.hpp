// Fits the DARwIn-OP walking offsets to a static posture with Ceres (docs/calibration.md).
//
//  - fit_joint_posture: the gait generator's standing output (stride::gait::standing_servo_counts,
//    the code of gait.fmu, autodiff through the templated IK) against a joint posture, one residual
//    per joint in servo counts with a Cauchy loss so that one bad servo does not drag the fit;
//  - fit_plant_posture: the settled gait + robot plant (plant_simulator) against a plant target,
//    central differences.
// Both report the offsets before/after, the residuals before/after, the final cost and the
// uncertainty of each fitted offset from the Ceres covariance, with a warning for every offset the
// target does not determine.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "stride/calibration/offsets.hpp"
#include "stride/calibration/plant.hpp"
#include "stride/calibration/targets.hpp"
#include "stride/gait/kinematics.hpp"
#include "stride/gait/walking_params.hpp"

namespace stride::calibration {

/// Settings shared by both modes.
struct fit_options {
  /// Indices into offset_table() to fit; empty = the mode's default (joints: all seven; plant:
  /// the offsets that drive the given targets, see default_plant_selection()).
  std::vector<std::size_t> fit;
  gait::ik_mode ik = gait::ik_mode::darwin;
  offset_bounds bounds = offset_bounds::defaults();
  /// Joint mode: scale of the Cauchy loss, counts (residuals well above it are down-weighted).
  double loss_scale = 2.0;
  /// Joint mode: solver iterations (the plant mode takes plant_target::max_iterations).
  int max_iterations = 100;
  /// Fitted values are rounded to this many decimals before they are written and re-evaluated.
  int decimals = 4;
};

/// One offset in the report.
struct offset_result {
  std::size_t index = 0;  ///< into offset_table()
  double before = 0, after = 0;
  bool fitted = false;
  /// 1-sigma uncertainty from the covariance (fitted and identifiable only), in the unit.
  double stddev = 0;
  /// False when the target does not determine this offset (then stddev means nothing).
  bool identifiable = true;
  bool at_bound = false;
  std::string note;  ///< why not identifiable, or which bound was hit
};

/// One joint in a joint-mode report (counts).
struct joint_result {
  int id = 0;
  int posture = 0;  ///< index into joint_target::postures
  double target = 0;
  double model_before = 0, model_after = 0;  ///< untruncated gait output
  bool fitted = true;    ///< false: no offset changes this servo (arms, head); not in the cost
  bool outlier = false;  ///< |residual after| > 3 * loss scale: down-weighted by the loss
  double residual_before() const { return model_before - target; }
  double residual_after() const { return model_after - target; }
};

/// One residual in a plant-mode report.
struct plant_result {
  std::string name;  ///< "pitch_deg", "roll_deg", "height_m", "com_dx_m", "com_dy_m"
  double target = 0;
  double before = 0, after = 0;
  double sigma = 0;
};

struct calibration_report {
  std::string mode;  ///< "joints" or "plant"
  std::string target_source;
  gait::ik_mode ik = gait::ik_mode::darwin;
  std::vector<offset_result> offsets;       ///< all seven, table order
  std::vector<joint_result> joints;         ///< joint mode, by posture then ID
  std::vector<posture> postures;            ///< joint mode: the target's postures
  std::vector<plant_result> plant;          ///< plant mode
  double initial_cost = 0, final_cost = 0;  ///< Ceres cost (1/2 sum of robust squared residuals)
  int iterations = 0;
  std::string termination;  ///< Ceres termination message
  bool converged = false;
  std::int64_t evaluations = 0;  ///< plant settles
  std::vector<std::string> warnings;
  gait::walking_params fitted;  ///< the input parameters with the fitted offsets (rounded)
};

/// Joint mode. Throws std::invalid_argument for a start value outside its bounds and
/// std::domain_error when the leg IK fails at the start values.
calibration_report fit_joint_posture(const joint_target& target, const gait::walking_params& start,
                                     const fit_options& options);

/// The plant mode's default selection: pitch -> hip_pitch_offset, height -> z_offset, CoM over
/// support -> x_offset. Torso roll has no default: the offsets move both legs as mirror images.
std::vector<std::size_t> default_plant_selection(const plant_target& target);

/// Plant mode. `plant.settle_s` and `plant.average_s` are taken from the target. Throws as
/// fit_joint_posture, and std::runtime_error when the robot falls at the start values.
calibration_report fit_plant_posture(const plant_target& target, const gait::walking_params& start,
                                     const fit_options& options, plant_options plant);

/// The report as text (offsets, residuals, cost, uncertainties, warnings).
std::string format_report(const calibration_report& report);

/// Reads `input` (a config.ini), sets the fitted offsets in its [Walking Config] section (other
/// keys, comments and order kept; a missing key is added) and writes `output`. Throws
/// gait::config_error naming the file.
void write_fitted_config(const std::filesystem::path& input, const std::filesystem::path& output,
                         const calibration_report& report);

}  // namespace stride::calibration
