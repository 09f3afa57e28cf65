// The plant profile: how a URDF robot is simulated and what its plant FMU shows (docs/
// plant-profile.md). A small XML file next to the URDF; every setting has a default, and a
// default that had to be guessed for the robot at hand is reported as a warning.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "stride/robot/robot_config.hpp"
#include "stride/robot/robot_model.hpp"

namespace stride::robot {

/// One numeric setting of robot_config: its name in the profile file (`element.attribute`), in
/// the FMU (parameter name) and where it lives. ONE list serves the profile reader, the FMU's
/// parameters and the docs.
struct plant_setting {
  const char* profile_name;  ///< e.g. "physics.step"
  const char* fmu_name;      ///< e.g. "physics_step"
  double& (*field)(robot_config&);
  const char* unit;
  double min;
  double max;
  const char* description;
};
std::span<const plant_setting> plant_settings();

/// Servo attributes set by one <servo joints="..."/> rule; unset ones are NaN.
struct servo_rule {
  std::vector<std::string> patterns;  ///< joint name patterns (* and ?)
  servo_config values;                ///< NaN = not set by this rule
  bool clamp_set = false;
  int line = 0;
};

/// Values of plant_settings() set in the file (NaN = not set), and servo rules.
struct profile_layer {
  std::vector<double> settings;
  std::vector<servo_rule> servos;
};

/// A board output: an integer or real the robot's electronics report, computed from the IMU as
/// gain·signal + offset and rounded (`rounding`): e.g. the CM-730's gyro counts.
struct board_channel {
  enum class source { gyro_x, gyro_y, gyro_z, acc_x, acc_y, acc_z };
  enum class rounding { none, floor, nearest };
  std::string name;
  source from = source::gyro_x;
  double gain = 1.0;
  double offset = 0.0;
  rounding round = rounding::none;  ///< none: a Real output; otherwise an Integer output
  std::string description;
};

/// An output of the normal floor force on a link, N.
struct contact_output {
  std::string name;
  std::string link;
};

/// Joints simulated as welds at their initial angle, optionally behind a Boolean parameter.
struct weld_group {
  std::vector<std::string> patterns;
  std::string parameter;  ///< "" = always welded
  std::string description;
};

/// A named variant of the settings and servo rules, selected by a String parameter.
struct profile_preset {
  std::string name;
  profile_layer layer;
};

struct plant_profile {
  std::string source;  ///< file (or label) for messages
  std::string name;
  profile_layer base;
  /// Array order of the joint variables: "urdf" (document order) or "servo_id" (the URDF's
  /// <servo id> tags, which must then number 1..N).
  std::string joint_order = "urdf";
  std::vector<std::string> passive;  ///< joint patterns without a servo
  std::vector<weld_group> welds;
  std::vector<std::pair<std::string, double>> pose;  ///< initial position by joint pattern
  std::string imu_link;                              ///< "" = the root link (guessed)
  std::string left_foot;
  std::string right_foot;
  std::vector<board_channel> board;
  std::vector<contact_output> contact_forces;
  std::string preset_parameter = "preset";
  std::vector<profile_preset> presets;
  std::string default_preset;  ///< "" when there are no presets
};

/// Reads a profile file. Throws model_error naming the file, line and element for anything
/// malformed or unknown.
plant_profile load_plant_profile(const std::string& path);
plant_profile parse_plant_profile(const std::string& xml, const std::string& source);
/// The profile of a robot without a profile file: every default guessed.
plant_profile default_plant_profile();

/// The profile applied to a model.
struct resolved_plant {
  robot_config config;                        ///< without urdf_path
  std::vector<int> actuated;                  ///< model joint indices, in array order
  std::vector<std::vector<int>> weld_joints;  ///< per weld group: the servo IDs it welds
  std::vector<std::string> warnings;          ///< defaults that had to be guessed
};

/// Resolves `profile` for `model` with preset `preset` ("" = the default), the explicitly set
/// plant_settings() `overrides` (NaN = not set, else applied last, to every servo for servo
/// settings) and the weld switches `welds_on` (per weld group). Throws model_error for a
/// profile that does not fit the model (unknown joint or link, no match for a pattern).
resolved_plant resolve_plant(const plant_profile& profile, const robot_model& model,
                             std::string_view preset, std::span<const double> overrides = {},
                             std::span<const bool> welds_on = {});

}  // namespace stride::robot
