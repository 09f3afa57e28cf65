// Calibration targets: a standing joint posture (CSV) and a settled plant posture (INI).
//
// Joint posture (docs/calibration.md): a CSV file with a header; column `id` (servo ID 1..20,
// any subset, each at most once per posture) and exactly one of `count` (MX-28 counts, 2048 =
// 0 deg), `deg` or `rad` (URDF/Webots joint convention, (count - 2048) * 0.088 deg). Optional
// columns `delta_<offset>` (e.g. delta_z_offset) give, per row, how far that offset was moved from
// the unknown calibrated value when the posture was recorded; rows with equal deltas form one
// posture. Several postures make all seven offsets identifiable. Other columns are ignored; blank
// lines and lines starting with '#' are skipped.
//
// Plant posture: an INI file with a [Plant Target] section (pitch_deg, roll_deg, height_m,
// com_over_support and their *_sigma_* scales) and an optional [Settle] section (time_s,
// average_s, max_iterations).
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "stride/calibration/offsets.hpp"

namespace stride::calibration {

/// A malformed or invalid target file; the message starts with "file:line: " (or "file: ").
class target_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Unit of the joint values of a target file.
enum class angle_unit { count, deg, rad };

/// Column name of a unit ("count", "deg", "rad").
std::string_view to_string(angle_unit unit) noexcept;

/// A value in `unit` as (untruncated) MX-28 counts, and back.
double to_counts(double value, angle_unit unit);
double from_counts(double counts, angle_unit unit);

/// One joint of a posture target.
struct joint_reading {
  int id = 0;          ///< servo ID 1..20
  double count = 0.0;  ///< the value converted to servo counts (not rounded)
  int line = 0;        ///< line in the target file
  int posture = 0;     ///< index into joint_target::postures
};

/// One recorded posture: the offsets commanded on the robot were the calibrated ones plus `delta`.
struct posture {
  offset_values delta{};  ///< offset_table() order, mm / deg; all zero for a plain target
  int line = 0;           ///< first line of the posture in the target file
};

/// Standing postures as a robot reports them.
struct joint_target {
  std::string source;  ///< file name, for messages
  angle_unit unit = angle_unit::count;
  std::vector<posture> postures;      ///< in order of first appearance; at least one
  std::vector<joint_reading> joints;  ///< by posture, then ascending ID
};

/// Parses a joint target; `source` names it in messages. Throws target_error naming source and
/// line for: a missing/ambiguous header, an unknown `delta_` column, a row with the wrong number
/// of fields, a non-integer or unknown ID (outside 1..20), a duplicate ID in one posture, a
/// non-numeric or non-finite value or delta, a value outside the servo range 0..4095 counts, and
/// a file without joint rows.
joint_target parse_joint_target(std::string_view text, const std::string& source);
/// Reads and parses a file; an unreadable file is a target_error.
joint_target read_joint_target(const std::filesystem::path& file);

/// The recording plan of docs/calibration.md: 27 deltas, x_offset -30/0/+30 mm x z_offset
/// -10/+5/+20 mm x y_offset -15/0/+15 mm (x slowest). With the 12 leg servos of each posture read
/// to +-1 count, it determines all seven offsets to better than a third of 0.5 mm / 0.2 deg.
std::vector<offset_values> recommended_posture_plan();

/// What the settled plant should look like, with the scale (1 sigma) of each residual.
struct plant_target {
  std::string source;
  std::optional<double> pitch_deg;  ///< torso pitch, deg (+ leaning forward)
  std::optional<double> roll_deg;   ///< torso roll, deg
  std::optional<double> height_m;   ///< torso (root link) origin above the floor, m
  bool com_over_support = false;    ///< whole-body CoM over the centre of the support polygon
  double pitch_sigma_deg = 0.2;
  double roll_sigma_deg = 0.2;
  double height_sigma_m = 0.002;
  double com_sigma_m = 0.002;
  double settle_s = 1.0;    ///< simulated settle time per evaluation (whole 8 ms steps)
  double average_s = 0.2;   ///< outputs averaged over the last average_s of the settle
  int max_iterations = 20;  ///< solver iterations

  /// Number of residuals (com_over_support counts two: x and y).
  int residual_count() const;
};

/// Parses a plant target. Throws target_error naming source and line for: a line that is not
/// "key = value", an entry outside the two sections, an unknown or repeated key, a non-numeric
/// or out-of-range value, and a file that sets no target.
plant_target parse_plant_target(std::string_view text, const std::string& source);
/// Reads and parses a file; an unreadable file is a target_error.
plant_target read_plant_target(const std::filesystem::path& file);

}  // namespace stride::calibration
