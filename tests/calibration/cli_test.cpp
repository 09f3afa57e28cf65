// `stride calibrate`: help, exit codes, one-line errors naming file and line, both modes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
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

// the example targets in models/calibration/ run as its README says
class calibration_examples : public calibration_cli {
 protected:
  const fs::path examples = fs::path(STRIDE_SOURCE_DIR) / "models" / "calibration";
  const gait::walking_params start = gait::read_walking_config(k_config, {}, nullptr);
};

TEST_F(calibration_examples, one_posture_gives_back_the_stance_it_was_read_in) {
  // the walk-ready pose is the gait's standing output with the framework's default offsets
  // (docs/robot-model.md §5.1), the start values of the gait's config.ini
  const auto r = stride(args(examples / "walk-ready.csv",
                             "--fit x_offset,y_offset,z_offset,roll_offset,yaw_offset,"
                             "hip_pitch_offset"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, Not(HasSubstr("NOT IDENTIFIABLE")));
  const auto fitted = gait::read_walking_config(out(), {}, nullptr);
  EXPECT_NEAR(fitted.x_offset, start.x_offset, 0.5);
  EXPECT_NEAR(fitted.z_offset, start.z_offset, 0.5);
  EXPECT_NEAR(fitted.hip_pitch_offset, start.hip_pitch_offset, 0.2);
  // y, roll and yaw act through few servos: one posture pins them to about a millimetre/degree
  EXPECT_NEAR(fitted.y_offset, start.y_offset, 2.0);
  EXPECT_NEAR(fitted.roll_offset, start.roll_offset, 1.0);
  EXPECT_NEAR(fitted.yaw_offset, start.yaw_offset, 1.0);
  EXPECT_EQ(fitted.pitch_offset, start.pitch_offset);  // held
}

TEST_F(calibration_examples, the_posture_plan_gives_back_the_offsets_its_header_names) {
  // "# calibrated offsets are x -7.3, y 8.1, z 25.4 mm, roll 1.7, pitch 2.3, yaw 3.1, hip_pitch
  // 10.6 deg": the offsets the synthetic file was recorded with
  std::ifstream in(examples / "posture-plan.csv");
  std::string header, line;
  while (std::getline(in, line) && line.starts_with("#")) header += line.substr(1) + " ";
  std::map<std::string, double> truth;
  const std::regex offset(R"(\b(x|y|z|roll|pitch|yaw|hip_pitch)\s+(-?[0-9]+(\.[0-9]+)?)\b)");
  for (auto it = std::sregex_iterator(header.begin(), header.end(), offset);
       it != std::sregex_iterator(); ++it) {
    truth[(*it)[1]] = std::stod((*it)[2]);
  }
  ASSERT_EQ(truth.size(), 7u) << header;
  const auto r = stride(args(examples / "posture-plan.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("27 postures"));
  EXPECT_THAT(r.out, Not(HasSubstr("NOT IDENTIFIABLE")));
  const auto fitted = gait::read_walking_config(out(), {}, nullptr);
  EXPECT_NEAR(fitted.x_offset, truth["x"], 0.5);
  EXPECT_NEAR(fitted.y_offset, truth["y"], 0.5);
  EXPECT_NEAR(fitted.z_offset, truth["z"], 0.5);
  EXPECT_NEAR(fitted.roll_offset, truth["roll"], 0.2);
  EXPECT_NEAR(fitted.pitch_offset, truth["pitch"], 0.2);
  EXPECT_NEAR(fitted.yaw_offset, truth["yaw"], 0.2);
  EXPECT_NEAR(fitted.hip_pitch_offset, truth["hip_pitch"], 0.2);
}

TEST_F(calibration_examples, the_plant_target_is_fitted) {
  const fs::path report = scratch.path() / "report.txt";
  const auto r = stride(
      args(examples / "stand-upright.ini", "--mode plant --quiet --report " + quoted(report)));
  // 0: fitted; 3: written, the solver stopped before converging (docs/calibration.md)
  EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 3) << r.exit_code << ": " << r.err;
  ASSERT_TRUE(fs::exists(out()));
  std::ifstream in(report);
  std::stringstream text;
  text << in.rdbuf();
  for (const char* target : {"pitch_deg", "height_m", "com"})
    EXPECT_THAT(text.str(), HasSubstr(target));
  const auto fitted = gait::read_walking_config(out(), {}, nullptr);
  EXPECT_EQ(fitted.period_time, start.period_time);            // only offsets are rewritten
  EXPECT_NE(fitted.hip_pitch_offset, start.hip_pitch_offset);  // fitted to pitch_deg by default
}

}  // namespace
}  // namespace stride::calibration
