// The study's link between learner and gait: grid checks against the gait's ranges (from the
// system's parameters) and the best config.ini written from a V table and the gait's settings.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/learner/artefacts.hpp"
#include "stride/study/gait_link.hpp"

namespace stride::study {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(study_gait_link, out_of_range_gait_parameters_are_errors_naming_the_parameter) {
  using learner::state_grid;
  EXPECT_THAT(error_of([] { check_grid_against_gait(state_grid::parse("period_time:0:900:15")); }),
              HasSubstr("grid dimension period_time: walking parameter 'period_time' = 0"));
  EXPECT_THAT(
      error_of([] { check_grid_against_gait(state_grid::parse("swing_right_left:-4:30:2")); }),
      HasSubstr("swing_right_left"));
  EXPECT_THAT(error_of([] { check_grid_against_gait(state_grid::parse("dsp_ratio:0.5:1:0.5")); }),
              HasSubstr("dsp_ratio"));
  // a parameter the gait does not know is passed on unchecked (it may drive anything)
  EXPECT_NO_THROW(check_grid_against_gait(state_grid::parse("something_else:-5:5:1")));
}

TEST(study_gait_link, the_learners_of_a_system_are_checked_naming_file_and_line) {
  cosim::system_structure s;
  s.add_component("gait", "gait");
  auto& l = s.add_component("agent", "learner");
  l.parameters.push_back({"grid", "period_time:450:960:15", {"exp.xml", 12}});
  EXPECT_NO_THROW(check_learner_grids(s));
  l.parameters.push_back({"eval_point", "-5", {"exp.xml", 13}});
  EXPECT_THAT(error_of([&] { check_learner_grids(s); }),
              HasSubstr("exp.xml:13: agent.eval_point dimension period_time"));
  l.parameters[0].value = "period_time:-15:960:15";
  EXPECT_THAT(error_of([&] { check_learner_grids(s); }),
              HasSubstr("exp.xml:12: agent.grid dimension period_time"));
  // other components are not learners
  s.components[1].fmu = "other";
  EXPECT_NO_THROW(check_learner_grids(s));
}

std::string read_all(const fs::path& f) {
  std::ifstream in(f);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(study_gait_link, the_best_state_goes_into_the_gaits_config_ini) {
  cosim::temp_dir dir("stride-study-");
  const auto grid = learner::state_grid::parse("period_time:450:960:15,swing_right_left:15:39:2");
  learner::dense_value_table v(grid.size());
  v.add(grid.find({645, 29}, "t"), 10.0);
  learner::write_value_table(dir.path() / learner::run_files::value_table, grid, v);

  // the system as run: the learner drives gait.period_time and gait.swing_right_left
  cosim::system_structure s;
  auto& gait = s.add_component("gait", "gait");
  gait.parameters = {{"x_move", "20", {}}, {"balance_hip_roll_gain", "0", {}}};
  auto& l = s.add_component("learner", "learner");
  l.parameters = {{"grid", grid.str(), {}}, {"output_dir", dir.path().string(), {}}};
  s.connect("learner.value[1]", "gait.period_time");
  s.connect("learner.value[2]", "gait.swing_right_left");
  ASSERT_EQ(write_best_configs(s), std::vector<fs::path>{dir.path() / "config.ini"});
  const std::string text = read_all(dir.path() / "config.ini");
  EXPECT_THAT(text, HasSubstr("period_time=645.000000"));
  EXPECT_THAT(text, HasSubstr("swing_right_left=29.000000"));
  EXPECT_THAT(text, HasSubstr("balance_hip_roll_gain=0.000000"));    // the gait's setting
  EXPECT_THAT(text, HasSubstr("balance_ankle_roll_gain=1.000000"));  // framework default

  // evaluation runs have no best state
  l.parameters.push_back({"mode", "1", {}});
  fs::remove(dir.path() / "config.ini");
  EXPECT_TRUE(write_best_configs(s).empty());
}

}  // namespace
}  // namespace stride::study
