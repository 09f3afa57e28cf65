// `stride robot-fmu` through the built CLI: the DARwIn-OP's FMU made by the command walks exactly
// as the plant did before it was generated, generated FMUs pass the checker and simulate other
// robots correctly, and bad input is refused naming the file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "process.hpp"
#include "stride/cosim/archive.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::quoted;
using test::run_command;
using ::testing::HasSubstr;

const std::string k_cli = STRIDE_CLI;
const fs::path k_source = STRIDE_SOURCE_DIR;
const fs::path k_darwin = k_source / "models" / "darwin-op";
const fs::path k_data = k_source / "tests" / "components" / "robot_fmu" / "data";

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// the columns of a results CSV by name
std::map<std::string, std::vector<double>> columns(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream header(line);
  for (std::string n; std::getline(header, n, ',');) names.push_back(n);
  std::map<std::string, std::vector<double>> out;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string cell;
    for (std::size_t i = 0; std::getline(row, cell, ','); ++i) {
      out[names.at(i)].push_back(cell == "true" ? 1.0 : cell == "false" ? 0.0 : std::stod(cell));
    }
  }
  return out;
}

class robot_fmu_cli : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-robot-fmu-test-"};
  test::process_result stride(const std::string& args, const std::string& env = "") {
    return run_command("cd " + quoted(scratch.path()) + " && " + env + " '" + k_cli + "' " + args,
                       scratch.path());
  }
  fs::path out(const std::string& name) const { return scratch.path() / name; }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(out(name)) << text;
  }
  // a system of the plant FMU `fmu` alone, with these extra lines
  void plant_system(const std::string& name, const std::string& fmu, const std::string& stop,
                    const std::string& body) const {
    write(name, "<system name=\"plant\" version=\"1\">\n<simulation start=\"0\" stop=\"" + stop +
                    "\" step=\"0.002\"/>\n<component name=\"robot\" fmu=\"" + out(fmu).string() +
                    "\"/>\n" + body + "</system>\n");
  }
};

TEST_F(robot_fmu_cli, help_documents_the_options) {
  const auto r = stride("robot-fmu --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* option :
       {"--profile", "--output", "--name", "--package-path", "--binaries-from", "--quiet"}) {
    EXPECT_THAT(r.out, HasSubstr(option));
  }
}

// the reference was recorded with robot.fmu as it was before it was generated from the profile
TEST_F(robot_fmu_cli, the_darwin_fmu_made_by_the_command_walks_exactly_as_before) {
  const auto made =
      stride("robot-fmu " + quoted(k_darwin / "darwin-op.urdf") + " --profile " +
             quoted(k_darwin / "darwin-op.profile.xml") + " --name robot --output made/robot.fmu");
  ASSERT_EQ(made.exit_code, 0) << made.err;
  EXPECT_THAT(made.out, HasSubstr("20 joints"));
  EXPECT_EQ(made.err, "") << "the DARwIn profile leaves nothing to guess";
  const std::string walk =
      "run " + quoted(k_source / "models" / "walk.xml") +
      " --quiet --stop-time 10 --set robot.profile=webots --record "
      "'robot.base_x,robot.base_y,robot.base_z,robot.roll,robot.pitch,robot.yaw,robot.com_*,robot."
      "joint_angle[*],"
      "robot.gyro*,robot.acc*,robot.*_foot_force,robot.max_penetration,robot.fallen' "
      "--record-interval 0.08 -o ";
  const auto generated = stride(walk + "generated", "STRIDE_FMU_PATH=" + quoted(out("made")));
  ASSERT_EQ(generated.exit_code, 0) << generated.err;
  const auto built = stride(walk + "built");
  ASSERT_EQ(built.exit_code, 0) << built.err;
  const std::string reference = read(k_data / "darwin_walk_webots_10s.csv");
  ASSERT_GT(reference.size(), 10000u);
  EXPECT_TRUE(read(out("generated") / "results.csv") == reference);
  EXPECT_TRUE(read(out("built") / "results.csv") == reference);
}

TEST_F(robot_fmu_cli, the_same_inputs_give_the_same_archive) {
  const std::string args = "robot-fmu " + quoted(k_data / "pendulum.urdf") + " --quiet -o ";
  ASSERT_EQ(stride(args + "a/pendulum.fmu", "SOURCE_DATE_EPOCH=1700000000").exit_code, 0);
  ASSERT_EQ(stride(args + "b/pendulum.fmu", "SOURCE_DATE_EPOCH=1700000000").exit_code, 0);
  const std::string a = read(out("a/pendulum.fmu"));
  EXPECT_GT(a.size(), 100000u);
  EXPECT_TRUE(a == read(out("b/pendulum.fmu")));
}

TEST_F(robot_fmu_cli, without_a_profile_every_guess_is_reported) {
  const auto r = stride("robot-fmu " + quoted(k_data / "pendulum.urdf") + " -o p.fmu");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("warning: no <servo> rule"));
  EXPECT_THAT(r.err, HasSubstr("warning: no <imu link>"));
  EXPECT_THAT(r.err, HasSubstr("warning: no physics.step"));
  EXPECT_THAT(r.out, HasSubstr("p.fmu: 1 joints"));
  const auto v = stride("validate p.fmu");
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
}

// a compound pendulum released from 5°: its servo has no torque, so it swings freely
TEST_F(robot_fmu_cli, a_released_pendulum_swings_with_the_analytic_period) {
  const double theta0 = 5.0 * std::numbers::pi / 180.0;
  std::ostringstream pose;
  pose.precision(17);
  pose << theta0;
  write("pendulum.xml",
        "<plant_profile>\n<physics step=\"0.0005\"/>\n"
        "<servo joints=\"pivot\" torque_limit=\"0\" static_friction=\"0\" "
        "damping=\"0\"/>\n<pose joints=\"pivot\" value=\"" +
            pose.str() + "\"/>\n</plant_profile>\n");
  const auto made = stride("robot-fmu " + quoted(k_data / "pendulum.urdf") +
                           " --profile pendulum.xml --quiet -o pendulum.fmu");
  ASSERT_EQ(made.exit_code, 0) << made.err;
  plant_system("swing.xml", "pendulum.fmu", "12",
               "<record interval=\"0.002\" file=\"results.csv\">"
               "<signal name=\"robot.joint_angle[1]\"/></record>\n");
  const auto run = stride("run swing.xml --quiet -o swing");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto c = columns(out("swing") / "results.csv");
  const std::vector<double>& t = c.at("time");
  const std::vector<double>& q = c.at("robot.joint_angle[1]");
  ASSERT_NEAR(q.front(), theta0, 1e-12);
  // downward zero crossings, interpolated
  std::vector<double> crossings;
  for (std::size_t i = 1; i < q.size(); ++i) {
    if (q[i - 1] > 0 && q[i] <= 0) {
      crossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * q[i - 1] / (q[i - 1] - q[i]));
    }
  }
  ASSERT_GE(crossings.size(), 8u);
  const double measured =
      (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  // rod 0.4 kg (centre 0.2 m below the pivot), bob 0.6 kg (0.4 m), inertias from the URDF
  const double mass = 1.0;
  const double d = (0.4 * 0.2 + 0.6 * 0.4) / mass;
  const double inertia = 0.005347 + 0.4 * 0.2 * 0.2 + 0.00024 + 0.6 * 0.4 * 0.4;
  const double small = 2.0 * std::numbers::pi * std::sqrt(inertia / (mass * 9.81 * d));
  const double analytic = small * (1.0 + theta0 * theta0 / 16.0);
  EXPECT_NEAR(measured / analytic, 1.0, 0.01) << measured << " s against " << analytic << " s";
}

// data/quadruped.urdf (6.2 kg: a 4 kg body, four legs of 0.55 kg) on bent knees, P servos
TEST_F(robot_fmu_cli, a_quadruped_stands_under_gravity_with_p_servos) {
  const auto made = stride("robot-fmu " + quoted(k_data / "quadruped.urdf") + " --profile " +
                           quoted(k_data / "quadruped.profile.xml") + " -o quadruped.fmu");
  ASSERT_EQ(made.exit_code, 0) << made.err;
  EXPECT_EQ(made.err, "");
  EXPECT_THAT(made.out, HasSubstr("8 joints"));
  plant_system("stand.xml", "quadruped.fmu", "5",
               "<record interval=\"0.1\" file=\"results.csv\">"
               "<signal name=\"robot.base_z\"/><signal name=\"robot.roll\"/>"
               "<signal name=\"robot.pitch\"/><signal name=\"robot.fallen\"/>"
               "<signal name=\"robot.*_force\"/><signal name=\"robot.*_knee.angle\"/>"
               "</record>\n");
  const auto run = stride("run stand.xml --quiet -o stand");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto c = columns(out("stand") / "results.csv");
  const std::size_t at_2s = 20, last = c.at("time").size() - 1;
  ASSERT_EQ(c.at("time")[last], 5.0);
  EXPECT_NEAR(c.at("robot.base_z")[last], c.at("robot.base_z")[at_2s], 0.002);
  EXPECT_GT(c.at("robot.base_z")[last], 0.2);  // standing, not lying on its body
  for (std::size_t i = at_2s; i <= last; ++i) {
    EXPECT_LT(std::abs(c.at("robot.roll")[i]), 0.02);
    EXPECT_LT(std::abs(c.at("robot.pitch")[i]), 0.02);
    EXPECT_EQ(c.at("robot.fallen")[i], 0.0);
  }
  // the last second: the feet carry the weight, the knees hold their target
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = last - 10; i <= last; ++i, ++n) {
    for (const char* foot : {"fl", "fr", "hl", "hr"}) {
      sum += c.at("robot." + std::string(foot) + "_force")[i];
    }
    for (const char* knee : {"fl", "fr", "hl", "hr"}) {
      EXPECT_NEAR(c.at("robot." + std::string(knee) + "_knee.angle")[i], -1.0, 0.01);
    }
  }
  EXPECT_NEAR(sum / n / (6.2 * 9.81), 1.0, 0.01);
}

// a mesh named relative to the URDF and the same mesh as package://: both travel in the FMU
TEST_F(robot_fmu_cli, mesh_files_travel_inside_the_fmu) {
  const auto relative = stride("robot-fmu " + quoted(k_data / "mesh_box.urdf") + " -q -o rel.fmu");
  ASSERT_EQ(relative.exit_code, 0) << relative.err;
  fs::create_directories(out("pkgs/boxes/meshes"));
  fs::copy_file(k_data / "unit_cube.stl", out("pkgs/boxes/meshes/unit_cube.stl"));
  std::string urdf = read(k_data / "mesh_box.urdf");
  urdf.replace(urdf.find("\"unit_cube.stl\""), 15, "\"package://boxes/meshes/unit_cube.stl\"");
  write("crate.urdf", urdf);
  const auto packaged = stride("robot-fmu crate.urdf --package-path pkgs -q -o pkg.fmu");
  ASSERT_EQ(packaged.exit_code, 0) << packaged.err;
  fs::remove_all(out("pkgs"));  // the FMU must not need them any more
  for (const char* fmu : {"rel", "pkg"}) {
    plant_system(std::string(fmu) + ".xml", std::string(fmu) + ".fmu", "1",
                 "<record interval=\"0.1\" file=\"results.csv\">"
                 "<signal name=\"robot.base_z\"/></record>\n");
    const auto run = stride(std::string("run ") + fmu + ".xml --quiet -o run_" + fmu);
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  // the crate rests on its mesh: the link origin 0.05 + 0.03 m above the floor
  const auto c = columns(out("run_rel") / "results.csv");
  EXPECT_NEAR(c.at("robot.base_z").back(), 0.08, 0.002);
  EXPECT_TRUE(read(out("run_rel") / "results.csv") == read(out("run_pkg") / "results.csv"));

  urdf.replace(urdf.find("package://boxes"), 15, "/abs/boxes");
  write("absolute.urdf", urdf);
  const auto absolute = stride("robot-fmu absolute.urdf -q -o abs.fmu");
  EXPECT_NE(absolute.exit_code, 0);
  EXPECT_THAT(absolute.err, HasSubstr("absolute.urdf"));
}

TEST_F(robot_fmu_cli, bad_input_is_refused_naming_the_file) {
  write("bad.xml", "<plant_profile>\n<servo joints=\"*\" p_gian=\"3\"/>\n</plant_profile>\n");
  auto r = stride("robot-fmu " + quoted(k_data / "pendulum.urdf") + " --profile bad.xml -o x.fmu");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.err, HasSubstr("bad.xml:2: <servo>: unknown attribute 'p_gian'"));
  EXPECT_FALSE(fs::exists(out("x.fmu")));

  write("nomatch.xml", "<plant_profile><pose joints=\"elbow\" value=\"1\"/></plant_profile>");
  r = stride("robot-fmu " + quoted(k_data / "pendulum.urdf") + " --profile nomatch.xml -o x.fmu");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.err, HasSubstr("nomatch.xml: <pose joints> 'elbow' matches no servo joint"));

  r = stride("robot-fmu " + quoted(k_data / "malformed.urdf") + " -o x.fmu");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.err, HasSubstr("malformed.urdf"));
  EXPECT_FALSE(fs::exists(out("x.fmu")));

  r = stride("robot-fmu " + quoted(k_data / "pendulum.urdf") + " -o pendulum.zip");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.err, HasSubstr("pendulum.zip: must end in .fmu"));
}

}  // namespace
}  // namespace stride::cosim
