// `stride view` and `stride run --record-view` through the built CLI on short DARwIn walks:
// what is recorded and at which interval, the frames a page gets (window, decimation), and the
// errors for runs that lack what the viewer needs.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "process.hpp"
#include "stride/cosim/archive.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::quoted;
using test::run_command;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::string k_cli = STRIDE_CLI;
const fs::path k_walk = fs::path(STRIDE_SOURCE_DIR) / "models" / "walk.xml";

std::string first_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

std::string line(const fs::path& file, int n) {
  std::ifstream in(file);
  std::string text;
  for (int i = 0; i <= n; ++i) std::getline(in, text);
  return text;
}

class view_cli : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-view-test-"};
  test::process_result stride(const std::string& args) {
    return run_command("cd " + quoted(scratch.path()) + " && '" + k_cli + "' " + args,
                       scratch.path());
  }
  // a walk of `seconds` into folder `name`
  void walk(const std::string& name, const std::string& seconds, const std::string& args) {
    const auto r = stride("run " + quoted(k_walk) + " --quiet --stop-time " + seconds + " -o " +
                          name + " " + args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  fs::path out(const std::string& name) const { return scratch.path() / name; }
};

TEST_F(view_cli, help_documents_the_options) {
  const auto r = stride("view --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* option :
       {"--output", "--open", "--from", "--to", "--fps", "--robot", "--urdf"}) {
    EXPECT_THAT(r.out, HasSubstr(option));
  }
  EXPECT_THAT(stride("run --help").out, HasSubstr("--record-view"));
}

TEST_F(view_cli, record_view_writes_the_pose_joints_and_falls_beside_the_results) {
  walk("w", "1", "--record-view --record robot.base_x");
  // the results keep what was asked; view.csv has the viewer's signals
  EXPECT_EQ(first_line(out("w") / "results.csv"), "time,robot.base_x");
  const std::string header = first_line(out("w") / "view.csv") + ",";
  for (const char* column : {"robot.base_x", "robot.base_z", "robot.roll", "robot.yaw",
                             "robot.joint_angle[1]", "robot.joint_angle[20]", "robot.fallen"}) {
    EXPECT_THAT(header, HasSubstr(std::string(column) + ",")) << column;
  }
  // 0.032 s = 4 base steps of 8 ms: rows at 0, 0.032, 0.064
  EXPECT_THAT(line(out("w") / "view.csv", 2), StartsWith("0.032,"));
  EXPECT_THAT(line(out("w") / "view.csv", 3), StartsWith("0.064,"));
  // another interval is taken to the nearest multiple of the base step: 0.05 s → 6 × 8 ms
  walk("w2", "0.2", "--record-view --record-view-interval 0.05");
  EXPECT_THAT(line(out("w2") / "view.csv", 2), StartsWith("0.048,"));
}

TEST_F(view_cli, the_page_holds_the_frames_of_the_window_and_fetches_nothing) {
  walk("w", "4.8", "--record-view");
  // every row: 4.8 / 0.032 + 1 = 151 frames
  auto r = stride("view w --fps 0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("151 frames of robot from view.csv"));
  // 2 ≤ t ≤ 4: rows 63 (2.016 s) to 125 (4.0 s)
  r = stride("view w --fps 0 --from 2 --to 4 -o window.html");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("63 frames"));
  // 10 a second: the first row of each 0.1 s bin, 0 ... 4.8 s → 49 frames
  r = stride("view w --fps 10 -o ten.html");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("49 frames"));
  // self-contained: no script or resource from anywhere else
  const std::string html = test::read_file(out("w") / "view.html");
  for (const char* fetch :
       {"<script src", "<link", "src=\"http", "href=\"http", "import(\"http", "import('http"}) {
    EXPECT_EQ(html.find(fetch), std::string::npos) << fetch;
  }
  EXPECT_NE(html.find("WebGLRenderer"), std::string::npos) << "three.js inlined";
}

TEST_F(view_cli, a_run_without_the_pose_is_an_error_that_says_how_to_record_it) {
  walk("bare", "0.16", "--record gait.phase");
  auto r = stride("view bare");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, StartsWith("stride: error: bare: results.csv records no robot pose: the "
                                "viewer needs P.base_x, P.base_y, P.base_z, P.roll, P.pitch"));
  EXPECT_THAT(r.err, HasSubstr("stride run SYSTEM --record-view"));
  EXPECT_FALSE(fs::exists(out("bare") / "view.html"));
  // the pose without the joint angles: the missing columns are named
  walk("pose", "0.16", "--record 'robot.base_?,robot.roll,robot.pitch,robot.yaw'");
  r = stride("view pose");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("has no column robot.joint_angle[1], robot.joint_angle[2]"));
  EXPECT_THAT(r.err, HasSubstr("--record-view"));
  // not a run folder
  fs::create_directories(out("empty"));
  r = stride("view empty");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("holds no recorded signals"));
}

TEST_F(view_cli, the_model_is_the_urdf_the_run_used_or_the_one_named) {
  // the plant's urdf parameter names a file: the page draws that file
  const fs::path urdf = out("my-robot.urdf");
  fs::copy_file(fs::path(STRIDE_SOURCE_DIR) / "models" / "darwin-op" / "darwin-op.urdf", urdf);
  walk("custom", "0.16", "--record-view --set robot.urdf=" + quoted(urdf));
  auto r = stride("view custom");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("robot " + urdf.string()));
  // without it, the URDF in the FMU's resources
  walk("plain", "0.16", "--record-view");
  r = stride("view plain");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("robot robot.fmu:resources/darwin-op.urdf"));
  // --urdf draws another file, read as the plant reads it: a missing mesh file is refused,
  // naming the link and the file
  std::ofstream(out("mesh.urdf"))
      << "<robot name='m'><link name='base'><inertial><mass value='1'/><inertia ixx='1' "
         "iyy='1' izz='1' ixy='0' ixz='0' iyz='0'/></inertial><collision><geometry><mesh "
         "filename='base.stl'/></geometry></collision></link></robot>";
  r = stride("view plain --urdf mesh.urdf -o mesh.html");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("link 'base' collision mesh: mesh file 'base.stl' cannot be read"));
}

TEST_F(view_cli, several_robots_show_the_first_or_the_one_named) {
  const fs::path walkers = fs::path(STRIDE_SOURCE_DIR) / "models" / "walkers.xml";
  auto r = stride("run " + quoted(walkers) + " --quiet --stop-time 0.16 -o four --record-view");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = stride("view four");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("frames of robot[1] from view.csv"));
  r = stride("view four --robot 'robot[3]' -o three.html");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("frames of robot[3] from view.csv"));
  r = stride("view four --robot robot -o none.html");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("no pose of 'robot' in view.csv, results.csv (recorded poses: "
                               "robot[1], robot[2], robot[3], robot[4])"));
}

TEST_F(view_cli, a_learner_run_offers_its_episodes_and_shows_its_state) {
  // the demo learner cut to 2 episodes of 3 RL steps (about 10 s simulated)
  const fs::path demo = fs::path(STRIDE_SOURCE_DIR) / "models" / "experiments" / "demo.xml";
  auto r = stride("run " + quoted(demo) +
                  " --quiet --no-plots -o learn --record-view --set learner.total_steps=6 "
                  "--set learner.steps_per_episode=3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = stride("view learn --fps 0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("2 episodes to choose from"));
  const std::string html = test::read_file(out("learn") / "view.html");
  EXPECT_NE(html.find("{\"label\":\"learner.episode 1\",\"from\":0,"), std::string::npos);
  // the state's values are named by the gait parameters they drive
  for (const char* name : {"\"name\":\"gait.period_time\"", "\"name\":\"gait.swing_right_left\"",
                           "\"name\":\"learner.rl_step\""}) {
    EXPECT_NE(html.find(name), std::string::npos) << name;
  }
  // one episode alone: its rows only, from the first row at which learner.episode is 2
  r = stride("view learn --fps 0 --episode 2 -o two.html");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("1 episodes to choose from"));
  r = stride("view learn --episode 7 -o none.html");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("no row with learner.episode = 7"));
}

}  // namespace
}  // namespace stride::cosim
