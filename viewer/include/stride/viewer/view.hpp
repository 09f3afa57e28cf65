// `stride view`: one self-contained HTML page that replays a run's robot in 3-D (WebGL,
// three.js inlined), posed from the recorded base pose and joint angles by forward kinematics
// on the URDF the run used (docs/viewer.md).
#ifndef STRIDE_VIEWER_VIEW_HPP
#define STRIDE_VIEWER_VIEW_HPP

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace stride::viewer {

/// The file `stride run --record-view` writes into the run folder, and its default interval (a
/// multiple of the walk's 8 ms step near 1/30 s).
inline constexpr const char* k_view_file = "view.csv";
inline constexpr const char* k_view_interval = "0.032";

/// What the viewer needs of a plant component P, as `stride run` record patterns: P.base_x/y/z,
/// P.roll/pitch/yaw, P.joint_angle[*] and P.fallen for every component that has them.
std::vector<std::string> view_signal_patterns();

struct view_options {
  std::filesystem::path run_dir;
  /// empty: RUN_DIR/view.html
  std::filesystem::path output;
  /// window of the run, seconds (nullopt: from the start / to the end)
  std::optional<double> from;
  std::optional<double> to;
  /// recorded frames kept per simulated second at most (larger runs are decimated); 0 = all
  double fps = 30;
  /// the pose prefix P to show (a component name); empty = the first one recorded
  std::string robot;
  /// the URDF to draw; empty = the one the run used (system.xml and the component's FMU)
  std::filesystem::path urdf;
  /// frames in the page at most: a longer window is thinned evenly (0: no limit)
  std::size_t max_frames = 20000;
  /// a column whose runs of equal values the page offers to replay one by one (a learner's
  /// episodes or RL steps); empty = the first column named `*.episode`, if any
  std::string episodes;
  /// replay only the rows at which the `episodes` column has this value (e.g. episode 120)
  std::optional<double> episode;
  /// columns shown in the panel as they change (patterns with * and ?); empty = every column
  /// named `*.episode`, `*.rl_step` or `*.value[*]` (a learner's state), if any
  std::vector<std::string> state;
};

struct view_report {
  std::filesystem::path output;
  std::filesystem::path results;  ///< the CSV the frames came from
  std::filesystem::path urdf;     ///< where the robot model came from (inside the FMU: a label)
  std::string robot;              ///< the pose prefix shown
  std::size_t frames = 0;
  std::size_t bytes = 0;
  std::vector<double> falls;  ///< times at which `P.fallen` became true
  std::size_t episodes = 0;   ///< spans of view_options::episodes in the page
};

/// Writes the page. \throws std::runtime_error (cosim::validation_error for what the user can
/// fix) naming what is missing: no run folder, no recorded pose or joint angles (and how to
/// record them), no URDF, a URDF the plant could not load.
view_report write_view(const view_options& options);

}  // namespace stride::viewer

#endif  // STRIDE_VIEWER_VIEW_HPP
