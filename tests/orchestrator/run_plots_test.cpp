// Figures of any run (stride/cosim/run_plots.hpp): which columns make a pose, what the data
// files and scripts hold, and that nothing is left behind when there is nothing to draw.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/run_plots.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

bool have_gnuplot() {
  return std::system("command -v gnuplot > /dev/null 2>&1") == 0;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> read_lines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<double> numbers(const std::string& line) {
  std::istringstream in(line);
  std::vector<double> out;
  for (double v; in >> v;) out.push_back(v);
  return out;
}

// a results file as csv_recorder writes it: time, then the columns; row i has time i/10 and
// column k the value `value(i, k)`
struct fake_results {
  std::vector<std::string> columns;
  int rows = 6;
  static double value(int i, std::size_t k) { return std::sin(0.3 * i + static_cast<double>(k)); }
  void write(const fs::path& file) const {
    fs::create_directories(file.parent_path());
    std::ofstream out(file);
    out << "time";
    for (const auto& c : columns) out << "," << c;
    out << "\n";
    for (int i = 0; i < rows; ++i) {
      out << i / 10.0;
      out.precision(17);
      for (std::size_t k = 0; k < columns.size(); ++k) out << "," << value(i, k);
      out << "\n";
    }
  }
};

bool is_png(const fs::path& file) {
  return read_text(file).starts_with("\x89PNG");
}

class run_plots : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-run-plots-test-"};
  fs::path run = scratch.path() / "run";
  fake_results results{{"robot.base_x", "robot.base_y", "robot.base_z", "gait.phase",
                        "gait.footsteps", "other.base_x", "robot.fallen"}};
  void SetUp() override { results.write(run / "results.csv"); }
};

TEST(run_plots_rules, a_pose_is_a_base_x_with_the_base_y_of_the_same_prefix) {
  EXPECT_THAT(
      pose_prefixes({"time", "robot.base_x", "robot.base_z", "robot.base_y", "walker[2].base_y",
                     "walker[2].base_x", "lone.base_x", "base_x", "other.base_y"}),
      ElementsAre("robot", "walker[2]"));
  EXPECT_TRUE(pose_prefixes({"a.x", "a.y"}).empty());
}

TEST(run_plots_rules, signal_patterns_are_split_at_commas_and_empty_ones_refused) {
  EXPECT_THAT(split_signal_patterns({"robot.base_z, gait.*", "x?"}),
              ElementsAre("robot.base_z", "gait.*", "x?"));
  try {
    split_signal_patterns({"robot.base_z,,gait.*"});
    ADD_FAILURE() << "no error";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("'robot.base_z,,gait.*': empty pattern"));
  }
}

TEST_F(run_plots, the_results_file_is_the_one_the_manifest_names) {
  EXPECT_EQ(run_results_file(run), run / "results.csv");
  results.write(run / "results-2.csv");
  std::ofstream(run / "manifest.json") << "{\n  \"status\": \"ok\",\n  \"results\": "
                                          "\"results-2.csv\",\n  \"components\": []\n}\n";
  EXPECT_EQ(run_results_file(run), run / "results-2.csv");
  EXPECT_EQ(run_results_file(scratch.path()), fs::path());
}

TEST_F(run_plots, a_pose_path_and_chosen_signals_are_drawn_from_the_results) {
  if (!have_gnuplot()) GTEST_SKIP() << "no gnuplot";
  const auto files = write_run_plots(run, {"robot.base_z", "gait.*"});
  const fs::path fig = run / "figures";
  EXPECT_THAT(files, ElementsAre(fig / "path_robot.png", fig / "signal_robot.base_z.png",
                                 fig / "signal_gait.phase.png", fig / "signal_gait.footsteps.png"));
  for (const auto& f : files) EXPECT_TRUE(is_png(f)) << f;
  // "other" has no base_y: no path; robot.fallen was not chosen
  EXPECT_FALSE(fs::exists(fig / "path_other.png"));
  EXPECT_FALSE(fs::exists(fig / "signal_robot.fallen.png"));

  // the path's data: time, x, y of every results row
  const auto path = read_lines(fig / "path_robot.dat");
  ASSERT_EQ(path.size(), 1u + results.rows);
  EXPECT_EQ(path[0], "# time robot.base_x robot.base_y");
  for (int i = 0; i < results.rows; ++i) {
    const auto v = numbers(path[1 + i]);
    ASSERT_EQ(v.size(), 3u) << path[1 + i];
    EXPECT_DOUBLE_EQ(v[0], i / 10.0);
    EXPECT_DOUBLE_EQ(v[1], fake_results::value(i, 0));  // robot.base_x
    EXPECT_DOUBLE_EQ(v[2], fake_results::value(i, 1));  // robot.base_y
  }
  const std::string gp = read_text(fig / "path_robot.gp");
  EXPECT_THAT(gp, HasSubstr("using 2:3"));
  EXPECT_THAT(gp, HasSubstr("set output '" + (fig / "path_robot.png").string() + "'"));

  const auto z = read_lines(fig / "signal_robot.base_z.dat");
  ASSERT_EQ(z.size(), 1u + results.rows);
  EXPECT_EQ(z[0], "# time robot.base_z");
  for (int i = 0; i < results.rows; ++i) {
    const auto v = numbers(z[1 + i]);
    ASSERT_EQ(v.size(), 2u);
    EXPECT_DOUBLE_EQ(v[1], fake_results::value(i, 2));
  }
  EXPECT_EQ(read_lines(fig / "signal_gait.footsteps.dat")[0], "# time gait.footsteps");
  EXPECT_THAT(read_text(fig / "signal_gait.phase.gp"), HasSubstr("using 1:2"));
}

TEST_F(run_plots, runs_in_the_folders_below_get_their_folder_as_prefix) {
  if (!have_gnuplot()) GTEST_SKIP() << "no gnuplot";
  fake_results walker{{"w[1].base_x", "w[1].base_y"}, 4};
  walker.write(run / "agent2" / "results.csv");
  const auto files = write_run_plots(run, {});
  const fs::path fig = run / "figures";
  EXPECT_THAT(files, ElementsAre(fig / "path_robot.png", fig / "agent2_path_w_1_.png"));
  EXPECT_EQ(read_lines(fig / "agent2_path_w_1_.dat")[0], "# time w[1].base_x w[1].base_y");
  EXPECT_EQ(read_lines(fig / "agent2_path_w_1_.dat").size(), 5u);
}

TEST_F(run_plots, nothing_to_draw_leaves_no_figures_folder) {
  fake_results plain{{"a.y", "b.echo"}};
  const fs::path other = scratch.path() / "plain";
  plain.write(other / "results.csv");
  EXPECT_TRUE(write_run_plots(other, {}).empty());
  EXPECT_FALSE(fs::exists(other / "figures"));
  // no results at all
  fs::create_directories(scratch.path() / "empty");
  EXPECT_TRUE(write_run_plots(scratch.path() / "empty", {}).empty());
  EXPECT_FALSE(fs::exists(scratch.path() / "empty" / "figures"));
  EXPECT_THROW(write_run_plots(scratch.path() / "empty", {"a.*"}), validation_error);
}

TEST_F(run_plots, a_pattern_matching_no_column_is_named_and_nothing_is_left_behind) {
  try {
    write_run_plots(run, {"gait.*", "robot.bse_z"});
    ADD_FAILURE() << "no error";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("pattern 'robot.bse_z' matches no column"));
    EXPECT_THAT(e.what(), HasSubstr("results.csv"));
  }
  EXPECT_FALSE(fs::exists(run / "figures"));
}

TEST_F(run_plots, a_value_that_is_no_number_is_named_with_file_line_and_column) {
  std::ofstream(run / "results.csv") << "time,robot.base_x,robot.base_y\n0,1,2\n0.1,1,oops\n";
  try {
    write_run_plots(run, {});
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(),
                HasSubstr("results.csv:3: column 'robot.base_y': 'oops' is not a number"));
  }
  EXPECT_FALSE(fs::exists(run / "figures"));
}

}  // namespace
}  // namespace stride::cosim
