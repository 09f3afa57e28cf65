// Plant mode: gait.fmu + robot.fmu through the orchestrator library, settled from the same
// snapshot on every evaluation.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
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

}  // namespace
}  // namespace stride::calibration
