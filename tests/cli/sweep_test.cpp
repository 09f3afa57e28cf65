// `stride sweep` through the built CLI: grid and argument errors, every point run once and kept
// afterwards, failed points reported while the others go on, and a point's files equal to those
// of `stride run` of the same point (for the stride_test pair and for the speed map).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "png_size.hpp"
#include "process.hpp"
#include "stride/cosim/archive.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::quoted;
using test::run_command;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const fs::path k_data = STRIDE_TEST_DATA_DIR;
const std::string k_cli = STRIDE_CLI;
const fs::path k_pair = k_data / "stride_test_pair.xml";

std::string read(const fs::path& file) {
  return test::read_file(file);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::size_t line_count(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

// every file below `dir`, relative, but the manifest (it holds times and paths)
std::set<fs::path> files_below(const fs::path& dir) {
  std::set<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file() && e.path().filename() != "manifest.json") {
      files.insert(fs::relative(e.path(), dir));
    }
  }
  return files;
}

// the two folders hold the same files, byte for byte (manifests aside)
void expect_same_files(const fs::path& a, const fs::path& b) {
  const auto fa = files_below(a), fb = files_below(b);
  EXPECT_EQ(fa, fb) << a << " vs " << b;
  for (const auto& f : fa) {
    if (fb.count(f) == 0) continue;
    EXPECT_TRUE(read(a / f) == read(b / f)) << f << " differs between " << a << " and " << b;
  }
}

bool have_gnuplot() {
  return std::system("command -v gnuplot > /dev/null 2>&1") == 0;
}

class sweep_cli : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-sweep-test-"};
  // in the scratch folder: relative --output folders land there
  test::process_result stride(const std::string& args) {
    return run_command("cd " + quoted(scratch.path()) + " && '" + k_cli + "' " + args,
                       scratch.path());
  }
};

TEST_F(sweep_cli, help_names_the_grid_jobs_and_collectors) {
  const auto top = stride("--help");
  EXPECT_THAT(top.out, HasSubstr("sweep"));
  const auto r = stride("sweep --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* option : {"--grid", "--set", "--jobs", "--output", "--stop-time", "--collect",
                             "speed-map", "comp.var=name:min:max:step"}) {
    EXPECT_THAT(r.out, HasSubstr(option));
  }
}

TEST_F(sweep_cli, bad_arguments_are_one_line_errors_naming_the_argument) {
  const std::string pair = "sweep " + quoted(k_pair) + " --output out --quiet ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--grid a.gain=1:2", "--grid 'a.gain=1:2': '1:2' is not name:min:max:step"},
      {"--grid gain=1:2:1", "--grid 'gain=1:2:1': expected comp.var=name:min:max:step"},
      {"--grid a.gain=x:1:2:1,y:1:2", "--grid 'a.gain=x:1:2:1,y:1:2': 'y:1:2' is not"},
      {"--grid a.gain=1:two:1", "'1:two:1': min, max and step must be numbers"},
      {"--grid a.gain=2:1:1", "'2:1:1': need step > 0 and max >= min"},
      {"--grid nosuch.gain=1:2:1", "--grid 'nosuch.gain=1:2:1': "},
      {"--grid a.gain=1:2:1 --stop-time soon", "--stop-time: "},
      {"--grid a.gain=1:2:1 --step 0", "--step must be positive"},
      {"--grid a.gain=1:2:1 --algorithm newton", "--algorithm newton: not gauss-seidel or jacobi"},
      {"--grid a.gain=1:2:1 --set a.gain=3", "--set 'a.gain=3': a.gain is swept by --grid"},
      {"--grid a.gain=1:2:1 --collect nothing", "--collect 'nothing': expected"},
      {"--grid a.gain=1:2:1 --collect speed-map", "sweep one learner's eval_point"},
      {"--grid a.gain=1:2:1 --set a.no_such_variable=1", "point 1 cannot run: "},
  };
  for (const auto& [args, message] : cases) {
    const auto r = stride(pair + args);
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_THAT(r.err, StartsWith("stride: error: ")) << args;
    EXPECT_THAT(r.err, HasSubstr(message)) << args;
    EXPECT_EQ(line_count(r.err), 1u) << args << ": " << r.err;
  }
  EXPECT_THAT(stride(pair + "--grid a.gain=1:2:1 --set a.no_such_variable=1").err,
              HasSubstr("no_such_variable"));
  EXPECT_FALSE(fs::exists(scratch.path() / "out" / "points"));  // nothing ran
  EXPECT_NE(stride(pair + "--grid a.gain=1:2:1 --jobs 0").exit_code, 0);
  EXPECT_NE(stride("sweep " + quoted(k_pair) + " --output out").exit_code, 0);  // no --grid
}

// a point's folder holds exactly what `stride run` of that point writes
TEST_F(sweep_cli, a_point_equals_stride_run_of_that_point) {
  const auto r = stride("sweep " + quoted(k_pair) +
                        " --grid a.gain=1:3:2 --grid b.gain=0.5:0.7:0.1 --set a.offset=0.25 "
                        "--stop-time 0.5 --jobs 2 --quiet --output out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* point : {"1_0.6", "3_0.7"}) {
    const std::string a = std::string(point).substr(0, 1), b = std::string(point).substr(2);
    const auto single = stride("run " + quoted(k_pair) +
                               " --quiet --stop-time 0.5 --set a.offset=0.25 --set a.gain=" + a +
                               " --set b.gain=" + b + " --output single_" + point);
    ASSERT_EQ(single.exit_code, 0) << single.err;
    expect_same_files(scratch.path() / "out" / "points" / point,
                      scratch.path() / ("single_" + std::string(point)));
  }
}

// --step and --algorithm reach every point, and a sweep into the same folder must repeat them
TEST_F(sweep_cli, the_step_and_algorithm_given_apply_to_every_point) {
  const std::string sweep =
      "sweep " + quoted(k_pair) + " --grid a.gain=1:2:1 --stop-time 0.05 --quiet --output out";
  const auto r = stride(sweep + " --step 0.005 --algorithm jacobi");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto single = stride("run " + quoted(k_pair) +
                             " --quiet --stop-time 0.05 --set a.gain=2 --step 0.005 "
                             "--algorithm jacobi --output single");
  ASSERT_EQ(single.exit_code, 0) << single.err;
  expect_same_files(scratch.path() / "out" / "points" / "2", scratch.path() / "single");
  // the header and t = 0, 0.005, ..., 0.05: the step given, not the system's 0.01
  EXPECT_EQ(line_count(read(scratch.path() / "single" / "results.csv")), 12u);
  const auto other = stride(sweep + " --step 0.01");
  EXPECT_EQ(other.exit_code, 1);
  EXPECT_THAT(other.err, HasSubstr("out"));
}

TEST_F(sweep_cli, failed_points_are_reported_the_others_tabled_and_finished_ones_kept) {
  // fail_at_step 50 ends those points with an error at step 50 of 100
  const std::string args = "sweep " + quoted(k_pair) +
                           " --grid a.fail_at_step=0:50:50 --grid a.gain=1:3:2 --stop-time 1 "
                           "--jobs 2 --output out --collect results.csv:b.y "
                           "--collect n=results.csv:b.y:count";
  const auto r = stride(args);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("stride sweep: point 50,1 failed: "));
  EXPECT_THAT(r.err, HasSubstr("stride sweep: point 50,3 failed: "));
  EXPECT_THAT(r.err, HasSubstr("2 of 4 points failed (50,1; 50,3)"));
  EXPECT_THAT(r.err, HasSubstr("sweep: 4/4 points (0 kept, 2 failed)"));
  const fs::path out = scratch.path() / "out";
  // b.y = 2 b.u = 2 a.y = 2 a.gain (u = 1, offsets 0, b keeps gain 2); t = 0 .. 1 s: 101 rows
  EXPECT_EQ(lines_of(read(out / "sweep.csv")),
            (std::vector<std::string>{"fail_at_step,gain,b.y,n", "0,1,2,101", "0,3,6,101"}));
  if (have_gnuplot()) {
    EXPECT_EQ(stride::test::png_size(out / "sweep.png"),
              std::make_pair(1400u, 600u));  // two panels
  }

  // again: the finished points are kept, the failed ones run (and fail) again
  const fs::path kept = out / "points" / "0_3" / "manifest.json";
  const auto stamp = fs::last_write_time(kept);
  const auto again = stride(args);
  EXPECT_EQ(again.exit_code, 1);
  EXPECT_THAT(again.err, HasSubstr("sweep: 4/4 points (2 kept, 2 failed)"));
  EXPECT_EQ(fs::last_write_time(kept), stamp);
  EXPECT_EQ(lines_of(read(out / "sweep.csv")).size(), 3u);

  // the folder belongs to that sweep: other settings are refused, naming what differs
  const auto other = stride("sweep " + quoted(k_pair) +
                            " --grid a.fail_at_step=0:50:50 --grid a.gain=1:3:2 --stop-time 2 "
                            "--output out");
  EXPECT_EQ(other.exit_code, 1);
  EXPECT_THAT(other.err, HasSubstr("holds a sweep with other settings"));
  EXPECT_THAT(other.err, HasSubstr("'stop_time = 1'; now 'stop_time = 2'"));
}

#ifdef STRIDE_HAVE_DARWIN_FMUS
// The speed map of three states of Experiment 1's grid, 10 s each: every point's files are
// those of `stride run` of that point, and the table holds its evaluation.
TEST_F(sweep_cli, speed_map_points_equal_stride_run_of_the_point) {
  const fs::path system = fs::path(STRIDE_SOURCE_DIR) / "models/experiments/evaluate-point.xml";
  const std::string grid = "period_time:450:960:255,swing_right_left:15:15:2";
  const auto r = stride("sweep " + quoted(system) + " --grid eval.eval_point=" + grid +
                        " --collect speed-map --stop-time 10 --jobs 2 --output map");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path map = scratch.path() / "map";
  const auto rows = lines_of(read(map / "speed_map.csv"));
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0], "period_time,swing_right_left,windows,falls,mean_speed,mean_reward");
  EXPECT_THAT(rows[1], StartsWith("450,15,"));
  EXPECT_THAT(rows[2], StartsWith("705,15,"));
  EXPECT_THAT(rows[3], StartsWith("960,15,"));
  EXPECT_THAT(r.out, HasSubstr("3 states, "));
  EXPECT_THAT(r.out, HasSubstr("fastest without falls: "));
  if (have_gnuplot()) {
    EXPECT_EQ(stride::test::png_size(map / "speed_map.png"), std::make_pair(1400u, 600u));
  }

  for (const char* point : {"450,15", "960,15"}) {
    std::string folder = point;
    std::replace(folder.begin(), folder.end(), ',', '_');
    const auto single = stride("run " + quoted(system) +
                               " --quiet --no-plots --stop-time 10 --set eval.grid=" + grid +
                               " --set eval.eval_point=" + point + " --output single_" + folder);
    ASSERT_EQ(single.exit_code, 0) << single.err;
    const fs::path swept = map / "points" / folder;
    ASSERT_TRUE(fs::exists(swept / "evaluation.csv"));
    expect_same_files(swept, scratch.path() / ("single_" + folder));
  }
}
#endif

}  // namespace
}  // namespace stride::cosim
