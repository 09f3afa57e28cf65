// The templated IK and standing posture work with ceres::Jet: derivatives match central finite
// differences of the double versions.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <array>

#include "stride/gait/kinematics.hpp"
#include "stride/gait/walking.hpp"

namespace {

using namespace stride::gait;
using jet = ceres::Jet<double, 3>;

TEST(gait_autodiff, leg_ik_jacobian_matches_finite_differences) {
  for (const ik_mode mode : {ik_mode::darwin, ik_mode::geometric}) {
    const double x0 = -8, y0 = 6, z0 = 25;
    foot_target<jet> e{jet(x0, 0), jet(y0, 1), jet(z0, 2), jet(0.05), jet(-0.03), jet(0.1)};
    jet q[6];
    ASSERT_TRUE(leg_ik(e, mode, q));
    const double h = 1e-5;
    for (int k = 0; k < 3; ++k) {
      double qp[6], qm[6];
      double base[3] = {x0, y0, z0};
      base[k] += h;
      ASSERT_TRUE(
          leg_ik(foot_target<double>{base[0], base[1], base[2], 0.05, -0.03, 0.1}, mode, qp));
      base[k] -= 2 * h;
      ASSERT_TRUE(
          leg_ik(foot_target<double>{base[0], base[1], base[2], 0.05, -0.03, 0.1}, mode, qm));
      for (int j = 0; j < 6; ++j) {
        const double fd = (qp[j] - qm[j]) / (2 * h);
        EXPECT_NEAR(q[j].v[k], fd, 1e-6 + 1e-5 * std::abs(fd))
            << "mode " << static_cast<int>(mode) << " dq" << j << "/d"
            << "xyz"[k];
      }
    }
  }
}

TEST(gait_autodiff, standing_joint_angles_derivatives_wrt_offsets) {
  const walking_params p;
  standing_params<jet> sp = standing_params<jet>::from(p);
  sp.x_offset.v[0] = 1;
  sp.z_offset.v[1] = 1;
  sp.hip_pitch_offset.v[2] = 1;
  const std::array<jet, servo_total> angles = standing_joint_angles(sp, ik_mode::darwin);

  const double h = 1e-4;
  for (int k = 0; k < 3; ++k) {
    standing_params<double> plus = standing_params<double>::from(p), minus = plus;
    double* fp = k == 0 ? &plus.x_offset : k == 1 ? &plus.z_offset : &plus.hip_pitch_offset;
    double* fm = k == 0 ? &minus.x_offset : k == 1 ? &minus.z_offset : &minus.hip_pitch_offset;
    *fp += h;
    *fm -= h;
    const auto ap = standing_joint_angles(plus, ik_mode::darwin);
    const auto am = standing_joint_angles(minus, ik_mode::darwin);
    for (int i = 0; i < servo_total; ++i) {
      const double fd = (ap[i] - am[i]) / (2 * h);
      EXPECT_NEAR(angles[i].v[k], fd, 1e-7 + 1e-5 * std::abs(fd))
          << "servo " << i + 1 << " k " << k;
    }
  }
  // hip pitch offset moves only the hip pitch servos, by 11.378 counts per degree
  const double per_deg = counts_per_degree * degrees_per_count * std::numbers::pi / 180;
  EXPECT_NEAR(angles[10].v[2], -per_deg, 1e-12);
  EXPECT_NEAR(angles[11].v[2], per_deg, 1e-12);
  EXPECT_EQ(angles[12].v[2], 0.0);
  // the crouch (z offset) bends the knees: right knee (dir +1) count grows
  EXPECT_GT(angles[12].v[1], 0.0);
  EXPECT_LT(angles[13].v[1], 0.0);
}

}  // namespace
