// The settled posture of gait.fmu + robot.fmu standing still, run through the orchestrator
// library. Every evaluation starts from the same snapshot: fresh instances of the once-loaded
// FMUs, i.e. the robot standing in its start pose at the origin, so the result is a deterministic
// function of the offsets.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "stride/calibration/offsets.hpp"
#include "stride/cosim/log.hpp"
#include "stride/cosim/system_structure.hpp"
#include "stride/gait/kinematics.hpp"
#include "stride/gait/walking_params.hpp"

namespace stride::calibration {

/// The built-in standing system: components "gait" (bundled gait.fmu, not walking, gyro
/// feedback off) and "robot" (bundled robot.fmu), joint angles connected by servo ID, the gyro
/// fed back with one step delay, 8 ms base step, nothing recorded.
cosim::system_structure make_standing_system();

/// How the plant is simulated.
struct plant_options {
  /// A system with components named "gait" and "robot" (e.g. a copy of models/walk.xml);
  /// nullopt = make_standing_system(). gait.walking is forced to false, every [Walking Config]
  /// parameter and ik_mode are set from the calibration, recording is switched off.
  std::optional<cosim::system_structure> system;
  std::vector<std::filesystem::path> fmu_search_path;  ///< empty = cosim::default_fmu_search_path()
  cosim::log_sink log;     ///< component messages; empty = warnings on stderr
  double settle_s = 1.0;   ///< simulated time per evaluation
  double average_s = 0.2;  ///< averaging window at the end
};

/// What the settled robot looks like (averages over the window).
struct plant_posture {
  double pitch_deg = 0;  ///< torso pitch, + forward
  double roll_deg = 0;
  double height_m = 0;                     ///< torso origin z
  double com_x = 0, com_y = 0;             ///< whole-body CoM, world, m
  double support_x = 0, support_y = 0;     ///< centre of the support polygon, world, m
  double left_force = 0, right_force = 0;  ///< normal foot forces, N
  bool fallen = false;
};

/// Settles the plant for given offsets. Not thread-safe; one instance per thread.
class plant_simulator {
 public:
  /// Loads the FMUs (once) and the robot's URDF (for the support polygon). Throws
  /// cosim::validation_error / fmu_import_error / robot::model_error naming what is wrong.
  plant_simulator(const plant_options& options, const gait::walking_params& params,
                  gait::ik_mode mode);
  ~plant_simulator();
  plant_simulator(const plant_simulator&) = delete;
  plant_simulator& operator=(const plant_simulator&) = delete;

  /// Runs one settle with `params` whose offsets are replaced by `offsets`. Throws
  /// std::domain_error when the standing foot targets are out of the leg's reach (the gait would
  /// silently keep its previous servo values) and cosim::error if a component fails.
  plant_posture settle(const offset_values& offsets);

  /// Number of settles run so far.
  std::int64_t evaluations() const noexcept;

 private:
  struct impl;
  std::unique_ptr<impl> impl_;
};

}  // namespace stride::calibration
