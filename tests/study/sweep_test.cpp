// The study's part of `stride sweep`: the speed map's columns from an evaluation run's files,
// its summary, the overrides that go with sweeping an evaluator's point, and the heat maps.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "png_size.hpp"
#include "stride/learner/artefacts.hpp"
#include "stride/study/sweep.hpp"

namespace stride::study {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class study_sweep : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() /
        ("stride-study-sweep-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // an evaluation run's folder: evaluation.csv and steps.csv with these rewards
  fs::path evaluation(const std::string& name, std::int64_t windows, std::int64_t falls,
                      double speed, const std::vector<double>& rewards) {
    const fs::path d = dir_ / name;
    fs::create_directories(d);
    learner::evaluation_result r;
    r.point = {{"period_time", 600}, {"swing_right_left", 20}};
    r.windows = windows;
    r.falls = falls;
    r.mean_speed = speed;
    learner::write_evaluation(d, r);
    std::ofstream steps(d / learner::run_files::steps);
    steps << "rl_step,speed,reward\n";
    for (std::size_t i = 0; i < rewards.size(); ++i) {
      steps << i + 1 << ",1," << rewards[i] << "\n";
    }
    return d;
  }

  fs::path dir_;
};

TEST_F(study_sweep, a_point_counts_walked_windows_and_averages_the_reward) {
  // the evaluator counts a fall as a window: 12 windows with 2 falls are 10 walked
  const auto v = read_speed_map_point(evaluation("a", 12, 2, 9.5, {4, -10, 3}));
  ASSERT_EQ(v.size(), speed_map_columns().size());
  EXPECT_EQ(v[0], 10);
  EXPECT_EQ(v[1], 2);
  EXPECT_EQ(v[2], 9.5);
  EXPECT_EQ(v[3], -1);
  // nothing walked: no speed; nothing logged: no reward
  const auto fell = read_speed_map_point(evaluation("b", 1, 1, 0, {}));
  EXPECT_EQ(fell[0], 0);
  EXPECT_TRUE(std::isnan(fell[2]));
  EXPECT_TRUE(std::isnan(fell[3]));
}

TEST_F(study_sweep, a_missing_file_is_named) {
  fs::create_directories(dir_ / "empty");
  try {
    read_speed_map_point(dir_ / "empty");
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_THAT(e.what(), HasSubstr("evaluation.csv"));
  }
  const fs::path d = evaluation("c", 3, 0, 5, {1});
  fs::remove(d / learner::run_files::steps);
  EXPECT_THROW(read_speed_map_point(d), std::exception);
}

TEST_F(study_sweep, sweeping_an_eval_point_sets_the_evaluators_grid) {
  EXPECT_EQ(speed_map_overrides("eval.eval_point", "period_time:450:960:15"),
            std::vector<std::string>{"eval.grid=period_time:450:960:15"});
  EXPECT_THROW(speed_map_overrides("gait.x_move", "x:1:2:1"), std::runtime_error);
}

grid_table speed_map_table() {
  grid_table t;
  t.axes = {"period_time", "swing_right_left"};
  t.columns = speed_map_columns();
  // 450/15 fastest without a fall, 480/15 faster but fell, 450/17 fell at once
  t.axis_values = {{450, 15}, {450, 17}, {480, 15}, {480, 17}};
  t.values = {{10, 0, 12.5, 30}, {0, 3, std::nan(""), -200}, {8, 1, 14, 40}, {9, 0, 7.25, 5}};
  return t;
}

TEST_F(study_sweep, the_summary_names_the_fastest_states_without_a_fall_and_the_best_reward) {
  const std::string s = summarize_speed_map(speed_map_table());
  EXPECT_THAT(s, HasSubstr("4 states, 2 fell at least once\n"));
  EXPECT_THAT(s, HasSubstr("fastest without falls: 450/15 12.50 cm/s (0 falls, reward 30.0); "
                           "480/17 7.25 cm/s (0 falls, reward 5.0)\n"));
  EXPECT_THAT(s, HasSubstr("highest mean reward: 480/15 14.00 cm/s (1 falls, reward 40.0); "
                           "450/15"));
}

TEST_F(study_sweep, heat_maps_are_drawn_for_two_axes_only) {
  grid_table one = speed_map_table();
  one.axes = {"period_time"};
  EXPECT_THROW(write_grid_heat_map(one, dir_ / "one.png"), std::runtime_error);
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) GTEST_SKIP() << "no gnuplot";
  write_speed_map_figure(speed_map_table(), dir_ / "speed_map.png");
  EXPECT_EQ(test::png_size(dir_ / "speed_map.png"), std::make_pair(1400u, 600u));
  // the falls are marked from their own file
  std::ifstream falls(dir_ / "speed_map_falls.dat");
  std::string text((std::istreambuf_iterator<char>(falls)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "450 17 3\n480 15 1\n");
  write_grid_heat_map(speed_map_table(), dir_ / "grid.png");
  // four columns: panels of 700 x 600 pixels, three across
  EXPECT_EQ(test::png_size(dir_ / "grid.png"), std::make_pair(2100u, 1200u));
}

}  // namespace
}  // namespace stride::study
