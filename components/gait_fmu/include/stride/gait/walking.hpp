// The DARwIn-OP / ROBOTIS-OP walking generator (docs/walking-generator.md; § below refers to
// it), bit-exact to the ROBOTIS framework's servo output. Plain C++: the configuration (IK mode)
// lives in the const `walking` object, everything that evolves lives in the trivially copyable
// `walking_state`.
//
// Typical driver (the golden-data sequence):
//   walking gen;  walking_params p;  walking_state s = gen.initialize(p);   // standing pose
//   gen.set_command(s, 20, 0, 0, false);  gen.start(s);
//   every 8 ms: gen.set_command(s, x, y, a, aim);  gen.tick(s, p, feedback);  use s.servo_count
#pragma once

#include <array>
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "stride/gait/kinematics.hpp"
#include "stride/gait/walking_params.hpp"

namespace stride::gait {

/// Control period of the generator (TIME_UNIT), ms.
inline constexpr double tick_ms = 8.0;

/// Gyro feedback of one tick (§8).
struct walking_feedback {
  bool balance_on = true;  ///< BALANCE_ENABLE
  int gyro_fb = 0;         ///< front/back (pitch-rate) gyro, raw counts minus centre (512)
  int gyro_rl = 0;         ///< right/left (roll-rate) gyro, raw counts minus centre (512)
};

/// Parameters latched at the double-support centres t = 0 and t = T/2 ("half"), with everything
/// derived from them (phase boundaries, oscillator rates and the constant oscillator values of
/// the "hold" intervals, §3, §4.2).
struct gait_timing {
  double period;          ///< T, ms
  double dsp_ratio;       ///< delta
  double ssp_ratio;       ///< s = 1 - delta
  double ssp_start_l;     ///< tL0
  double ssp_end_l;       ///< tL1
  double ssp_start_r;     ///< tR0
  double ssp_end_r;       ///< tR1
  double phase_time1;     ///< T/4 (command latch)
  double phase_time2;     ///< T/2 (time latch, t snaps to it)
  double phase_time3;     ///< 3T/4 (command latch)
  double pelvis_offset;   ///< pelvis_offset * K, counts
  double pelvis_swing;    ///< 0.35 * pelvis_offset * K, counts
  double arm_swing_gain;  ///< deg per mm
  // oscillator rates 2*pi/P (with the oscillator's pi) and phase shifts
  double rate_x_swing;  ///< P = T/2
  double rate_y_swing;  ///< P = T
  double rate_z_swing;  ///< P = T/2
  double rate_step;     ///< P = sT (x, y and yaw stepping)
  double rate_lift;     ///< P = sT/2 (foot lift and pelvis)
  double rate_arm;      ///< P = T
  double shift_step_l;  ///< phiL(sT)
  double shift_step_r;  ///< phiR(sT) + pi
  double shift_lift_l;  ///< phiL(sT/2)
  double shift_lift_r;  ///< phiR(sT/2)
  // sine values of the held intervals
  double hold_step_l0;  ///< stepping held at tL0 (I0)
  double hold_step_l1;  ///< stepping held at tL1 (I2)
  double hold_step_r1;  ///< stepping held at tR1 (I4)
  double hold_lift_l0;  ///< left lift held at tL0 (I0)
  double hold_lift_l1;  ///< left lift held at tL1 (I2-I4)
  double hold_lift_r0;  ///< right lift held at tR0 (I0-I2)
  double hold_lift_r1;  ///< right lift held at tR1 (I4)
};

/// Computes the "half" latch of §3 from the parameters (framework update_param_time()).
gait_timing make_gait_timing(const walking_params& params);

/// Amplitudes latched at the quarter points T/4 and 3T/4 (§4.1, framework update_param_move()).
struct gait_amplitudes {
  double x_move;        ///< Xm = X, mm
  double x_swing;       ///< Xs = X * step_forward_back_ratio
  double y_move;        ///< Ym = Y/2
  double y_move_shift;  ///< Yb = |Y|/2
  double y_swing;       ///< Ys = swing_right_left + 0.04 |Y|/2
  double z_move;        ///< Zm = foot_height/2
  double z_move_shift;  ///< Zb = foot_height/4
  double z_swing;       ///< Zs = swing_top_down (amplitude and bias)
  double a_move;        ///< Am, rad (sign flipped when aim is on)
  double a_move_shift;  ///< Ab, rad
};

/// Everything one tick computed before the IK (§4.4, §4.2, §7.2): both foot targets (offsets
/// included), the arm swing and the pelvis bump.
struct gait_pose {
  foot_target<double> right;  ///< e_R, right hip frame (mm, rad)
  foot_target<double> left;   ///< e_L, left hip frame
  double arm_right_deg;       ///< right shoulder pitch swing before the servo flip, deg
  double arm_left_deg;        ///< left shoulder pitch swing, deg
  double pelvis_right;        ///< pelvis bump added to the right hip roll, counts
  double pelvis_left;         ///< pelvis bump added to the left hip roll, counts
  double body_swing_y;        ///< framework diagnostic GetBodySwingY (mm)
  double body_swing_z;        ///< framework diagnostic GetBodySwingZ (mm)
};

/// All evolving state of the generator: trivially copyable, its fields listed below for state
/// images.
struct walking_state {
  /// Goal position of servo ID i + 1 in MX-28 counts (0..4095), as the framework outputs them.
  int servo_count[servo_total];

  double time_ms;           ///< gait clock t at which the NEXT tick is evaluated, in [0, T)
  double eval_time_ms;      ///< t at which the last tick was evaluated (see phase_ms())
  int phase;                ///< 0..3, set at the four latch ticks (GetCurrentPhase)
  int footsteps;            ///< see footsteps()
  bool ctrl_running;        ///< set by start(), cleared by stop()
  bool real_running;        ///< is_running(): the clock advances
  bool moved_since_centre;  ///< the clock advanced since the last double-support centre tick
  bool ik_failed;           ///< the last tick's IK failed (servo_count kept, §9.4)

  // command inputs (X_MOVE_AMPLITUDE, Y_MOVE_AMPLITUDE, A_MOVE_AMPLITUDE, A_MOVE_AIM_ON)
  double x_command;  ///< mm
  double y_command;  ///< mm
  double a_command;  ///< deg (also drives the head pan servo, raw)
  bool aim_on;

  gait_timing timing;          ///< latched at t = 0 and T/2
  gait_amplitudes amplitudes;  ///< latched at T/4 and 3T/4
  gait_pose pose;              ///< what the last tick evaluated
};
static_assert(std::is_trivially_copyable_v<walking_state>);

// The fields of the state structs, for the gait FMU's state image (stride/sdk/state_fields.hpp;
// the FMU checks that each list covers its struct).
template <class F>
void state_fields(gait_timing& s, F&& f) {
  f(s.period, s.dsp_ratio, s.ssp_ratio, s.ssp_start_l, s.ssp_end_l, s.ssp_start_r, s.ssp_end_r,
    s.phase_time1, s.phase_time2, s.phase_time3, s.pelvis_offset, s.pelvis_swing, s.arm_swing_gain,
    s.rate_x_swing, s.rate_y_swing, s.rate_z_swing, s.rate_step, s.rate_lift, s.rate_arm,
    s.shift_step_l, s.shift_step_r, s.shift_lift_l, s.shift_lift_r, s.hold_step_l0, s.hold_step_l1,
    s.hold_step_r1, s.hold_lift_l0, s.hold_lift_l1, s.hold_lift_r0, s.hold_lift_r1);
}
template <class F>
void state_fields(gait_amplitudes& s, F&& f) {
  f(s.x_move, s.x_swing, s.y_move, s.y_move_shift, s.y_swing, s.z_move, s.z_move_shift, s.z_swing,
    s.a_move, s.a_move_shift);
}
template <class F>
void state_fields(gait_pose& s, F&& f) {
  f(s.right, s.left, s.arm_right_deg, s.arm_left_deg, s.pelvis_right, s.pelvis_left, s.body_swing_y,
    s.body_swing_z);
}
template <class F>
void state_fields(walking_state& s, F&& f) {
  f(s.servo_count, s.time_ms, s.eval_time_ms, s.phase, s.footsteps, s.ctrl_running, s.real_running,
    s.moved_since_centre, s.ik_failed, s.x_command, s.y_command, s.a_command, s.aim_on, s.timing,
    s.amplitudes, s.pose);
}

/// The generator. Const: its only configuration is the IK mode; all state is in walking_state.
class walking {
 public:
  explicit walking(ik_mode mode = ik_mode::darwin);

  /// Framework Initialize(): zero commands, not running, t = 0, latch all parameters and compute
  /// the standing posture (= golden row -1). Throws std::invalid_argument for invalid params.
  walking_state initialize(const walking_params& params) const;
  /// Start(): the clock runs (resuming where it stopped: t = 0 or T/2).
  void start(walking_state& state) const;
  /// Stop(): the gait finishes its step and stops at the next double-support centre with zero
  /// amplitudes, provided the caller stops re-asserting non-zero commands (§9.2).
  void stop(walking_state& state) const;
  /// Writes the command inputs X (mm), Y (mm), A (deg) and the aim flag; they are latched only
  /// at T/4 and 3T/4. A is also the head-pan angle. Throws std::invalid_argument for NaN/inf.
  void set_command(walking_state& state, double x_mm, double y_mm, double a_deg, bool aim_on) const;
  /// One 8 ms Process(). `params` is the live parameter set: offsets, hip pitch offset and balance
  /// gains apply at once, the rest only at its latch point (§9.1). Precondition: the values
  /// satisfy check_param_value(); non-finite live values and invalid latched values throw
  /// std::invalid_argument (before the state is changed).
  void tick(walking_state& state, const walking_params& params,
            const walking_feedback& feedback) const;

  ik_mode mode() const { return mode_; }

 private:
  ik_mode mode_;
};

/// IsRunning(): the gait clock advances on each tick.
bool is_running(const walking_state& state);

/// Gait-phase time t (ms, in [0, T)) at which the LAST tick was evaluated, i.e. after the T/2 snap
/// and before the +8 ms advance (the `t_ms` column of the golden end-point file). With T = 600
/// the ticks of one cycle are evaluated at 0, 8, ..., 288, 300 (snapped from 296), 308, ..., 596.
/// 0 right after initialize().
double phase_ms(const walking_state& state);

/// Phase number 0..3 set at the last latch tick (t = 0, T/4, T/2, 3T/4).
int current_phase(const walking_state& state);

/// Completed steps (half cycles) of the current walk. A step is completed on the tick evaluated at
/// the next double-support centre (t = T/2 after the left swing, t = 0 after the right swing),
/// provided the clock advanced since the previous centre tick; so with T = 600 after start() from
/// t = 0 the count becomes 1 at tick 37, 2 at tick 75, 2n at tick 75n. The tick on which a stop
/// completes counts its step; a stopped generator counts nothing. start() on a stopped generator
/// resets the count to 0; initialize() sets 0.
int footsteps(const walking_state& state);

/// The foot targets, arm swing and pelvis terms the last tick evaluated.
const gait_pose& last_pose(const walking_state& state);

/// True when the last tick's IK failed and servo_count was kept from the tick before (§9.4).
bool last_tick_ik_failed(const walking_state& state);

// ---------------------------------------------------------------------------------------------
// Standing posture as a differentiable function of the offsets (calibration).

/// The gait parameters that shape the standing posture, as scalar T (double or ceres::Jet).
/// period_time and dsp_ratio only enter through round-off of the oscillator phases and stay double.
template <class T>
struct standing_params {
  T x_offset, y_offset, z_offset;           ///< mm
  T roll_offset, pitch_offset, yaw_offset;  ///< deg
  T hip_pitch_offset;                       ///< deg
  T foot_height, swing_top_down;            ///< mm
  double period_time, dsp_ratio;

  static standing_params from(const walking_params& p) {
    return {T(p.x_offset),         T(p.y_offset),     T(p.z_offset),
            T(p.roll_offset),      T(p.pitch_offset), T(p.yaw_offset),
            T(p.hip_pitch_offset), T(p.foot_height),  T(p.swing_top_down),
            p.period_time,         p.dsp_ratio};
  }
};

/// Untruncated servo counts of the standing posture (the output of initialize(), X = Y = A = 0,
/// t = 0, no gyro feedback), indexed by servo ID - 1. For the 12 leg servos and the two shoulder
/// pitches this is 2048 + trunc(base * K) + (dir * angle * K + extra), i.e. exactly the
/// framework's arithmetic except that the last truncation is omitted, so
/// servo_count[i] == 2048 + trunc(base) + trunc(counts[i] - 2048 - trunc(base)) up to round-off.
/// The constant servos (shoulder roll, elbows, head) are returned as their (integer) counts.
/// Returns false (counts untouched) when the IK fails.
template <class T>
bool standing_servo_counts(const standing_params<T>& p, ik_mode mode,
                           std::array<T, servo_total>& counts);

/// standing_servo_counts() converted with servo_count_to_rad(): the 20 joint angles in rad in the
/// Webots/URDF servo convention, untruncated (differentiable w.r.t. the standing_params).
template <class T>
bool standing_joint_angles(const standing_params<T>& p, ik_mode mode,
                           std::array<T, servo_total>& angles);

/// Convenience form; throws std::domain_error when the IK fails.
template <class T>
std::array<T, servo_total> standing_joint_angles(const standing_params<T>& p, ik_mode mode);

// ---------------------------------------------------------------------------------------------
// Servo table (§7.1): the 14 joints the gait drives, in the framework's order
// R hip yaw, R hip roll, R hip pitch, R knee, R ankle pitch, R ankle roll, L (same), R arm, L arm.

namespace detail {
inline constexpr int driven_servo_id[14] = {7, 9, 11, 13, 15, 17, 8, 10, 12, 14, 16, 18, 1, 2};
inline constexpr int driven_dir[14] = {-1, -1, 1, 1, -1, 1, -1, -1, -1, -1, 1, 1, 1, -1};
inline constexpr double driven_base_deg[14] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -48.345, 41.313};
/// Angles set once by the constructor: shoulder rolls, elbows (IDs 3..6) and head tilt (ID 20).
inline constexpr double r_shoulder_roll_deg = -17.873;
inline constexpr double l_shoulder_roll_deg = 17.580;
inline constexpr double r_elbow_deg = 29.300;
inline constexpr double l_elbow_deg = -29.593;
inline constexpr double head_tilt_deg = 40.0;

/// MX28::Angle2Value: 2048 + trunc(angle * K), not clamped.
inline int angle_to_value(double deg) {
  return static_cast<int>(deg * counts_per_degree) + servo_center;
}

/// sin(2 pi / P * t - shift), the sine inside the oscillator of §1 (A sin(..) + B); the rate
/// 2 pi / P (with the oscillator's pi) is precomputed.
inline double osc_sin(double rate, double time, double shift) {
  return std::sin(rate * time - shift);
}
}  // namespace detail

template <class T>
bool standing_servo_counts(const standing_params<T>& p, ik_mode mode,
                           std::array<T, servo_total>& counts) {
  walking_params wp;
  wp.period_time = p.period_time;
  wp.dsp_ratio = p.dsp_ratio;
  const gait_timing tm = make_gait_timing(wp);
  // t = 0 lies in the first double support: lift held at tL0 (left) / tR0 (right), body bob at 0
  const double bob_sin = detail::osc_sin(tm.rate_z_swing, 0.0, framework_pi * 3 / 2);
  const T z_move = p.foot_height / 2.0;
  const T z_move_shift = z_move / 2.0;
  const T z_swing = p.swing_top_down * bob_sin + p.swing_top_down;
  const T z_left = z_move * tm.hold_lift_l0 + z_move_shift;
  const T z_right = z_move * tm.hold_lift_r0 + z_move_shift;
  const T roll = p.roll_offset * framework_pi / 180.0;
  const T pitch = p.pitch_offset * framework_pi / 180.0;
  const T yaw = p.yaw_offset * framework_pi / 180.0;

  foot_target<T> right{
      p.x_offset, -(p.y_offset / 2.0), z_swing + z_right + p.z_offset, -(roll / 2.0),
      pitch,      -(yaw / 2.0)};
  foot_target<T> left{p.x_offset, p.y_offset / 2.0, z_swing + z_left + p.z_offset, roll / 2.0,
                      pitch,      yaw / 2.0};
  T q[12];
  if (!leg_ik(right, mode, q) || !leg_ik(left, mode, q + 6)) return false;

  std::array<T, servo_total> out;
  for (int i = 0; i < 12; ++i) {
    const double dir = detail::driven_dir[i];
    T offset = dir * (q[i] * (180.0 / framework_pi)) * counts_per_degree;
    if (i == 2 || i == 8) offset -= dir * (p.hip_pitch_offset * counts_per_degree);
    out[detail::driven_servo_id[i] - 1] = double(servo_center) + offset;
  }
  // arms: no swing while X == 0
  out[0] = T(double(detail::angle_to_value(detail::driven_base_deg[12])));
  out[1] = T(double(detail::angle_to_value(detail::driven_base_deg[13])));
  out[2] = T(double(detail::angle_to_value(detail::r_shoulder_roll_deg)));
  out[3] = T(double(detail::angle_to_value(detail::l_shoulder_roll_deg)));
  out[4] = T(double(detail::angle_to_value(detail::r_elbow_deg)));
  out[5] = T(double(detail::angle_to_value(detail::l_elbow_deg)));
  out[18] = T(double(servo_center));  // head pan = A command = 0
  out[19] = T(double(detail::angle_to_value(detail::head_tilt_deg)));
  counts = out;
  return true;
}

template <class T>
bool standing_joint_angles(const standing_params<T>& p, ik_mode mode,
                           std::array<T, servo_total>& angles) {
  std::array<T, servo_total> counts;
  if (!standing_servo_counts(p, mode, counts)) return false;
  for (int i = 0; i < servo_total; ++i) angles[i] = servo_count_to_rad(counts[i]);
  return true;
}

template <class T>
std::array<T, servo_total> standing_joint_angles(const standing_params<T>& p, ik_mode mode) {
  std::array<T, servo_total> angles;
  if (!standing_joint_angles(p, mode, angles))
    throw std::domain_error("standing_joint_angles: leg IK failed (foot target out of reach)");
  return angles;
}

}  // namespace stride::gait
