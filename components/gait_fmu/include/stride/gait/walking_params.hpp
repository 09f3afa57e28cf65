// Gait parameters of the DARwIn-OP walking generator ([Walking Config] keys) and the single table
// that describes them (INI reader/writer, range validation, FMU variable table).
#pragma once

#include <span>
#include <string_view>

namespace stride::gait {

/// Every [Walking Config] key of the ROBOTIS framework. The member initialisers are the framework's
/// constructor defaults (docs/walking-generator.md §2.2), which are also what the golden data uses.
struct walking_params {
  double x_offset = -10;                  ///< mm, constant foot x in the hip frame
  double y_offset = 5;                    ///< mm, lateral foot spacing (left +y/2, right -y/2)
  double z_offset = 20;                   ///< mm, constant leg shortening (crouch)
  double roll_offset = 0;                 ///< deg, foot roll (left +r/2, right -r/2)
  double pitch_offset = 0;                ///< deg, foot pitch (both feet)
  double yaw_offset = 0;                  ///< deg, foot yaw (left +a/2, right -a/2)
  double hip_pitch_offset = 13;           ///< deg, subtracted from both hip pitch angles
  double period_time = 600;               ///< ms, one cycle = two steps
  double dsp_ratio = 0.1;                 ///< fraction of the cycle in double support
  double step_forward_back_ratio = 0.28;  ///< fore-aft body swing = X * ratio
  double foot_height = 40;                ///< mm, swing foot lift
  double swing_right_left = 20;           ///< mm, lateral body sway amplitude
  double swing_top_down = 5;              ///< mm, vertical body bob amplitude
  double pelvis_offset = 3;               ///< deg, hip roll bump during single support
  double arm_swing_gain = 1.5;            ///< deg per mm of X
  double balance_knee_gain = 0.3;
  double balance_ankle_pitch_gain = 0.9;
  double balance_hip_roll_gain = 0.5;
  double balance_ankle_roll_gain = 1.0;
  int p_gain = 32;  ///< MX-28 gain registers written to the leg servos (7..18)
  int i_gain = 0;
  int d_gain = 0;
};

/// Its fields, for the gait FMU's state image (stride/sdk/state_fields.hpp).
template <class F>
void state_fields(walking_params& p, F&& f) {
  f(p.x_offset, p.y_offset, p.z_offset, p.roll_offset, p.pitch_offset, p.yaw_offset,
    p.hip_pitch_offset, p.period_time, p.dsp_ratio, p.step_forward_back_ratio, p.foot_height,
    p.swing_right_left, p.swing_top_down, p.pelvis_offset, p.arm_swing_gain, p.balance_knee_gain,
    p.balance_ankle_pitch_gain, p.balance_hip_roll_gain, p.balance_ankle_roll_gain, p.p_gain,
    p.i_gain, p.d_gain);
}

/// One row of the parameter table. Exactly one of `real_member` / `int_member` is non-null.
struct param_info {
  const char* key;                      ///< INI key == FMI variable name, e.g. "period_time"
  double walking_params::*real_member;  ///< non-null for real parameters
  int walking_params::*int_member;      ///< non-null for the integer gains
  const char* unit;                     ///< "mm", "deg", "ms", "" ...
  double min, max;                      ///< valid range (+-infinity where unbounded)
  bool min_exclusive, max_exclusive;    ///< e.g. period_time > 0, dsp_ratio < 1
  const char* latch;  ///< "live" (every tick), "half" (t = 0, T/2), "quarter" (T/4, 3T/4)
  const char* description;
};

/// All 22 parameters in [Walking Config] order (the order the writer uses).
std::span<const param_info> walking_param_table();

/// Case-insensitive lookup by INI key; nullptr if the key is unknown.
const param_info* find_param(std::string_view key);

/// Throws std::invalid_argument naming the key when `value` is NaN/inf, outside the valid range
/// or (for the integer gains) not an integer.
void check_param_value(const param_info& info, double value);

/// check_param_value() for every member of `params`.
void check_params(const walking_params& params);

/// The value of one parameter as double (integers converted).
double get_param(const walking_params& params, const param_info& info);

/// Sets one parameter after check_param_value(); integer gains must be integral.
void set_param(walking_params& params, const param_info& info, double value);

}  // namespace stride::gait
