// DARwIn-OP leg kinematics and servo constants (docs/walking-generator.md §1, §5, §6, §7; § below
// refers to that page).
//
// Header-only templates on the scalar type T (double or ceres::Jet) so that a calibration can
// autodiff through the inverse kinematics. Only std::sin/cos/atan2/acos/sqrt and comparisons are
// used; for a Jet they are found by argument-dependent lookup.
#pragma once

#include <cmath>
#include <numbers>
#include <type_traits>

namespace stride::gait {

/// Which leg inverse kinematics the generator uses.
///  - darwin: the framework's IK including its matrix-product quirk (product = I + A*B, §6.4),
///    bit-compatible with the ROBOTIS framework / Webots (halves hip roll, yaw and pitch-sum
///    corrections).
///  - geometric: the ideal IK; forward kinematics of its output reproduces the target.
enum class ik_mode : int { darwin = 0, geometric = 1 };

/// pi as the framework writes it for phase shifts and deg<->rad conversions.
inline constexpr double framework_pi = 3.14159265;
/// The oscillator evaluates its 2*pi as 2 * this value (§1).
inline constexpr double oscillator_pi = 3.141592;
/// MX-28 counts per degree (RATIO_ANGLE2VALUE) and the reverse factor used by Webots.
inline constexpr double counts_per_degree = 11.378;
inline constexpr double degrees_per_count = 0.088;
inline constexpr int servo_center = 2048;
inline constexpr int servo_max = 4095;
/// Number of servos (IDs 1..20); servo_count[i] belongs to ID i + 1.
inline constexpr int servo_total = 20;

/// Leg geometry (mm).
inline constexpr double thigh_length = 93.0;
inline constexpr double calf_length = 93.0;
inline constexpr double ankle_length = 33.5;
inline constexpr double leg_length = 219.5;

/// Foot end point in its hip frame (x forward, y left, z up; §1): x, y, z in mm where z is the leg
/// shortening (sole point at (x, y, z - 219.5)), roll/pitch/yaw in rad (R = Rz(yaw) Ry(pitch)
/// Rx(roll)).
template <class T>
struct foot_target {
  T x, y, z, roll, pitch, yaw;
};

/// Its fields, for state images (stride/sdk/state_fields.hpp).
template <class T, class F>
void state_fields(foot_target<T>& t, F&& f) {
  f(t.x, t.y, t.z, t.roll, t.pitch, t.yaw);
}

/// Webots / URDF joint angle of a servo count: (count - 2048) * 0.088 * pi / 180 rad.
inline double servo_count_to_rad(int count) {
  return (count - servo_center) * degrees_per_count * std::numbers::pi / 180.0;
}

/// The same for an untruncated (possibly differentiable) count value.
template <class T>
T servo_count_to_rad(const T& count) {
  return (count - double(servo_center)) * (degrees_per_count * std::numbers::pi / 180.0);
}

/// Leg inverse kinematics (§6.2). q = hip yaw, hip roll, hip pitch, knee, ankle pitch, ankle roll
/// in rad, in the common right-handed convention of §6.1 (servo directions are applied later).
/// Returns false when the target is out of reach (knee acos undefined, §9.4); q is then untouched.
///
/// With T = double and ik_mode::darwin the ankle roll uses the framework's law-of-cosines form
/// (clamped), everything else uses atan2 (smooth for autodiff, equal to ~1e-11 rad).
template <class T>
bool leg_ik(const foot_target<T>& e, ik_mode mode, T q[6]) {
  using std::acos;
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;

  // 1. target orientation R = Rz(yaw) Ry(pitch) Rx(roll) and sole point p
  const auto sin_cos = [](const T& a, T& s, T& c) {
    if constexpr (std::is_same_v<T, double>) {
      if (a == 0.0) {  // the common case of flat, straight feet; same values as sin/cos
        s = a;
        c = 1.0;
        return;
      }
    }
    s = sin(a);
    c = cos(a);
  };
  T sx, cx, sy, cy, sz, cz;
  sin_cos(e.roll, sx, cx);
  sin_cos(e.pitch, sy, cy);
  sin_cos(e.yaw, sz, cz);
  const T r00 = cz * cy, r01 = cz * sy * sx - sz * cx, r02 = cz * sy * cx + sz * sx;
  const T r10 = sz * cy, r11 = sz * sy * sx + cz * cx, r12 = sz * sy * cx - cz * sx;
  const T r21 = cy * sx, r22 = cy * cx;  // r20 = -sy is not needed
  const T px = e.x, py = e.y, pz = e.z - leg_length;

  // 2. ankle point
  const T vx = px + r02 * ankle_length;
  const T vy = py + r12 * ankle_length;
  const T vz = pz + r22 * ankle_length;

  // 3. knee (the framework squares the length, not the sum of squares)
  const T v_len = sqrt(vx * vx + vy * vy + vz * vz);
  const T knee_cos = (v_len * v_len - thigh_length * thigh_length - calf_length * calf_length) /
                     (2 * thigh_length * calf_length);
  if (!(knee_cos >= -1.0 && knee_cos <= 1.0)) return false;  // also rejects NaN
  const T q3 = acos(knee_cos);

  // 4. ankle roll from the hip position seen from the sole frame, h = -R^T p
  const T hy = -(r01 * px + r11 * py + r21 * pz);
  const T hz = -(r02 * px + r12 * py + r22 * pz);
  T q5;
  if constexpr (std::is_same_v<T, double>) {
    if (mode == ik_mode::darwin) {
      // framework form: law of cosines on the sole-ankle-hip triangle, cosine clamped
      const double k = sqrt(hy * hy + hz * hz);
      const double l = sqrt(hy * hy + (hz - ankle_length) * (hz - ankle_length));
      double m = (k * k - l * l - ankle_length * ankle_length) / (2 * l * ankle_length);
      if (m > 1.0) m = 1.0;
      if (m < -1.0) m = -1.0;
      const double a = acos(m);
      if (std::isnan(a)) return false;
      q5 = hy < 0.0 ? -a : a;
    } else {
      q5 = atan2(hy, hz - ankle_length);
    }
  } else {
    q5 = atan2(hy, hz - ankle_length);
  }

  // 5./6. M = R Rx(q5)^T; the framework's product adds the identity (§6.4)
  const T c5 = cos(q5), s5 = sin(q5);
  T m00, m01, m02, m10, m11, m12, m21;
  if (mode == ik_mode::darwin) {
    // accumulated as the framework does: I_ij + sum_k A_ik B_kj, k in order
    m00 = 1.0 + r00;
    m01 = (0.0 + r01 * c5) + r02 * (-s5);
    m02 = (0.0 + r01 * s5) + r02 * c5;
    m10 = 0.0 + r10;
    m11 = (1.0 + r11 * c5) + r12 * (-s5);
    m12 = (0.0 + r11 * s5) + r12 * c5;
    m21 = (0.0 + r21 * c5) + r22 * (-s5);
  } else {
    m00 = r00;
    m01 = r01 * c5 + r02 * (-s5);
    m02 = r01 * s5 + r02 * c5;
    m10 = r10;
    m11 = r11 * c5 + r12 * (-s5);
    m12 = r11 * s5 + r12 * c5;
    m21 = r21 * c5 + r22 * (-s5);
  }
  const T q0 = atan2(-m01, m11);
  const T s0 = sin(q0), c0 = cos(q0);
  const T q1 = atan2(m21, -m01 * s0 + m11 * c0);
  const T theta = atan2(m02 * c0 + m12 * s0, m00 * c0 + m10 * s0);  // q2 + q3 + q4

  // 7. planar two-link solution in the leg plane
  const T s1 = sin(q1), c1 = cos(q1);
  const T k = sin(q3) * calf_length;
  const T l = -thigh_length - cos(q3) * calf_length;
  const T m = c0 * vx + s0 * vy;
  const T n = c1 * vz + s0 * s1 * vx - c0 * s1 * vy;
  const T s = (k * n + l * m) / (k * k + l * l);
  const T c = (n - k * s) / l;
  const T q2 = atan2(s, c);

  q[0] = q0;
  q[1] = q1;
  q[2] = q2;
  q[3] = q3;
  q[4] = theta - q3 - q2;
  q[5] = q5;
  return true;
}

/// Forward kinematics of §6.1: the foot target reached by joint angles q (rad). Orientation is
/// returned as roll/pitch/yaw with R = Rz(yaw) Ry(pitch) Rx(roll).
template <class T>
foot_target<T> leg_fk(const T q[6]) {
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  struct mat {
    T a[3][3];
  };
  struct vec {
    T v[3];
  };
  const auto mul = [](const mat& x, const mat& y) {
    mat r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        r.a[i][j] = x.a[i][0] * y.a[0][j] + x.a[i][1] * y.a[1][j] + x.a[i][2] * y.a[2][j];
    return r;
  };
  const auto apply = [](const mat& x, const vec& y) {
    vec r;
    for (int i = 0; i < 3; ++i)
      r.v[i] = x.a[i][0] * y.v[0] + x.a[i][1] * y.v[1] + x.a[i][2] * y.v[2];
    return r;
  };
  const auto add = [](const vec& x, const vec& y) {
    return vec{{x.v[0] + y.v[0], x.v[1] + y.v[1], x.v[2] + y.v[2]}};
  };
  const T zero(0.0), one(1.0);
  const auto rx = [&](const T& a) {
    return mat{{{one, zero, zero}, {zero, cos(a), -sin(a)}, {zero, sin(a), cos(a)}}};
  };
  const auto ry = [&](const T& a) {
    return mat{{{cos(a), zero, sin(a)}, {zero, one, zero}, {-sin(a), zero, cos(a)}}};
  };
  const auto rz = [&](const T& a) {
    return mat{{{cos(a), -sin(a), zero}, {sin(a), cos(a), zero}, {zero, zero, one}}};
  };
  const vec thigh{{zero, zero, T(-thigh_length)}};
  const vec calf{{zero, zero, T(-calf_length)}};
  const vec ankle{{zero, zero, T(-ankle_length)}};

  const mat hip = mul(mul(rz(q[0]), rx(q[1])), ry(q[2]));
  const vec below_knee = add(calf, apply(mul(ry(q[4]), rx(q[5])), ankle));
  const vec sole = apply(hip, add(thigh, apply(ry(q[3]), below_knee)));
  const mat r = mul(mul(mul(rz(q[0]), rx(q[1])), ry(q[2] + q[3] + q[4])), rx(q[5]));

  foot_target<T> e;
  e.x = sole.v[0];
  e.y = sole.v[1];
  e.z = sole.v[2] + leg_length;
  e.roll = atan2(r.a[2][1], r.a[2][2]);
  e.pitch = atan2(-r.a[2][0], sqrt(r.a[2][1] * r.a[2][1] + r.a[2][2] * r.a[2][2]));
  e.yaw = atan2(r.a[1][0], r.a[0][0]);
  return e;
}

}  // namespace stride::gait
