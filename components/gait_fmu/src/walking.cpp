// The walking generator. Sections (§) refer to docs/walking-generator.md: §3 (clock and
// latching), §4 (trajectories), §7 (servo values), §8 (gyro feedback), §9 (start/stop, IK
// failure).
//
// Bit-exactness notes: every oscillator value is computed as A * sin(2pi/P * t - shift) + B with
// the operands in the framework's order (2pi as 2 * 3.141592, shifts with pi = 3.14159265). The
// sine values of the "hold" intervals only depend on the time latch, so they are computed once per
// latch; A * sin(x) + B is then the same double as the framework's. Truncations as in §7.2/§8.
#include "stride/gait/walking.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace stride::gait {
namespace {

using detail::osc_sin;

constexpr double half_tick = tick_ms / 2;  // the latch windows are [tp - 4, tp + 4)

/// C integer cast, made total: values far outside the servo range saturate instead of being UB.
inline int trunc_to_int(double v) {
  if (!(v > -1e9)) return -1000000000;  // also NaN (cannot happen after a successful IK)
  if (v > 1e9) return 1000000000;
  return static_cast<int>(v);
}

inline int clamp_count(int v) {
  return std::clamp(v, 0, servo_max);
}

enum class latch_kind { none, zero, quarter1, half, quarter3 };

latch_kind latch_at(const gait_timing& tm, double t) {
  if (t == 0) return latch_kind::zero;
  if (t >= tm.phase_time1 - half_tick && t < tm.phase_time1 + half_tick)
    return latch_kind::quarter1;
  if (t >= tm.phase_time2 - half_tick && t < tm.phase_time2 + half_tick) return latch_kind::half;
  if (t >= tm.phase_time3 - half_tick && t < tm.phase_time3 + half_tick)
    return latch_kind::quarter3;
  return latch_kind::none;
}

/// Framework update_param_move(): the quarter-point latch of commands and amplitudes.
void latch_amplitudes(walking_state& s, const walking_params& p) {
  gait_amplitudes& am = s.amplitudes;
  am.x_move = s.x_command;
  am.x_swing = s.x_command * p.step_forward_back_ratio;

  am.y_move = s.y_command / 2;
  am.y_move_shift = am.y_move > 0 ? am.y_move : -am.y_move;
  am.y_swing = p.swing_right_left + am.y_move_shift * 0.04;

  am.z_move = p.foot_height / 2;
  am.z_move_shift = am.z_move / 2;
  am.z_swing = p.swing_top_down;

  if (!s.aim_on) {
    am.a_move = s.a_command * framework_pi / 180.0 / 2;
    am.a_move_shift = am.a_move > 0 ? am.a_move : -am.a_move;
  } else {
    am.a_move = -s.a_command * framework_pi / 180.0 / 2;
    am.a_move_shift = am.a_move > 0 ? -am.a_move : am.a_move;
  }
}

/// At t = 0 and T/2 (§9.2): a stopped controller either freezes the clock (all latched amplitudes
/// zero) or zeroes the command inputs so that the next quarter latch brings the amplitudes to 0.
void stop_check(walking_state& s) {
  if (s.ctrl_running) return;
  const gait_amplitudes& am = s.amplitudes;
  if (am.x_move == 0 && am.y_move == 0 && am.a_move == 0) {
    s.real_running = false;
  } else {
    s.x_command = 0;
    s.y_command = 0;
    s.a_command = 0;
  }
}

/// §4.2 / §4.4: end points, arm swing and pelvis bump at gait time t.
gait_pose evaluate_pose(const walking_state& s, const walking_params& p, double t) {
  const gait_timing& tm = s.timing;
  const gait_amplitudes& am = s.amplitudes;

  // common-mode body swings
  const double x_swing = am.x_swing * osc_sin(tm.rate_x_swing, t, framework_pi) + 0.0;
  const double y_swing = am.y_swing * osc_sin(tm.rate_y_swing, t, 0.0) + 0.0;
  const double z_swing =
      am.z_swing * osc_sin(tm.rate_z_swing, t, framework_pi * 3 / 2) + am.z_swing;

  // stepping (x, y, yaw share one sine), foot lift and pelvis bump per interval
  double step = 0, lift_l = 0, lift_r = 0, pelvis_l = 0, pelvis_r = 0;
  if (t <= tm.ssp_start_l) {  // I0: double support
    step = tm.hold_step_l0;
    lift_l = tm.hold_lift_l0;
    lift_r = tm.hold_lift_r0;
  } else if (t <= tm.ssp_end_l) {  // I1: left swing
    step = osc_sin(tm.rate_step, t, tm.shift_step_l);
    lift_l = osc_sin(tm.rate_lift, t, tm.shift_lift_l);
    lift_r = tm.hold_lift_r0;
    pelvis_l = tm.pelvis_swing / 2 * lift_l + tm.pelvis_swing / 2;
    pelvis_r = -tm.pelvis_offset / 2 * lift_l + -tm.pelvis_offset / 2;
  } else if (t <= tm.ssp_start_r) {  // I2: double support
    step = tm.hold_step_l1;
    lift_l = tm.hold_lift_l1;
    lift_r = tm.hold_lift_r0;
  } else if (t <= tm.ssp_end_r) {  // I3: right swing
    step = osc_sin(tm.rate_step, t, tm.shift_step_r);
    lift_l = tm.hold_lift_l1;
    lift_r = osc_sin(tm.rate_lift, t, tm.shift_lift_r);
    pelvis_l = tm.pelvis_offset / 2 * lift_r + tm.pelvis_offset / 2;
    pelvis_r = -tm.pelvis_swing / 2 * lift_r + -tm.pelvis_swing / 2;
  } else {  // I4: double support
    step = tm.hold_step_r1;
    lift_l = tm.hold_lift_l1;
    lift_r = tm.hold_lift_r1;
  }
  const double x_move_l = am.x_move * step + 0.0;
  const double x_move_r = -am.x_move * step + -0.0;
  const double y_move_l = am.y_move * step + am.y_move_shift;
  const double y_move_r = -am.y_move * step + -am.y_move_shift;
  const double c_move_l = am.a_move * step + am.a_move_shift;
  const double c_move_r = -am.a_move * step + -am.a_move_shift;
  const double z_move_l = am.z_move * lift_l + am.z_move_shift;
  const double z_move_r = am.z_move * lift_r + am.z_move_shift;

  // live offsets (update_param_balance)
  const double roll = p.roll_offset * framework_pi / 180.0;
  const double pitch = p.pitch_offset * framework_pi / 180.0;
  const double yaw = p.yaw_offset * framework_pi / 180.0;

  gait_pose pose;
  pose.right = {x_swing + x_move_r + p.x_offset,
                y_swing + y_move_r - p.y_offset / 2,
                z_swing + z_move_r + p.z_offset,
                0.0 + 0.0 - roll / 2,
                0.0 + 0.0 + pitch,
                0.0 + c_move_r - yaw / 2};
  pose.left = {x_swing + x_move_l + p.x_offset,
               y_swing + y_move_l + p.y_offset / 2,
               z_swing + z_move_l + p.z_offset,
               0.0 + 0.0 + roll / 2,
               0.0 + 0.0 + pitch,
               0.0 + c_move_l + yaw / 2};
  if (t <= tm.ssp_end_l) {
    pose.body_swing_y = -pose.left.y;
    pose.body_swing_z = pose.left.z;
  } else {
    pose.body_swing_y = -pose.right.y;
    pose.body_swing_z = pose.right.z;
  }
  pose.body_swing_z -= leg_length;

  if (am.x_move == 0) {
    pose.arm_right_deg = 0;
    pose.arm_left_deg = 0;
  } else {
    const double arm_sin = osc_sin(tm.rate_arm, t, framework_pi * 1.5);
    pose.arm_right_deg = -am.x_move * tm.arm_swing_gain * arm_sin + 0.0;
    pose.arm_left_deg = am.x_move * tm.arm_swing_gain * arm_sin + 0.0;
  }
  pose.pelvis_right = pelvis_r;
  pose.pelvis_left = pelvis_l;
  return pose;
}

/// Throws (naming the key) if a live parameter is not finite; cheap path for every tick.
void check_live_finite(const walking_params& p) {
  const double sum = p.x_offset + p.y_offset + p.z_offset + p.roll_offset + p.pitch_offset +
                     p.yaw_offset + p.hip_pitch_offset + p.balance_knee_gain +
                     p.balance_ankle_pitch_gain + p.balance_hip_roll_gain +
                     p.balance_ankle_roll_gain;
  if (std::isfinite(sum)) return;
  for (const param_info& info : walking_param_table()) {
    if (info.real_member == nullptr) continue;
    const double v = p.*info.real_member;
    if (!std::isfinite(v)) check_param_value(info, v);  // throws
  }
  // only overflow of the sum: the values themselves are finite
}

}  // namespace

gait_timing make_gait_timing(const walking_params& p) {
  gait_timing tm{};
  tm.period = p.period_time;
  tm.dsp_ratio = p.dsp_ratio;
  tm.ssp_ratio = 1 - p.dsp_ratio;
  const double period = tm.period;
  const double ssp = tm.ssp_ratio;
  const double x_swing_period = period / 2;
  const double y_swing_period = period;
  const double z_swing_period = period / 2;
  const double step_period = period * ssp;      // x, y and yaw stepping
  const double lift_period = period * ssp / 2;  // foot lift and pelvis

  tm.ssp_start_l = (1 - ssp) * period / 4;
  tm.ssp_end_l = (1 + ssp) * period / 4;
  tm.ssp_start_r = (3 - ssp) * period / 4;
  tm.ssp_end_r = (3 + ssp) * period / 4;
  tm.phase_time1 = (tm.ssp_end_l + tm.ssp_start_l) / 2;
  tm.phase_time2 = (tm.ssp_start_r + tm.ssp_end_l) / 2;
  tm.phase_time3 = (tm.ssp_end_r + tm.ssp_start_r) / 2;

  tm.pelvis_offset = p.pelvis_offset * counts_per_degree;
  tm.pelvis_swing = tm.pelvis_offset * 0.35;
  tm.arm_swing_gain = p.arm_swing_gain;

  constexpr double osc_two_pi = 2 * oscillator_pi;
  tm.rate_x_swing = osc_two_pi / x_swing_period;
  tm.rate_y_swing = osc_two_pi / y_swing_period;
  tm.rate_z_swing = osc_two_pi / z_swing_period;
  tm.rate_step = osc_two_pi / step_period;
  tm.rate_lift = osc_two_pi / lift_period;
  tm.rate_arm = osc_two_pi / period;

  constexpr double half_pi = framework_pi / 2;
  tm.shift_step_l = half_pi + 2 * framework_pi / step_period * tm.ssp_start_l;
  tm.shift_step_r = half_pi + 2 * framework_pi / step_period * tm.ssp_start_r + framework_pi;
  tm.shift_lift_l = half_pi + 2 * framework_pi / lift_period * tm.ssp_start_l;
  tm.shift_lift_r = half_pi + 2 * framework_pi / lift_period * tm.ssp_start_r;

  tm.hold_step_l0 = osc_sin(tm.rate_step, tm.ssp_start_l, tm.shift_step_l);
  tm.hold_step_l1 = osc_sin(tm.rate_step, tm.ssp_end_l, tm.shift_step_l);
  tm.hold_step_r1 = osc_sin(tm.rate_step, tm.ssp_end_r, tm.shift_step_r);
  tm.hold_lift_l0 = osc_sin(tm.rate_lift, tm.ssp_start_l, tm.shift_lift_l);
  tm.hold_lift_l1 = osc_sin(tm.rate_lift, tm.ssp_end_l, tm.shift_lift_l);
  tm.hold_lift_r0 = osc_sin(tm.rate_lift, tm.ssp_start_r, tm.shift_lift_r);
  tm.hold_lift_r1 = osc_sin(tm.rate_lift, tm.ssp_end_r, tm.shift_lift_r);
  return tm;
}

walking::walking(ik_mode mode) : mode_(mode) {
  if (mode != ik_mode::darwin && mode != ik_mode::geometric)
    throw std::invalid_argument("walking: unknown ik_mode " +
                                std::to_string(static_cast<int>(mode)));
}

walking_state walking::initialize(const walking_params& params) const {
  check_params(params);
  walking_state s{};
  // JointData defaults (centre), then the constant angles set by the framework's constructor
  std::fill(std::begin(s.servo_count), std::end(s.servo_count), servo_center);
  s.servo_count[2] = detail::angle_to_value(detail::r_shoulder_roll_deg);
  s.servo_count[3] = detail::angle_to_value(detail::l_shoulder_roll_deg);
  s.servo_count[4] = detail::angle_to_value(detail::r_elbow_deg);
  s.servo_count[5] = detail::angle_to_value(detail::l_elbow_deg);
  s.servo_count[19] = detail::angle_to_value(detail::head_tilt_deg);

  s.x_command = s.y_command = s.a_command = 0;
  s.aim_on = false;
  s.ctrl_running = false;
  s.real_running = false;
  s.time_ms = 0;
  s.eval_time_ms = 0;
  s.phase = 0;
  s.footsteps = 0;
  s.moved_since_centre = false;
  s.ik_failed = false;
  s.timing = make_gait_timing(params);
  latch_amplitudes(s, params);
  tick(s, params, walking_feedback{});  // the framework's Initialize() ends with one Process()
  return s;
}

void walking::start(walking_state& s) const {
  if (!s.real_running) {
    s.footsteps = 0;
    s.moved_since_centre = false;
  }
  s.ctrl_running = true;
  s.real_running = true;
}

void walking::stop(walking_state& s) const {
  s.ctrl_running = false;
}

void walking::set_command(walking_state& s, double x_mm, double y_mm, double a_deg,
                          bool aim_on) const {
  if (!std::isfinite(x_mm) || !std::isfinite(y_mm) || !std::isfinite(a_deg))
    throw std::invalid_argument(
        "walking::set_command: X, Y and A must be finite (got X=" + std::to_string(x_mm) +
        ", Y=" + std::to_string(y_mm) + ", A=" + std::to_string(a_deg) + ")");
  s.x_command = x_mm;
  s.y_command = y_mm;
  s.a_command = a_deg;
  s.aim_on = aim_on;
}

void walking::tick(walking_state& s, const walking_params& p, const walking_feedback& fb) const {
  // validate first so that a throw leaves the state untouched
  const latch_kind latch = latch_at(s.timing, s.time_ms);
  if (latch == latch_kind::none)
    check_live_finite(p);
  else
    check_params(p);

  // 1.-4. clock update and latching (§3)
  double t = s.time_ms;
  bool centre = false;
  switch (latch) {
    case latch_kind::zero:
      s.timing = make_gait_timing(p);
      s.phase = 0;
      stop_check(s);
      centre = true;
      break;
    case latch_kind::quarter1:
      latch_amplitudes(s, p);
      s.phase = 1;
      break;
    case latch_kind::half:
      s.timing = make_gait_timing(p);
      t = s.timing.phase_time2;  // snap to the (new) T/2
      s.phase = 2;
      stop_check(s);
      centre = true;
      break;
    case latch_kind::quarter3:
      latch_amplitudes(s, p);
      s.phase = 3;
      break;
    case latch_kind::none:
      break;
  }
  if (centre && s.moved_since_centre) {
    ++s.footsteps;
    s.moved_since_centre = false;
  }

  // 5.-6. trajectories at the (possibly snapped) t
  s.pose = evaluate_pose(s, p, t);
  s.eval_time_ms = t;

  // 7. advance the clock; the outputs belong to the time before the increment
  if (s.real_running) {
    t += tick_ms;
    if (t >= s.timing.period) t = 0;
    s.moved_since_centre = true;
  }
  s.time_ms = t;

  // 8. IK; on failure all servo values keep the previous tick's values (§9.4)
  double angle[14];
  if (!leg_ik(s.pose.right, mode_, angle) || !leg_ik(s.pose.left, mode_, angle + 6)) {
    s.ik_failed = true;
    return;
  }
  s.ik_failed = false;
  constexpr double rad_to_deg = 180.0 / framework_pi;
  for (int i = 0; i < 12; ++i) angle[i] *= rad_to_deg;
  angle[12] = s.pose.arm_right_deg;
  angle[13] = s.pose.arm_left_deg;

  // §7.2 servo values
  const double hip_pitch_counts = p.hip_pitch_offset * counts_per_degree;
  int out[14];
  for (int i = 0; i < 14; ++i) {
    const double dir = detail::driven_dir[i];
    double offset = dir * angle[i] * counts_per_degree;
    if (i == 1)
      offset += dir * s.pose.pelvis_right;
    else if (i == 7)
      offset += dir * s.pose.pelvis_left;
    else if (i == 2 || i == 8)
      offset -= dir * hip_pitch_counts;
    out[i] = detail::angle_to_value(detail::driven_base_deg[i]) + trunc_to_int(offset);
  }

  // §8 gyro feedback, each term truncated separately
  if (fb.balance_on) {
    const double rl = fb.gyro_rl;
    const double fbg = fb.gyro_fb;
    const auto d = [](int i) { return static_cast<double>(detail::driven_dir[i]); };
    out[1] += trunc_to_int(d(1) * rl * p.balance_hip_roll_gain * 4);
    out[7] += trunc_to_int(d(7) * rl * p.balance_hip_roll_gain * 4);
    out[3] -= trunc_to_int(d(3) * fbg * p.balance_knee_gain * 4);
    out[9] -= trunc_to_int(d(9) * fbg * p.balance_knee_gain * 4);
    out[4] -= trunc_to_int(d(4) * fbg * p.balance_ankle_pitch_gain * 4);
    out[10] -= trunc_to_int(d(10) * fbg * p.balance_ankle_pitch_gain * 4);
    out[5] -= trunc_to_int(d(5) * rl * p.balance_ankle_roll_gain * 4);
    out[11] -= trunc_to_int(d(11) * rl * p.balance_ankle_roll_gain * 4);
  }
  for (int i = 0; i < 14; ++i) s.servo_count[detail::driven_servo_id[i] - 1] = clamp_count(out[i]);

  // head pan follows the raw A command (angle clamped to +-180 deg, value to the servo range)
  const double pan = std::clamp(s.a_command, -180.0, 180.0);
  s.servo_count[18] = clamp_count(detail::angle_to_value(pan));
}

bool is_running(const walking_state& s) {
  return s.real_running;
}
double phase_ms(const walking_state& s) {
  return s.eval_time_ms;
}
int current_phase(const walking_state& s) {
  return s.phase;
}
int footsteps(const walking_state& s) {
  return s.footsteps;
}
const gait_pose& last_pose(const walking_state& s) {
  return s.pose;
}
bool last_tick_ik_failed(const walking_state& s) {
  return s.ik_failed;
}

}  // namespace stride::gait
