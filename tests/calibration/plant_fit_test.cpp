// Plant mode: gait.fmu + robot.fmu through the orchestrator library, settled from the same
// snapshot on every evaluation.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <numbers>

#include "stride/calibration/calibrate.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/execution.hpp"
#include "stride/cosim/system_builder.hpp"
#include "stride/gait/config_ini.hpp"

namespace stride::calibration {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path k_data = STRIDE_TEST_DATA_DIR;
const fs::path k_default_config =
    fs::path(STRIDE_SOURCE_DIR) / "components" / "gait_fmu" / "resources" / "config.ini";

plant_options fmus_of_this_build() {
  plant_options o;
  o.fmu_search_path = {STRIDE_FMU_DIR};
  o.log = cosim::stderr_log_sink(cosim::log_level::warning);
  return o;
}

// The torso pitch (deg) of the robot driven by a gait that loads `config` itself, after `seconds`
// of standing: a check that does not go through plant_simulator.
double settled_pitch_with(const fs::path& config, double seconds) {
  cosim::system_structure s = make_standing_system();
  s.set("gait.config_file", config.string());
  s.stop = cosim::time_from_seconds(seconds);
  cosim::build_options bo;
  bo.fmu_search_path = {STRIDE_FMU_DIR};
  bo.log = cosim::stderr_log_sink(cosim::log_level::warning);
  cosim::built_system built = cosim::build_system(s, bo);
  auto& algo = *built.execution;
  const std::size_t robot = *algo.find_component("robot");
  const auto pitch =
      algo.observe({robot, *algo.component_at(robot).model_description().index_of("pitch")});
  built.execution->simulate_until(built.stop);
  return algo.real_value(pitch) * 180 / std::numbers::pi;
}

// The standing system built here rather than by make_standing_system(): gait (not walking, gyro
// feedback off) drives the robot joint by joint, gyro fed back with one step delay, 8 ms steps.
// Without `drive_left_leg` the left leg (IDs 8, 10, .., 18) stays in the robot's walk-ready pose:
// no longer a mirror image, so z_offset (then the right leg's crouch alone) rolls the torso. The
// real, symmetric robot has no offset that drives the roll (docs/calibration.md); this plant gives
// the roll target one with a known answer.
cosim::system_structure standing_system_by_hand(bool drive_left_leg = true) {
  cosim::system_structure s;
  s.name = "stand-by-hand";
  s.base_step = std::chrono::milliseconds(8);
  s.record.enabled = false;
  cosim::component_spec& gait = s.add_component("gait", "gait");
  gait.parameters.push_back({"walking", "false", {}});
  gait.parameters.push_back({"balance_on", "false", {}});
  s.add_component("robot", "robot");
  for (int id = 1; id <= 20; ++id) {
    const bool left_leg = id >= 8 && id <= 18 && id % 2 == 0;
    if (left_leg && !drive_left_leg) continue;
    s.connect("gait.joint_angle[" + std::to_string(id) + "]",
              "robot.joint_target[" + std::to_string(id) + "]");
  }
  s.connect("robot.gyro_fb", "gait.gyro_fb", true);
  s.connect("robot.gyro_rl", "gait.gyro_rl", true);
  return s;
}

struct settled_robot {
  double pitch_deg = 0, roll_deg = 0, height_m = 0, com_x = 0, com_y = 0;
};

// The ground truth of the plant targets: the robot of `s` after 1 s with a gait that reads
// `offsets` from its own config file (other keys: defaults), averaged over the last 0.2 s like
// the plant mode, but built and stepped here, without plant_simulator.
settled_robot settle_independently(cosim::system_structure s, const offset_values& offsets) {
  cosim::temp_dir dir("stride-calibration-truth-");
  const fs::path config = dir.path() / "config.ini";
  {
    std::ofstream out(config);
    out << "[Walking Config]\n";
    for (std::size_t i = 0; i < offset_count; ++i) {
      char value[64];
      std::snprintf(value, sizeof value, "%.17g", offsets[i]);
      out << offset_table()[i].key << " = " << value << "\n";
    }
  }
  s.set("gait.config_file", config.string());
  const cosim::duration step = std::chrono::milliseconds(8);
  const int steps = 125, window = 25;  // 1 s, 0.2 s
  s.stop = s.start + steps * step;
  cosim::build_options bo;
  bo.fmu_search_path = {STRIDE_FMU_DIR};
  bo.log = cosim::stderr_log_sink(cosim::log_level::warning);
  cosim::built_system built = cosim::build_system(s, bo);
  auto& algo = *built.execution;
  const std::size_t robot = *algo.find_component("robot");
  const auto& md = algo.component_at(robot).model_description();
  const char* const names[] = {"pitch", "roll", "base_z", "com_x", "com_y"};
  std::vector<cosim::observed_variable> observed;
  for (const char* name : names) observed.push_back(algo.observe({robot, *md.index_of(name)}));
  double sum[5] = {};
  algo.initialize(built.stop);
  for (int k = 1; k <= steps; ++k) {
    algo.simulate_until(built.start + k * step);
    if (k > steps - window)
      for (std::size_t i = 0; i < 5; ++i) sum[i] += algo.real_value(observed[i]);
  }
  algo.end();
  constexpr double deg = 180 / std::numbers::pi;
  return {sum[0] / window * deg, sum[1] / window * deg, sum[2] / window, sum[3] / window,
          sum[4] / window};
}

// walking_params{} (the framework defaults) with one offset changed
offset_values defaults_with(const char* key, double value) {
  offset_values v = get_offsets(gait::walking_params{});
  v[*find_offset(key)] = value;
  return v;
}

gait::walking_params params_with(const offset_values& v) {
  gait::walking_params p;
  set_offsets(p, v);
  return p;
}

TEST(calibration_plant_fit, torso_pitch_zero_gives_a_config_whose_settled_robot_is_upright) {
  cosim::temp_dir dir("stride-calibration-plant-");
  const plant_target target = read_plant_target(k_data / "pitch_zero.ini");
  const gait::walking_params start = gait::read_walking_config(k_default_config, {}, nullptr);
  const auto r = fit_plant_posture(target, start, fit_options{}, fmus_of_this_build());
  std::cout << format_report(r);

  ASSERT_EQ(r.plant.size(), 1u);
  EXPECT_GT(r.plant[0].before, 10.0);  // the default stance leans forward by ~13 deg
  EXPECT_LE(std::abs(r.plant[0].after), 0.5);
  const offset_result& hip = r.offsets[*find_offset("hip_pitch_offset")];
  EXPECT_TRUE(hip.fitted);
  EXPECT_TRUE(hip.identifiable);
  EXPECT_GT(hip.stddev, 0.0);
  for (const offset_result& o : r.offsets)
    if (&o != &hip) {
      EXPECT_EQ(o.after, o.before);
    }
  EXPECT_LE(r.evaluations, 40);

  const fs::path out = dir.path() / "upright.ini";
  write_fitted_config(k_default_config, out, r);
  EXPECT_LE(std::abs(settled_pitch_with(out, 1.6)), 0.5);
  EXPECT_GT(std::abs(settled_pitch_with(k_default_config, 1.6)), 10.0);
}

TEST(calibration_plant_fit, every_settle_starts_from_the_same_snapshot) {
  plant_options o = fmus_of_this_build();
  o.settle_s = 0.4;
  plant_simulator sim(o, gait::walking_params{}, gait::ik_mode::darwin);
  offset_values x = get_offsets(gait::walking_params{});
  x[6] = 5.0;
  const plant_posture a = sim.settle(x);
  x[6] = 13.0;
  const plant_posture b = sim.settle(x);
  x[6] = 5.0;
  const plant_posture c = sim.settle(x);
  EXPECT_EQ(a.pitch_deg, c.pitch_deg);
  EXPECT_EQ(a.height_m, c.height_m);
  EXPECT_EQ(a.com_x, c.com_x);
  EXPECT_NE(a.pitch_deg, b.pitch_deg);
  EXPECT_EQ(sim.evaluations(), 3);
  // the default stance keeps the CoM over the middle of the feet
  EXPECT_LT(std::abs(b.com_x - b.support_x), 0.005);
  EXPECT_LT(std::abs(b.com_y - b.support_y), 0.005);
  EXPECT_GT(b.left_force, 5.0);
  EXPECT_GT(b.right_force, 5.0);
}

TEST(calibration_plant_fit, impossible_or_inconsistent_requests_are_errors) {
  const plant_target roll = parse_plant_target("[Plant Target]\nroll_deg = 1\n", "roll.ini");
  try {
    fit_plant_posture(roll, gait::walking_params{}, fit_options{}, fmus_of_this_build());
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("roll.ini: no offset drives the torso roll"));
  }

  plant_options o = fmus_of_this_build();
  o.system = make_standing_system();
  o.system->components.pop_back();  // no robot
  EXPECT_THROW(plant_simulator(o, gait::walking_params{}, gait::ik_mode::darwin),
               cosim::validation_error);
}

// The ground-truth path reproduces what plant_simulator settles to, bit for bit: a target recorded
// with it is exactly the plant's posture at the known offsets.
TEST(calibration_plant_fit, the_hand_built_standing_system_settles_like_the_plant_simulator) {
  plant_simulator sim(fmus_of_this_build(), gait::walking_params{}, gait::ik_mode::darwin);
  for (const offset_values& v :
       {defaults_with("hip_pitch_offset", 7.5), defaults_with("z_offset", 30.0)}) {
    const plant_posture a = sim.settle(v);
    const settled_robot b = settle_independently(standing_system_by_hand(), v);
    EXPECT_DOUBLE_EQ(a.pitch_deg, b.pitch_deg);
    EXPECT_DOUBLE_EQ(a.roll_deg, b.roll_deg);
    EXPECT_DOUBLE_EQ(a.height_m, b.height_m);
    EXPECT_DOUBLE_EQ(a.com_x, b.com_x);
    EXPECT_DOUBLE_EQ(a.com_y, b.com_y);
  }
}

// A single-target fit stops once the residual is within half a sigma (plant_fit.cpp), so the
// offset ends within 0.5 sigma / |slope| of the truth, plus one plateau of the staircase (the gait
// outputs whole servo counts). Its reported 1 sigma is sigma / |slope| for one residual and one
// offset; the slope is measured here with two independent settles 1 unit either side of the truth
// (the covariance takes its own at the fitted point: 10 % covers the difference, 2-4 % here).
struct single_target_check {
  const char* offset;
  double truth;
  double sigma;    // the target's sigma, in the quantity's unit
  double plateau;  // offset change that is sure to move the plant off one plateau
  double (*quantity)(const settled_robot&);
  cosim::system_structure system = standing_system_by_hand();
};

void check_single_target_fit(const single_target_check& c, double recorded,
                             const calibration_report& r) {
  std::cout << format_report(r);
  const std::size_t i = *find_offset(c.offset);
  const offset_result& o = r.offsets[i];
  ASSERT_TRUE(o.fitted) << c.offset;
  ASSERT_TRUE(o.identifiable) << c.offset << ": " << o.note;
  EXPECT_TRUE(r.converged) << r.termination;
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  for (const offset_result& other : r.offsets)
    if (&other != &o) {
      EXPECT_EQ(other.after, other.before) << offset_table()[other.index].key;
    }

  offset_values lo = get_offsets(gait::walking_params{}), hi = lo;
  lo[i] = c.truth - 1;
  hi[i] = c.truth + 1;
  const double slope = (c.quantity(settle_independently(c.system, hi)) -
                        c.quantity(settle_independently(c.system, lo))) /
                       2;
  ASSERT_GT(std::abs(slope), 0.1 * c.sigma) << c.offset << " hardly moves the target";
  EXPECT_NEAR(o.after, c.truth, 0.5 * c.sigma / std::abs(slope) + c.plateau)
      << c.offset << ": slope " << slope;
  // the right side of the start value, i.e. the offset was moved the right way
  EXPECT_EQ(o.after > o.before, c.truth > o.before) << c.offset;
  EXPECT_NEAR(o.stddev, c.sigma / std::abs(slope), 0.1 * c.sigma / std::abs(slope)) << c.offset;

  // the report: target as given, before/after as the plant settles at those offsets
  ASSERT_EQ(r.plant.size(), 1u);
  const settled_robot before = settle_independently(c.system, get_offsets(gait::walking_params{}));
  const settled_robot after = settle_independently(c.system, get_offsets(r.fitted));
  EXPECT_DOUBLE_EQ(r.plant[0].before, c.quantity(before));
  EXPECT_DOUBLE_EQ(r.plant[0].after, c.quantity(after));
  EXPECT_EQ(r.plant[0].target, recorded);
  EXPECT_EQ(r.plant[0].sigma, c.sigma);
  EXPECT_LE(std::abs(r.plant[0].after - r.plant[0].target), 0.5 * c.sigma);
}

TEST(calibration_plant_fit,
     a_non_zero_torso_pitch_gives_back_the_hip_pitch_offset_it_was_recorded_with) {
  // hip_pitch_offset 7.5 deg instead of 13: the torso leans forward by ~7.4 deg, not ~12.9
  single_target_check c{"hip_pitch_offset", 7.5, 0.2, 0.088,
                        [](const settled_robot& s) { return s.pitch_deg; }};
  plant_target target;
  target.source = "pitch.ini";
  target.pitch_deg = c.quantity(settle_independently(c.system, defaults_with(c.offset, c.truth)));
  target.pitch_sigma_deg = c.sigma;
  ASSERT_GT(*target.pitch_deg, 5.0);
  check_single_target_fit(
      c, *target.pitch_deg,
      fit_plant_posture(target, gait::walking_params{}, fit_options{}, fmus_of_this_build()));
}

TEST(calibration_plant_fit, a_torso_height_target_gives_back_the_z_offset_it_was_recorded_with) {
  // z_offset 30 mm instead of 20: the torso stands ~10 mm lower than the default ~0.317 m
  single_target_check c{"z_offset", 30.0, 0.0005, 0.3,
                        [](const settled_robot& s) { return s.height_m; }};
  plant_target target;
  target.source = "height.ini";
  target.height_m = c.quantity(settle_independently(c.system, defaults_with(c.offset, c.truth)));
  target.height_sigma_m = c.sigma;
  ASSERT_LT(*target.height_m, 0.31);
  check_single_target_fit(
      c, *target.height_m,
      fit_plant_posture(target, gait::walking_params{}, fit_options{}, fmus_of_this_build()));
}

TEST(calibration_plant_fit, a_torso_roll_target_gives_back_the_z_offset_of_a_one_sided_plant) {
  // z_offset 17 mm instead of 20 on the plant whose left leg is held: the torso rolls ~-1.1 deg
  single_target_check c{"z_offset",
                        17.0,
                        0.2,
                        0.3,
                        [](const settled_robot& s) { return s.roll_deg; },
                        standing_system_by_hand(false)};
  plant_target target;
  target.source = "roll.ini";
  target.roll_deg = c.quantity(settle_independently(c.system, defaults_with(c.offset, c.truth)));
  target.roll_sigma_deg = c.sigma;
  ASSERT_LT(*target.roll_deg, -0.5);
  fit_options fit;
  fit.fit = {*find_offset(c.offset)};
  plant_options plant = fmus_of_this_build();
  plant.system = c.system;
  check_single_target_fit(c, *target.roll_deg,
                          fit_plant_posture(target, gait::walking_params{}, fit, plant));
}

TEST(calibration_plant_fit,
     com_over_support_brings_x_offset_back_to_the_centred_stance_from_either_side) {
  // The default stance, x_offset -10 mm, has the CoM over the middle of the feet (within 0.1 mm,
  // docs/calibration.md): starting 15 mm behind or ahead, the fit must come back to it. The feet
  // stay where the robot was put, so the CoM moves by what the independent settles say.
  plant_target target;
  target.source = "com.ini";
  target.com_over_support = true;
  target.com_sigma_m = 0.0005;
  const cosim::system_structure system = standing_system_by_hand();
  const double com_slope = (settle_independently(system, defaults_with("x_offset", -9)).com_x -
                            settle_independently(system, defaults_with("x_offset", -11)).com_x) /
                           2;
  ASSERT_LT(com_slope, -0.5e-3);  // feet forward: the body, and the CoM, backward
  for (const double start : {-25.0, 5.0}) {
    const auto r = fit_plant_posture(target, params_with(defaults_with("x_offset", start)),
                                     fit_options{}, fmus_of_this_build());
    std::cout << format_report(r);
    const offset_result& x = r.offsets[*find_offset("x_offset")];
    ASSERT_TRUE(x.fitted && x.identifiable) << x.note;
    EXPECT_TRUE(r.converged) << r.termination;
    // 0.5 sigma / |slope| (where the fit stops) + 0.13 mm (the doc's 0.1 mm) + one plateau
    EXPECT_NEAR(x.after, -10.0, 0.5 * target.com_sigma_m / -com_slope + 0.13 + 0.3) << start;
    EXPECT_NEAR(x.stddev, target.com_sigma_m / -com_slope, 0.1 * target.com_sigma_m / -com_slope);
    for (const offset_result& o : r.offsets)
      if (&o != &x) {
        EXPECT_EQ(o.after, o.before) << offset_table()[o.index].key;
      }

    ASSERT_EQ(r.plant.size(), 2u);
    const plant_result& dx = r.plant[0];
    const plant_result& dy = r.plant[1];
    EXPECT_EQ(dx.name, "com_dx_m");
    EXPECT_EQ(dy.name, "com_dy_m");
    // x: the CoM was ahead of the feet (start behind) or behind them, by the slope's amount
    const double com_before = settle_independently(system, defaults_with("x_offset", start)).com_x;
    const double com_after = settle_independently(system, get_offsets(r.fitted)).com_x;
    EXPECT_NEAR(dx.before - dx.after, com_before - com_after, 1e-4);
    EXPECT_NEAR(dx.before, com_slope * (start + 10), 0.1 * std::abs(com_slope * (start + 10)));
    EXPECT_LE(std::abs(dx.after), 0.5 * target.com_sigma_m);
    // y: a left/right symmetric stance keeps the CoM over the middle of the feet
    EXPECT_LT(std::abs(dy.before), 1e-4);
    EXPECT_LT(std::abs(dy.after), 1e-4);
  }
}

TEST(calibration_plant_fit,
     pitch_and_height_targets_give_back_both_offsets_they_were_recorded_with) {
  // hip_pitch_offset down from 13 to 9 deg and z_offset up from 20 to 27 mm at once
  const cosim::system_structure system = standing_system_by_hand();
  offset_values truth = defaults_with("hip_pitch_offset", 9.0);
  const std::size_t hip = *find_offset("hip_pitch_offset"), z = *find_offset("z_offset");
  truth[z] = 27.0;
  const settled_robot recorded = settle_independently(system, truth);
  plant_target target;
  target.source = "pitch_height.ini";
  target.pitch_deg = recorded.pitch_deg;
  target.height_m = recorded.height_m;
  target.pitch_sigma_deg = 0.2;
  target.height_sigma_m = 0.0005;
  const auto r =
      fit_plant_posture(target, gait::walking_params{}, fit_options{}, fmus_of_this_build());
  std::cout << format_report(r);
  EXPECT_TRUE(r.converged) << r.termination;

  // the Jacobian (in sigmas per unit) by hand, from independent settles 1 unit either side
  const auto in_sigmas = [&](const settled_robot& s) {
    return std::array<double, 2>{s.pitch_deg / target.pitch_sigma_deg,
                                 s.height_m / target.height_sigma_m};
  };
  double j[2][2];
  for (int c = 0; c < 2; ++c) {
    offset_values lo = truth, hi = truth;
    const std::size_t i = c == 0 ? hip : z;
    lo[i] -= 1;
    hi[i] += 1;
    const auto l = in_sigmas(settle_independently(system, lo));
    const auto h = in_sigmas(settle_independently(system, hi));
    for (int k = 0; k < 2; ++k)
      j[k][c] = (h[static_cast<std::size_t>(k)] - l[static_cast<std::size_t>(k)]) / 2;
  }
  const double det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
  ASSERT_GT(std::abs(det), 1.0);
  const double inv[2][2] = {{j[1][1] / det, -j[0][1] / det}, {-j[1][0] / det, j[0][0] / det}};
  // covariance (J^T J)^-1 = J^-1 J^-T for a square J: the reported 1 sigma of each offset
  const double sd[2] = {std::hypot(inv[0][0], inv[0][1]), std::hypot(inv[1][0], inv[1][1])};
  // the fit stops within 1/2 sigma in cost (|r| <= 1/2): each offset within |J^-1| * 1/2 + plateau
  const double tol[2] = {0.5 * (std::abs(inv[0][0]) + std::abs(inv[0][1])) + 0.088,
                         0.5 * (std::abs(inv[1][0]) + std::abs(inv[1][1])) + 0.3};
  int c = 0;
  for (const std::size_t i : {hip, z}) {
    const offset_result& o = r.offsets[i];
    ASSERT_TRUE(o.fitted && o.identifiable) << offset_table()[i].key << ": " << o.note;
    EXPECT_NEAR(o.after, truth[i], tol[c]) << offset_table()[i].key;
    EXPECT_EQ(o.after > o.before, truth[i] > o.before) << offset_table()[i].key;
    EXPECT_NEAR(o.stddev, sd[c], 0.1 * sd[c]) << offset_table()[i].key;
    ++c;
  }
  ASSERT_EQ(r.plant.size(), 2u);
  EXPECT_EQ(r.plant[0].name, "pitch_deg");
  EXPECT_EQ(r.plant[1].name, "height_m");
  EXPECT_EQ(r.plant[0].target, recorded.pitch_deg);
  EXPECT_EQ(r.plant[1].target, recorded.height_m);
}

}  // namespace
}  // namespace stride::calibration
