// Joint-posture mode: recovery of known offsets, robustness to a bad servo, the walk-ready pose,
// identifiability warnings, bounds and the rewritten config.ini.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <utility>

#include "stride/calibration/calibrate.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/gait/config_ini.hpp"
#include "stride/gait/walking.hpp"

namespace stride::calibration {
namespace {

namespace fs = std::filesystem;
using gait::ik_mode;
using ::testing::Contains;
using ::testing::HasSubstr;

const fs::path k_data = STRIDE_TEST_DATA_DIR;

// every offset except pitch_offset: from joint angles alone, x/z/pitch/hip_pitch form a family
// with one degree of freedom (see the rank-deficiency test), so one of them must be held
const char* const k_identifiable =
    "x_offset,y_offset,z_offset,roll_offset,yaw_offset,hip_pitch_offset";

// the acceptance tolerances: 0.5 mm for lengths, 0.2 deg for angles
double tolerance(std::size_t index) {
  return offset_table()[index].unit == "mm" ? 0.5 : 0.2;
}

gait::walking_params truth() {
  gait::walking_params p;
  p.x_offset = -7.3;
  p.y_offset = 8.1;
  p.z_offset = 25.4;
  p.roll_offset = 1.7;
  p.yaw_offset = 3.1;
  p.hip_pitch_offset = 10.6;
  return p;
}

std::array<double, gait::servo_total> counts_of(const gait::walking_params& p, ik_mode mode) {
  std::array<double, gait::servo_total> c;
  EXPECT_TRUE(gait::standing_servo_counts(gait::standing_params<double>::from(p), mode, c));
  return c;
}

// The 12 leg servos of `p` as a robot reports them: whole counts plus noise of -1, 0 or +1 count
// (from the seed), `extra` added to single IDs.
std::string noisy_posture(const gait::walking_params& p, ik_mode mode, std::uint32_t seed,
                          std::map<int, int> extra = {}) {
  const auto c = counts_of(p, mode);
  std::mt19937 rng(seed);
  std::string csv = "id,count\n";
  for (int id = 7; id <= 18; ++id) {
    const auto noise = static_cast<int>(rng() % 3) - 1;
    const long value = std::lround(c[static_cast<std::size_t>(id - 1)]) + noise + extra[id];
    csv += std::to_string(id) + "," + std::to_string(value) + "\n";
  }
  return csv;
}

fit_options options(ik_mode mode, const char* fit = k_identifiable) {
  fit_options o;
  o.ik = mode;
  o.fit = parse_offset_selection(fit);
  return o;
}

double error(const calibration_report& r, std::size_t i, const gait::walking_params& p) {
  return r.offsets[i].after - get_offsets(p)[i];
}

class calibration_ik : public ::testing::TestWithParam<ik_mode> {};
INSTANTIATE_TEST_SUITE_P(both, calibration_ik,
                         ::testing::Values(ik_mode::darwin, ik_mode::geometric),
                         [](const auto& info) {
                           return info.param == ik_mode::darwin ? "darwin" : "geometric";
                         });

TEST_P(calibration_ik, recovers_known_offsets_from_an_exact_posture) {
  const auto c = counts_of(truth(), GetParam());
  std::string csv = "id,rad\n";
  for (int id = 7; id <= 18; ++id) {
    char value[64];
    std::snprintf(value, sizeof value, "%.17g",
                  from_counts(c[static_cast<std::size_t>(id - 1)], angle_unit::rad));
    csv += std::to_string(id) + "," + value + "\n";
  }
  const auto r = fit_joint_posture(parse_joint_target(csv, "exact.csv"), gait::walking_params{},
                                   options(GetParam()));
  EXPECT_TRUE(r.converged) << r.termination;
  for (std::size_t i = 0; i < offset_count; ++i)
    EXPECT_NEAR(r.offsets[i].after, get_offsets(truth())[i], 1e-3) << offset_table()[i].key;
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
}

TEST_P(calibration_ik, recovers_known_offsets_from_a_posture_with_one_count_noise) {
  const gait::walking_params p = truth();
  const auto r = fit_joint_posture(parse_joint_target(noisy_posture(p, GetParam(), 1), "n.csv"),
                                   gait::walking_params{}, options(GetParam()));
  std::cout << format_report(r);
  EXPECT_TRUE(r.converged) << r.termination;
  for (std::size_t i = 0; i < offset_count; ++i) {
    const offset_result& o = r.offsets[i];
    if (!o.fitted) continue;
    ASSERT_TRUE(o.identifiable) << offset_table()[i].key << ": " << o.note;
    // back within the tolerance, or within 3 reported sigma where a single posture with this
    // noise does not carry that much information (y, roll and yaw: sigma ~0.4-0.9 mm, 0.1-0.3 deg)
    EXPECT_LE(std::abs(error(r, i, p)), std::max(tolerance(i), 3 * o.stddev))
        << offset_table()[i].key << " sigma " << o.stddev;
  }
  for (const char* key : {"x_offset", "z_offset"})
    EXPECT_LE(std::abs(error(r, *find_offset(key), p)), tolerance(*find_offset(key))) << key;
}

// The 12 leg servos of `p` with Gaussian noise of `sigma` counts, not rounded. Box-Muller on
// mt19937's raw output: the same draws with every standard library.
std::string gaussian_posture(const gait::walking_params& p, ik_mode mode, std::uint32_t seed,
                             double sigma) {
  const auto c = counts_of(p, mode);
  std::mt19937 rng(seed);
  const auto uniform = [&] { return (static_cast<double>(rng()) + 0.5) / 4294967296.0; };
  std::string csv = "id,count\n";
  for (int id = 7; id <= 18; id += 2) {
    const double r = std::sqrt(-2 * std::log(uniform())), phi = 2 * std::numbers::pi * uniform();
    const double noise[2] = {sigma * r * std::cos(phi), sigma * r * std::sin(phi)};
    for (int k = 0; k < 2; ++k) {
      char value[64];
      std::snprintf(value, sizeof value, "%.17g",
                    c[static_cast<std::size_t>(id + k - 1)] + noise[k]);
      csv += std::to_string(id + k) + "," + value + "\n";
    }
  }
  return csv;
}

// Where s / sigma lies for the standard deviation s of n normal draws around their mean:
// (n - 1) s^2 / sigma^2 is chi-square with n - 1 degrees of freedom. Its quantiles at z standard
// normal deviations by the Wilson-Hilferty approximation (within 0.01 % of the exact ones here).
std::pair<double, double> chi_square_band(int n, double z) {
  const double k = n - 1, a = 2 / (9 * k);
  return {std::pow(1 - a - z * std::sqrt(a), 1.5), std::pow(1 - a + z * std::sqrt(a), 1.5)};
}

TEST_P(calibration_ik, reported_uncertainty_matches_the_scatter_of_400_noisy_postures_both_ways) {
  // The two regimes of the residual scale (docs/calibration.md): 2 counts of noise, above the
  // 1-count floor, where the fit's own scatter sets it (the loss scale of 20 counts makes the
  // Cauchy loss least squares within 1 %), and 0.5 count with the default loss, below the floor,
  // where the report takes 1 count: its sigma is then twice the scatter.
  const gait::walking_params p = truth();
  constexpr int n = 400;
  // 4.1 normal deviations: a false alarm probability of 1e-3 over the 24 comparisons (6 offsets,
  // 2 regimes, 2 IKs); the seeds are fixed, so the outcome is too
  const auto [low, high] = chi_square_band(n, 4.1);
  struct regime {
    double noise, loss_scale, floor_factor;  // expected scatter / reported sigma
  };
  for (const regime g : {regime{2.0, 20.0, 1.0}, regime{0.5, 2.0, 0.5}}) {
    fit_options o = options(GetParam());
    o.loss_scale = g.loss_scale;
    std::array<double, offset_count> sum{}, sum2{}, reported2{};
    for (std::uint32_t seed = 1; seed <= n; ++seed) {
      const auto r = fit_joint_posture(
          parse_joint_target(gaussian_posture(p, GetParam(), seed, g.noise), "g.csv"),
          gait::walking_params{}, o);
      ASSERT_TRUE(r.converged) << "seed " << seed << ": " << r.termination;
      for (std::size_t i = 0; i < offset_count; ++i) {
        if (!r.offsets[i].fitted) continue;
        ASSERT_TRUE(r.offsets[i].identifiable) << offset_table()[i].key;
        sum[i] += r.offsets[i].after;
        sum2[i] += r.offsets[i].after * r.offsets[i].after;
        reported2[i] += r.offsets[i].stddev * r.offsets[i].stddev;
      }
    }
    for (std::size_t i = 0; i < offset_count; ++i) {
      if (reported2[i] == 0) continue;
      const double mean = sum[i] / n;
      const double scatter = std::sqrt((sum2[i] - n * mean * mean) / (n - 1));
      // RMS of the reported sigmas: the scatter estimate in each fit is unbiased in the variance
      const double reported = std::sqrt(reported2[i] / n);
      const double ratio = scatter / (g.floor_factor * reported);
      EXPECT_GE(ratio, low) << offset_table()[i].key << " noise " << g.noise << ": scatter "
                            << scatter << ", reported " << reported;
      EXPECT_LE(ratio, high) << offset_table()[i].key << " noise " << g.noise << ": scatter "
                             << scatter << ", reported " << reported;
    }
  }
}

TEST_P(calibration_ik, an_outlier_servo_does_not_move_the_fit) {
  const gait::walking_params p = truth();
  const auto clean = fit_joint_posture(parse_joint_target(noisy_posture(p, GetParam(), 2), "a.csv"),
                                       gait::walking_params{}, options(GetParam()));
  const std::string bad = noisy_posture(p, GetParam(), 2, {{13, 200}});
  const auto robust = fit_joint_posture(parse_joint_target(bad, "b.csv"), gait::walking_params{},
                                        options(GetParam()));
  for (std::size_t i = 0; i < offset_count; ++i)
    EXPECT_LE(std::abs(robust.offsets[i].after - clean.offsets[i].after), tolerance(i))
        << offset_table()[i].key;
  ASSERT_EQ(robust.joints.size(), 12u);
  EXPECT_TRUE(robust.joints[13 - 7].outlier);
  EXPECT_NEAR(robust.joints[13 - 7].residual_after(), -200, 3);
  EXPECT_THAT(robust.warnings, Contains(HasSubstr("servo 13 (r_knee) (line 8)")));

  // without the robust loss the same servo drags the fit off by centimetres
  fit_options plain = options(GetParam());
  plain.loss_scale = 1e6;
  const auto dragged =
      fit_joint_posture(parse_joint_target(bad, "b.csv"), gait::walking_params{}, plain);
  EXPECT_GT(std::abs(dragged.offsets[0].after - clean.offsets[0].after), 5.0);
}

// recommended_posture_plan() as a robot reports it: the 12 leg servos of every posture as whole
// counts with -1/0/+1 count noise from the seed, `extra` added to (posture, ID)
std::string noisy_posture_plan(const gait::walking_params& p, ik_mode mode, std::uint32_t seed,
                               std::map<std::pair<int, int>, int> extra = {}) {
  std::mt19937 rng(seed);
  std::string csv;
  for (const offset_info& o : offset_table()) csv += "delta_" + std::string(o.key) + ",";
  csv += "id,count\n";
  int posture = 0;
  for (const offset_values& delta : recommended_posture_plan()) {
    gait::walking_params q = p;
    offset_values v = get_offsets(p);
    std::string prefix;
    for (std::size_t k = 0; k < offset_count; ++k) {
      v[k] += delta[k];
      prefix += std::to_string(delta[k]) + ",";
    }
    set_offsets(q, v);
    const auto c = counts_of(q, mode);
    for (int id = 7; id <= 18; ++id) {
      const auto noise = static_cast<int>(rng() % 3) - 1;
      const long value =
          std::lround(c[static_cast<std::size_t>(id - 1)]) + noise + extra[{posture, id}];
      csv += prefix + std::to_string(id) + "," + std::to_string(value) + "\n";
    }
    ++posture;
  }
  return csv;
}

// the truth with pitch_offset moved too: every one of the seven is off its default
gait::walking_params truth_all_seven() {
  gait::walking_params p = truth();
  p.pitch_offset = 2.3;
  return p;
}

TEST_P(calibration_ik, a_posture_plan_determines_all_seven_offsets_within_the_tolerance) {
  const gait::walking_params p = truth_all_seven();
  for (std::uint32_t seed = 1; seed <= 5; ++seed) {
    const auto r =
        fit_joint_posture(parse_joint_target(noisy_posture_plan(p, GetParam(), seed), "plan.csv"),
                          gait::walking_params{}, options(GetParam(), "all"));
    if (seed == 1) std::cout << format_report(r);
    EXPECT_TRUE(r.converged) << r.termination;
    EXPECT_EQ(r.postures.size(), 27u);
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    for (std::size_t i = 0; i < offset_count; ++i) {
      const offset_result& o = r.offsets[i];
      ASSERT_TRUE(o.fitted && o.identifiable) << offset_table()[i].key << ": " << o.note;
      EXPECT_LE(std::abs(error(r, i, p)), tolerance(i))
          << offset_table()[i].key << " seed " << seed << " sigma " << o.stddev;
      // not luck: the tolerance is at least three reported sigmas
      EXPECT_LE(3 * o.stddev, tolerance(i)) << offset_table()[i].key;
    }
  }
}

TEST_P(calibration_ik, an_outlier_servo_in_a_posture_plan_does_not_move_the_fit) {
  const gait::walking_params p = truth_all_seven();
  const auto clean =
      fit_joint_posture(parse_joint_target(noisy_posture_plan(p, GetParam(), 7), "a.csv"),
                        gait::walking_params{}, options(GetParam(), "all"));
  const auto robust = fit_joint_posture(
      parse_joint_target(noisy_posture_plan(p, GetParam(), 7, {{{4, 13}, 200}}), "b.csv"),
      gait::walking_params{}, options(GetParam(), "all"));
  for (std::size_t i = 0; i < offset_count; ++i) {
    EXPECT_LE(std::abs(robust.offsets[i].after - clean.offsets[i].after), tolerance(i))
        << offset_table()[i].key;
    EXPECT_LE(std::abs(error(robust, i, p)), tolerance(i)) << offset_table()[i].key;
  }
  // posture 5 (index 4) is rows 50..61 of the file: servo 13 on line 2 + 4 * 12 + 6
  std::size_t outliers = 0;
  for (const joint_result& j : robust.joints) {
    if (!j.outlier) continue;
    ++outliers;
    EXPECT_EQ(j.posture, 4);
    EXPECT_EQ(j.id, 13);
  }
  EXPECT_EQ(outliers, 1u);
  EXPECT_THAT(robust.warnings, Contains(HasSubstr("servo 13 (r_knee) (line 56)")));
  EXPECT_THAT(format_report(robust), HasSubstr("P5   13 r_knee"));
}

// Every offset off its default, the rotational ones with assorted signs: roll, pitch and yaw
// negative, positive, negative, hip_pitch below the default 13.
gait::walking_params truth_rotated() {
  gait::walking_params p;
  p.x_offset = -12.4;
  p.y_offset = 7.2;
  p.z_offset = 24.1;
  p.roll_offset = -2.6;
  p.pitch_offset = 4.3;
  p.yaw_offset = -3.8;
  p.hip_pitch_offset = 9.7;
  return p;
}

// 27 postures that move the rotational offsets only: delta_roll_offset -3/0/+5 x
// delta_pitch_offset -6/0/+9 x delta_yaw_offset -5/0/+7 deg, and delta_hip_pitch_offset
// -4/0/+6 deg in a Latin square over them (so each varies on its own). The levels are lopsided:
// with -d/0/+d a delta applied with the wrong sign averages out and the fit still lands on the
// truth. The 12 leg servos of each as untruncated counts, the offsets and deltas added here; each
// is checked to truncate to what the walking generator's initialize() outputs for that posture.
std::string rotational_plan(const gait::walking_params& p, ik_mode mode) {
  std::string csv =
      "delta_roll_offset,delta_pitch_offset,delta_yaw_offset,delta_hip_pitch_offset,id,count\n";
  const double rolls[3] = {-3, 0, 5}, pitches[3] = {-6, 0, 9}, yaws[3] = {-5, 0, 7},
               hips[3] = {-4, 0, 6};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int c = 0; c < 3; ++c) {
        gait::walking_params q = p;
        const double roll = rolls[a], pitch = pitches[b], yaw = yaws[c],
                     hip = hips[(a + b + c) % 3];
        q.roll_offset += roll;
        q.pitch_offset += pitch;
        q.yaw_offset += yaw;
        q.hip_pitch_offset += hip;
        const auto counts = counts_of(q, mode);
        const gait::walking_state s = gait::walking(mode).initialize(q);
        for (int id = 7; id <= 18; ++id) {
          const double count = counts[static_cast<std::size_t>(id - 1)];
          // the generator truncates the leg servo's joint term towards 2048
          EXPECT_EQ(2048 + static_cast<int>(count - 2048), s.servo_count[id - 1])
              << "servo " << id << " at deltas " << roll << " " << pitch << " " << yaw << " "
              << hip;
          char row[128];
          std::snprintf(row, sizeof row, "%g,%g,%g,%g,%d,%.17g\n", roll, pitch, yaw, hip, id,
                        count);
          csv += row;
        }
      }
  return csv;
}

TEST_P(calibration_ik, a_rotational_posture_plan_gives_back_roll_pitch_yaw_and_hip_pitch) {
  const gait::walking_params p = truth_rotated();
  const auto r = fit_joint_posture(parse_joint_target(rotational_plan(p, GetParam()), "rot.csv"),
                                   gait::walking_params{}, options(GetParam(), "all"));
  std::cout << format_report(r);
  EXPECT_TRUE(r.converged) << r.termination;
  EXPECT_EQ(r.postures.size(), 27u);
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  // exact readings: the truth reproduces all 324, and so must the fit
  EXPECT_LT(r.final_cost, 1e-8);
  for (std::size_t i = 0; i < offset_count; ++i) {
    const offset_result& o = r.offsets[i];
    ASSERT_TRUE(o.fitted && o.identifiable) << offset_table()[i].key << ": " << o.note;
    // written to 4 decimals; the solver stops far below that
    EXPECT_NEAR(o.after, get_offsets(p)[i], 1e-3) << offset_table()[i].key;
  }
  // the rotational offsets moved from their defaults the way the truth lies
  for (const char* key : {"roll_offset", "pitch_offset", "yaw_offset", "hip_pitch_offset"}) {
    const offset_result& o = r.offsets[*find_offset(key)];
    EXPECT_EQ(o.after > o.before, get_offsets(p)[*find_offset(key)] > o.before) << key;
  }
  // the report's model at the fitted offsets plus each posture's deltas reproduces every reading
  for (const joint_result& j : r.joints)
    EXPECT_LT(std::abs(j.residual_after()), 0.01) << "P" << j.posture + 1 << " servo " << j.id;
}

TEST(calibration_joint_fit, walk_ready_pose_is_the_framework_default_stance) {
  const joint_target target = read_joint_target(k_data / "walk_ready.csv");
  const gait::walking_params defaults;

  const auto darwin = fit_joint_posture(target, defaults, options(ik_mode::darwin));
  std::cout << format_report(darwin);
  // page 9 is the framework's standing output with the default offsets: the fit stays there,
  // within the tolerance where the posture determines the offset and within 2 sigma elsewhere
  for (std::size_t i = 0; i < offset_count; ++i) {
    const offset_result& o = darwin.offsets[i];
    ASSERT_TRUE(o.identifiable) << offset_table()[i].key;
    EXPECT_LE(std::abs(o.after - o.before), std::max(tolerance(i), 2 * o.stddev))
        << offset_table()[i].key;
  }
  double before = 0, after = 0;
  for (const joint_result& j : darwin.joints) {
    if (!j.fitted) continue;
    before = std::max(before, std::abs(j.residual_before()));
    after = std::max(after, std::abs(j.residual_after()));
  }
  EXPECT_LT(before, 1.0);  // the framework truncates; the model does not
  EXPECT_LT(after, 0.05);
  // the head tilt of page 9 is not the walking module's (40 deg): reported, not fitted
  EXPECT_THAT(darwin.warnings, Contains(HasSubstr("servo 20 (head_tilt) (line 22)")));
  EXPECT_EQ(darwin.warnings.size(), 1u);

  // the geometric IK reaches page 9 only with a narrower stance and the feet rolled outwards
  const auto geometric = fit_joint_posture(target, defaults, options(ik_mode::geometric));
  std::cout << format_report(geometric);
  const offset_result& y = geometric.offsets[*find_offset("y_offset")];
  const offset_result& roll = geometric.offsets[*find_offset("roll_offset")];
  EXPECT_GT(std::abs(y.after - y.before), 5 * y.stddev);
  EXPECT_GT(std::abs(roll.after - roll.before), 3 * roll.stddev);
  for (const joint_result& j : geometric.joints)
    if (j.fitted) {
      EXPECT_LT(std::abs(j.residual_after()), 0.05) << "servo " << j.id;
    }
}

TEST(calibration_joint_fit, all_seven_offsets_are_not_identifiable_from_joint_angles) {
  // hip pitch, knee and ankle pitch give three numbers for x, z, pitch and hip_pitch_offset
  const auto r =
      fit_joint_posture(parse_joint_target(noisy_posture(truth(), ik_mode::darwin, 3), "n.csv"),
                        gait::walking_params{}, fit_options{});
  for (const char* key : {"x_offset", "z_offset", "pitch_offset", "hip_pitch_offset"}) {
    const offset_result& o = r.offsets[*find_offset(key)];
    EXPECT_FALSE(o.identifiable) << key;
    EXPECT_THAT(o.note, HasSubstr("rank deficient")) << key;
  }
  for (const char* key : {"y_offset", "roll_offset", "yaw_offset"})
    EXPECT_TRUE(r.offsets[*find_offset(key)].identifiable) << key;
  EXPECT_THAT(r.warnings,
              Contains(HasSubstr("x_offset, z_offset, pitch_offset, hip_pitch_offset are not "
                                 "identifiable from this target")));
  EXPECT_THAT(format_report(r), HasSubstr("NOT IDENTIFIABLE"));
}

TEST(calibration_joint_fit, an_offset_the_target_does_not_constrain_is_reported_and_kept) {
  // page 9 without the hip pitch servos, which are the only ones hip_pitch_offset moves
  const auto r = fit_joint_posture(
      parse_joint_target("id,count\n7,2048\n8,2048\n9,2052\n10,2044\n13,2653\n14,1443\n"
                         "15,2389\n16,1707\n17,2057\n18,2039\n",
                         "no_hips.csv"),
      gait::walking_params{}, options(ik_mode::darwin, "x_offset,hip_pitch_offset"));
  const offset_result& hip = r.offsets[*find_offset("hip_pitch_offset")];
  EXPECT_FALSE(hip.identifiable);
  EXPECT_THAT(hip.note, HasSubstr("no effect on the target"));
  EXPECT_EQ(hip.after, hip.before);
  EXPECT_EQ(r.fitted.hip_pitch_offset, 13.0);
  EXPECT_TRUE(r.offsets[*find_offset("x_offset")].identifiable);
  EXPECT_THAT(r.warnings,
              Contains(HasSubstr("hip_pitch_offset is not identifiable from this target: no "
                                 "effect on the target")));
  EXPECT_THAT(format_report(r), HasSubstr("NOT IDENTIFIABLE: no effect on the target"));
}

TEST(calibration_joint_fit, bounds_hold_and_are_reported) {
  fit_options o = options(ik_mode::darwin);
  apply_bound(o.bounds, "hip_pitch_offset=12:20");
  const auto r =
      fit_joint_posture(parse_joint_target(noisy_posture(truth(), ik_mode::darwin, 4), "n.csv"),
                        gait::walking_params{}, o);
  const offset_result& hip = r.offsets[*find_offset("hip_pitch_offset")];
  EXPECT_EQ(hip.after, 12.0);
  EXPECT_TRUE(hip.at_bound);
  EXPECT_THAT(r.warnings, Contains(HasSubstr("hip_pitch_offset stopped at its bound 12 deg")));

  apply_bound(o.bounds, "hip_pitch_offset=0:10");  // the start value 13 is outside
  EXPECT_THROW(
      fit_joint_posture(read_joint_target(k_data / "walk_ready.csv"), gait::walking_params{}, o),
      std::invalid_argument);
  EXPECT_THROW(fit_joint_posture(parse_joint_target("id,count\n1,1498\n20,2161\n", "arms.csv"),
                                 gait::walking_params{}, options(ik_mode::darwin)),
               std::invalid_argument);
}

TEST(calibration_joint_fit, the_fitted_config_keeps_keys_comments_and_order) {
  cosim::temp_dir dir("stride-calibration-test-");
  const fs::path in = k_data / "config_commented.ini";
  const fs::path out = dir.path() / "out.ini";
  const gait::walking_params start = gait::read_walking_config(in, {}, nullptr);
  const auto r =
      fit_joint_posture(parse_joint_target(noisy_posture(truth(), ik_mode::darwin, 5), "n.csv"),
                        start, options(ik_mode::darwin, "x_offset,hip_pitch_offset"));
  write_fitted_config(in, out, r);

  const auto read = [](const fs::path& f) {
    std::ifstream s(f);
    std::stringstream t;
    t << s.rdbuf();
    return t.str();
  };
  std::string expected = read(in);
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto pos = expected.find(from);
    ASSERT_NE(pos, std::string::npos) << from;
    expected.replace(pos, from.size(), to);
  };
  const auto text = [](double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%f", v);
    return std::string(b);
  };
  replace("x_offset = -10 ;", "x_offset = " + text(r.fitted.x_offset) + " ;");
  replace("hip_pitch_offset = 13 ;",
          "hip_pitch_offset = " + text(r.fitted.hip_pitch_offset) + " ;");
  EXPECT_EQ(read(out), expected);

  const gait::walking_params back = gait::read_walking_config(out, {}, nullptr);
  EXPECT_EQ(back.x_offset, r.fitted.x_offset);
  EXPECT_EQ(back.hip_pitch_offset, r.fitted.hip_pitch_offset);
  EXPECT_NE(back.x_offset, -10.0);
}

}  // namespace
}  // namespace stride::calibration
