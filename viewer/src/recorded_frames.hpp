// The frames a page replays, read from a run's CSV: time, base pose, joint angles by servo ID
// and the fall flag of one pose prefix P, decimated and cut to a window.
#ifndef STRIDE_VIEWER_RECORDED_FRAMES_HPP
#define STRIDE_VIEWER_RECORDED_FRAMES_HPP

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace stride::viewer {

/// Columns, by name, a pose prefix P needs besides its joint angles.
inline constexpr const char* k_pose_columns[] = {"base_x", "base_y", "base_z",
                                                 "roll",   "pitch",  "yaw"};

struct frame_selection {
  std::optional<double> from;
  std::optional<double> to;
  double fps = 30;  ///< 0 = every row
  /// a column whose runs of equal values are spans the page offers (a learner's episode)
  std::string span_column;
};

/// A run of rows with the same value of frame_selection::span_column.
struct value_span {
  double value = 0;
  double from = 0;
  double to = 0;
};

struct recorded_frames {
  std::string prefix;
  std::vector<double> t, x, y, z, roll, pitch, yaw;
  /// joint angles by servo ID − 1 for the IDs asked for (others stay empty)
  std::vector<std::vector<double>> q;
  std::vector<int> fallen;    ///< empty when P.fallen was not recorded
  std::vector<double> falls;  ///< times at which P.fallen became true (every row, not decimated)
  /// extra columns shown as they change (learner state), by name
  std::vector<std::pair<std::string, std::vector<double>>> state;
  std::vector<value_span> spans;  ///< of frame_selection::span_column (every row in the window)
};

/// Keeps every `k`-th frame (and every frame at which the robot falls) so that at most
/// `max_frames` remain.
void thin_frames(recorded_frames& frames, std::size_t max_frames);

/// The times of the rows of `file` at which `column` equals `value`: the first and the last.
/// \throws cosim::validation_error when there is no such column or row.
value_span find_span(const std::filesystem::path& file, const std::string& column, double value);

/// The header of a CSV file, split into column names.
std::vector<std::string> csv_header(const std::filesystem::path& file);

/// The pose prefixes of `columns` that have every k_pose_columns column, in column order.
std::vector<std::string> full_pose_prefixes(const std::vector<std::string>& columns);

/// Reads P's frames from `file`: rows inside the window, at most `fps` a second (the first row
/// of each 1/fps bin of time), and always the row at which P.fallen turns true. `servo_ids`: the
/// joint angle columns P.joint_angle[i] wanted; `state_columns`: extra columns to carry.
/// \throws cosim::validation_error naming missing columns, std::runtime_error naming file and
/// line for a value that is not a finite number.
recorded_frames read_frames(const std::filesystem::path& file, const std::string& prefix,
                            const std::vector<int>& servo_ids,
                            const std::vector<std::string>& state_columns,
                            const frame_selection& selection);

}  // namespace stride::viewer

#endif  // STRIDE_VIEWER_RECORDED_FRAMES_HPP
