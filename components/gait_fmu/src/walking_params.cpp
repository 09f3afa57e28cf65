#include "stride/gait/walking_params.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "text_util.hpp"

namespace stride::gait {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

constexpr param_info real(const char* key, double walking_params::*member, const char* unit,
                          double min, double max, bool min_exclusive, bool max_exclusive,
                          const char* latch, const char* description) {
  return {key, member, nullptr, unit, min, max, min_exclusive, max_exclusive, latch, description};
}

constexpr param_info integer(const char* key, int walking_params::*member,
                             const char* description) {
  // MX-28 gain registers are one byte, 0..254
  return {key, nullptr, member, "", 0, 254, false, false, "live", description};
}

// Ranges: only what makes the generator meaningless or undefined is excluded (period_time <= 0,
// dsp_ratio outside [0, 1), negative lift/sway amplitudes, angles beyond +-180 deg).
constexpr std::array<param_info, 22> table{{
    real("x_offset", &walking_params::x_offset, "mm", -inf, inf, false, false, "live",
         "constant foot x in the hip frame (negative: feet behind the hips)"),
    real("y_offset", &walking_params::y_offset, "mm", -inf, inf, false, false, "live",
         "lateral foot spacing added: left +y/2, right -y/2"),
    real("z_offset", &walking_params::z_offset, "mm", -inf, inf, false, false, "live",
         "constant leg shortening (crouch depth)"),
    real("roll_offset", &walking_params::roll_offset, "deg", -180, 180, false, false, "live",
         "foot roll: left +r/2, right -r/2"),
    real("pitch_offset", &walking_params::pitch_offset, "deg", -180, 180, false, false, "live",
         "foot pitch, both feet"),
    real("yaw_offset", &walking_params::yaw_offset, "deg", -180, 180, false, false, "live",
         "foot yaw: left +a/2, right -a/2 (positive: toes out)"),
    real("hip_pitch_offset", &walking_params::hip_pitch_offset, "deg", -180, 180, false, false,
         "live", "subtracted from both hip pitch angles (trunk leans forward)"),
    real("period_time", &walking_params::period_time, "ms", 0, inf, true, false, "half",
         "full gait cycle = two steps (left swing, then right swing)"),
    real("dsp_ratio", &walking_params::dsp_ratio, "", 0, 1, false, true, "half",
         "fraction of the cycle in double support"),
    real("step_forward_back_ratio", &walking_params::step_forward_back_ratio, "", -inf, inf, false,
         false, "quarter", "fore-aft body swing amplitude = X * ratio"),
    real("foot_height", &walking_params::foot_height, "mm", 0, inf, false, false, "quarter",
         "swing foot lift (peak to peak)"),
    real("swing_right_left", &walking_params::swing_right_left, "mm", 0, inf, false, false,
         "quarter", "lateral body sway amplitude"),
    real("swing_top_down", &walking_params::swing_top_down, "mm", 0, inf, false, false, "quarter",
         "vertical body bob amplitude (peak to peak 2x)"),
    real("pelvis_offset", &walking_params::pelvis_offset, "deg", -180, 180, false, false, "half",
         "extra hip roll bump during single support"),
    real("arm_swing_gain", &walking_params::arm_swing_gain, "deg/mm", -inf, inf, false, false,
         "half", "shoulder pitch swing amplitude = X * gain"),
    real("balance_knee_gain", &walking_params::balance_knee_gain, "", -inf, inf, false, false,
         "live", "front/back gyro -> knees"),
    real("balance_ankle_pitch_gain", &walking_params::balance_ankle_pitch_gain, "", -inf, inf,
         false, false, "live", "front/back gyro -> ankle pitch"),
    real("balance_hip_roll_gain", &walking_params::balance_hip_roll_gain, "", -inf, inf, false,
         false, "live", "right/left gyro -> hip roll"),
    real("balance_ankle_roll_gain", &walking_params::balance_ankle_roll_gain, "", -inf, inf, false,
         false, "live", "right/left gyro -> ankle roll"),
    integer("p_gain", &walking_params::p_gain, "P gain written to the leg servos 7..18"),
    integer("i_gain", &walking_params::i_gain, "I gain written to the leg servos 7..18"),
    integer("d_gain", &walking_params::d_gain, "D gain written to the leg servos 7..18"),
}};

std::string bound_text(const param_info& info, bool lower) {
  const double bound = lower ? info.min : info.max;
  const bool exclusive = lower ? info.min_exclusive : info.max_exclusive;
  std::string s = lower ? (exclusive ? "> " : ">= ") : (exclusive ? "< " : "<= ");
  s += detail::format_double(bound);
  if (*info.unit != '\0') {
    s += ' ';
    s += info.unit;
  }
  return s;
}

}  // namespace

std::span<const param_info> walking_param_table() {
  return table;
}

const param_info* find_param(std::string_view key) {
  for (const param_info& info : table)
    if (detail::iequals(info.key, key)) return &info;
  return nullptr;
}

void check_param_value(const param_info& info, double value) {
  const auto fail = [&](const std::string& why) {
    throw std::invalid_argument("walking parameter '" + std::string(info.key) +
                                "' = " + detail::format_double(value) + ": " + why);
  };
  if (!std::isfinite(value)) fail("not a finite number");
  if (info.int_member != nullptr && value != std::trunc(value)) fail("must be an integer");
  const bool low = info.min_exclusive ? !(value > info.min) : !(value >= info.min);
  const bool high = info.max_exclusive ? !(value < info.max) : !(value <= info.max);
  if (low) fail("must be " + bound_text(info, true));
  if (high) fail("must be " + bound_text(info, false));
}

void check_params(const walking_params& params) {
  for (const param_info& info : table) check_param_value(info, get_param(params, info));
}

double get_param(const walking_params& params, const param_info& info) {
  return info.real_member != nullptr ? params.*info.real_member
                                     : static_cast<double>(params.*info.int_member);
}

void set_param(walking_params& params, const param_info& info, double value) {
  check_param_value(info, value);
  if (info.real_member != nullptr)
    params.*info.real_member = value;
  else
    params.*info.int_member = static_cast<int>(value);
}

}  // namespace stride::gait
