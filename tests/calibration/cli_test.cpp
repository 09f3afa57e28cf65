// `stride calibrate`: help, exit codes, one-line errors naming file and line, both modes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "process.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/gait/config_ini.hpp"

namespace stride::calibration {
namespace {

namespace fs = std::filesystem;
using cosim::test::quoted;
using cosim::test::run_command;
using ::testing::HasSubstr;
using ::testing::Not;

const fs::path k_data = STRIDE_TEST_DATA_DIR;
const fs::path k_config =
    fs::path(STRIDE_SOURCE_DIR) / "components" / "gait_fmu" / "resources" / "config.ini";
const std::string k_cli = STRIDE_CLI;

class calibration_cli : public ::testing::Test {
 protected:
  cosim::temp_dir scratch{"stride-calibrate-cli-"};
  cosim::test::process_result stride(const std::string& args) {
    return run_command("'" + k_cli + "' calibrate " + args, scratch.path());
  }
  std::string args(const fs::path& target, const std::string& extra = "") {
    return "--target " + quoted(target) + " --config " + quoted(k_config) + " --output " +
           quoted(out()) + " " + extra;
  }
  fs::path out() const { return scratch.path() / "out.ini"; }
};

TEST_F(calibration_cli, help_lists_the_options) {
  const auto r = stride("--help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* option : {"--target", "--config", "--output", "--fit", "--mode", "--ik",
                             "--bound", "--loss-scale", "--system", "--report"})
    EXPECT_THAT(r.out, HasSubstr(option));
  EXPECT_THAT(run_command("'" + k_cli + "' --help", scratch.path()).out, HasSubstr("calibrate"));
}

TEST_F(calibration_cli, usage_errors_fail_without_output) {
  EXPECT_NE(stride("").exit_code, 0);
  EXPECT_NE(stride(args(k_data / "walk_ready.csv", "--mode sideways")).exit_code, 0);
  EXPECT_NE(stride(args(k_data / "walk_ready.csv", "--ik exact")).exit_code, 0);
  const auto r = stride(args(k_data / "walk_ready.csv", "--fit x_offset,knee_offset"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("stride: error: --fit: unknown offset 'knee_offset'"));
  const auto b = stride(args(k_data / "walk_ready.csv", "--bound x_offset=3:1"));
  EXPECT_EQ(b.exit_code, 1);
  EXPECT_THAT(b.err, HasSubstr("stride: error: --bound: bound 'x_offset=3:1'"));
  EXPECT_FALSE(fs::exists(out()));
}

TEST_F(calibration_cli, bad_target_files_give_one_line_naming_file_and_line) {
  const struct {
    const char* file;
    const char* message;
  } cases[] = {
      {"unknown_id.csv", ":4: unknown servo ID 21 (DARwIn-OP servo IDs are 1..20)"},
      {"duplicate_id.csv", ":4: duplicate servo ID 11 (first on line 2)"},
      {"non_numeric.csv", ":3: value 'abc' of servo 14 is not a number"},
      {"empty.csv", ": empty target: no joint rows"},
  };
  for (const auto& c : cases) {
    const auto r = stride(args(k_data / c.file));
    EXPECT_EQ(r.exit_code, 1) << c.file;
    EXPECT_EQ(r.err, "stride: error: " + (k_data / c.file).string() + c.message + "\n");
  }
  const auto p = stride(args(k_data / "bad_plant.ini", "--mode plant"));
  EXPECT_EQ(p.exit_code, 1);
  EXPECT_THAT(p.err, HasSubstr((k_data / "bad_plant.ini").string() + ":3: unknown key 'hieght_m'"));
  EXPECT_FALSE(fs::exists(out()));
}

TEST_F(calibration_cli, joint_mode_writes_the_config_and_the_report) {
  const fs::path report = scratch.path() / "report.txt";
  const auto r = stride(args(k_data / "walk_ready.csv",
                             "--fit x_offset,y_offset,z_offset,roll_offset,yaw_offset,"
                             "hip_pitch_offset --report " +
                                 quoted(report)));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("hip_pitch_offset"));
  EXPECT_THAT(r.out, HasSubstr("servo 20 (head_tilt)"));
  EXPECT_THAT(r.out, HasSubstr("written: " + out().string()));
  std::ifstream in(report);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), r.out);
  const auto fitted = gait::read_walking_config(out(), {}, nullptr);
  EXPECT_NEAR(fitted.hip_pitch_offset, 13.0, 0.2);
  EXPECT_EQ(fitted.pitch_offset, 0.0);
  EXPECT_EQ(fitted.period_time, 600.0);

  // quiet: nothing on stdout, the warnings on stderr
  const auto q = stride(args(k_data / "walk_ready.csv", "--quiet"));
  EXPECT_EQ(q.exit_code, 0);
  EXPECT_EQ(q.out, "");
  EXPECT_THAT(q.err, HasSubstr("stride: warning: x_offset, z_offset, pitch_offset, "
                               "hip_pitch_offset are not identifiable"));
}

TEST_F(calibration_cli, a_posture_plan_file_gives_back_all_seven_offsets) {
  // data/posture_plan.csv: the recommended plan recorded with known offsets (its header)
  const auto r = stride(args(k_data / "posture_plan.csv"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("27 postures"));
  EXPECT_THAT(r.out, Not(HasSubstr("NOT IDENTIFIABLE")));
  EXPECT_EQ(r.err, "");
  const auto fitted = gait::read_walking_config(out(), {}, nullptr);
  EXPECT_NEAR(fitted.x_offset, -7.3, 0.5);
  EXPECT_NEAR(fitted.y_offset, 8.1, 0.5);
  EXPECT_NEAR(fitted.z_offset, 25.4, 0.5);
  EXPECT_NEAR(fitted.roll_offset, 1.7, 0.2);
  EXPECT_NEAR(fitted.pitch_offset, 2.3, 0.2);
  EXPECT_NEAR(fitted.yaw_offset, 3.1, 0.2);
  EXPECT_NEAR(fitted.hip_pitch_offset, 10.6, 0.2);
  EXPECT_EQ(fitted.period_time, 600.0);
}

TEST_F(calibration_cli, plant_mode_fits_the_torso_pitch) {
  const auto r = stride(args(k_data / "pitch_zero.ini", "--mode plant"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("pitch_deg"));
  const auto fitted = gait::read_walking_config(out(), {}, nullptr);
  EXPECT_LT(fitted.hip_pitch_offset, 2.0);
  EXPECT_EQ(fitted.x_offset, -10.0);
}

}  // namespace
}  // namespace stride::calibration
