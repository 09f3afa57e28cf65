// robot.fmu through its C interface: standing, push and reset, FMU state snapshots, errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "raw_fmu.hpp"

namespace stride::test {
namespace {

constexpr double h = 0.008;

std::string robot_fmu_path() {
  return std::string(STRIDE_FMU_DIR) + "/robot.fmu";
}

void run(raw_fmu& f, fmi2Component c, double& t, double seconds) {
  const int steps = static_cast<int>(std::lround(seconds / h));
  for (int i = 0; i < steps; ++i, t += h) ASSERT_EQ(f.fmi2DoStep(c, t, h, fmi2True), fmi2OK);
}

std::vector<double> pose(raw_fmu& f, fmi2Component c) {
  std::vector<double> out;
  for (const char* name :
       {"base_x", "base_y", "base_z", "roll", "pitch", "yaw", "com_x", "com_z"}) {
    out.push_back(f.real(c, name));
  }
  for (int i = 1; i <= 20; ++i) out.push_back(f.real(c, "joint_angle[" + std::to_string(i) + "]"));
  return out;
}

TEST(robot_fmu, stands_in_the_walk_ready_pose) {
  raw_fmu f(robot_fmu_path());
  fmi2Component c = f.instantiate();
  f.initialize(c);
  double t = 0;
  run(f, c, t, 3.0);
  EXPECT_FALSE(f.boolean(c, "fallen"));
  EXPECT_NEAR(f.real(c, "base_z"), 0.317, 0.005);  // docs/robot-model.md §5.2: torso origin 0.317 m
  EXPECT_NEAR(f.real(c, "pitch") * 180 / M_PI, 12.94, 1.0);
  const double weight = f.real(c, "left_foot_force") + f.real(c, "right_foot_force");
  EXPECT_NEAR(weight, 2.925 * 9.81, 3.0);  // the feet carry the robot
  EXPECT_LT(std::abs(f.integer(c, "gyro_fb")), 3);
}

TEST(robot_fmu, a_push_topples_it_and_reset_stands_it_up) {
  raw_fmu f(robot_fmu_path());
  fmi2Component c = f.instantiate();
  f.initialize(c);
  double t = 0;
  run(f, c, t, 0.5);
  ASSERT_EQ(f.set_real(c, "push_x", 20.0), fmi2OK);
  run(f, c, t, 0.3);
  ASSERT_EQ(f.set_real(c, "push_x", 0.0), fmi2OK);
  bool fallen = false;
  for (int i = 0; i < 250 && !fallen; ++i, t += h) {
    ASSERT_EQ(f.fmi2DoStep(c, t, h, fmi2True), fmi2OK);
    fallen = f.boolean(c, "fallen");
  }
  EXPECT_TRUE(fallen) << "20 N for 0.3 s did not topple the robot within 2 s";
  ASSERT_EQ(f.set_integer(c, "reset", 1), fmi2OK);
  run(f, c, t, 1.0);
  EXPECT_FALSE(f.boolean(c, "fallen"));
  EXPECT_NEAR(f.real(c, "base_z"), 0.317, 0.005);
  EXPECT_NEAR(f.real(c, "base_x"), 0.0, 0.01);
}

// forces of about 1e154 N overflow inside ODE, which aborts the process: refused at the set
TEST(robot_fmu, a_push_beyond_its_declared_range_is_an_error_not_a_crash) {
  raw_fmu f(robot_fmu_path());
  fmi2Component c = f.instantiate();
  f.initialize(c);
  double t = 0;
  run(f, c, t, 0.1);
  ASSERT_EQ(f.set_real(c, "push_x", 1e4), fmi2OK);  // the bound itself is allowed
  ASSERT_EQ(f.set_real(c, "push_x", 0.0), fmi2OK);
  EXPECT_EQ(f.set_real(c, "push_x", 1e154), fmi2Error);
  EXPECT_EQ(f.set_real(c, "push_y", -1e5), fmi2Error);
}

TEST(robot_fmu, fmu_state_restores_the_continuation_bit_exactly) {
  raw_fmu f(robot_fmu_path());
  fmi2Component c = f.instantiate();
  f.initialize(c);
  double t = 0;
  ASSERT_EQ(f.set_real(c, "push_y", 3.0), fmi2OK);  // make the motion non-trivial
  run(f, c, t, 0.5);
  fmi2FMUstate snapshot = nullptr;
  ASSERT_EQ(f.fmi2GetFMUstate(c, &snapshot), fmi2OK);
  const double t_snapshot = t;
  run(f, c, t, 0.5);
  const std::vector<double> first = pose(f, c);

  ASSERT_EQ(f.fmi2SetFMUstate(c, snapshot), fmi2OK);
  t = t_snapshot;
  run(f, c, t, 0.5);
  const std::vector<double> second = pose(f, c);
  ASSERT_EQ(first.size(), second.size());
  EXPECT_EQ(std::memcmp(first.data(), second.data(), first.size() * sizeof(double)), 0);

  // serialised into a second instance
  size_t size = 0;
  ASSERT_EQ(f.fmi2SerializedFMUstateSize(c, snapshot, &size), fmi2OK);
  std::vector<fmi2Byte> bytes(size);
  ASSERT_EQ(f.fmi2SerializeFMUstate(c, snapshot, bytes.data(), size), fmi2OK);
  fmi2Component other = f.instantiate("other");
  f.initialize(other);
  fmi2FMUstate restored = nullptr;
  ASSERT_EQ(f.fmi2DeSerializeFMUstate(other, bytes.data(), size, &restored), fmi2OK);
  ASSERT_EQ(f.fmi2SetFMUstate(other, restored), fmi2OK);
  t = t_snapshot;
  run(f, other, t, 0.5);
  const std::vector<double> third = pose(f, other);
  EXPECT_EQ(std::memcmp(first.data(), third.data(), first.size() * sizeof(double)), 0);
  f.fmi2FreeFMUstate(c, &snapshot);
  f.fmi2FreeFMUstate(other, &restored);
}

TEST(robot_fmu, a_malformed_urdf_is_an_error_naming_the_file) {
  raw_fmu f(robot_fmu_path());
  fmi2Component c = f.instantiate();
  const std::string urdf = std::string(STRIDE_TEST_DATA_DIR) + "/malformed.urdf";
  ASSERT_EQ(f.set_string(c, "urdf", urdf), fmi2OK);
  ASSERT_EQ(f.fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0), fmi2OK);
  ASSERT_EQ(f.fmi2EnterInitializationMode(c), fmi2OK);
  EXPECT_EQ(f.fmi2ExitInitializationMode(c), fmi2Error);
  EXPECT_TRUE(f.logged("malformed.urdf")) << f.last_message();
}

TEST(robot_fmu, physics_settings_are_checked) {
  raw_fmu f(robot_fmu_path());
  fmi2Component c = f.instantiate();
  EXPECT_EQ(f.set_real(c, "physics_step", 0.0), fmi2Error);
  EXPECT_TRUE(f.logged("'physics_step'"));
  EXPECT_EQ(f.set_real(c, "joint_target[3]", NAN), fmi2Error);
  f.initialize(c);
  EXPECT_EQ(f.set_real(c, "friction", 0.5), fmi2Error);  // fixed after initialization
}

// values are readable from initialization mode on
void enter_initialization(raw_fmu& f, fmi2Component c) {
  ASSERT_EQ(f.fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0), fmi2OK);
  ASSERT_EQ(f.fmi2EnterInitializationMode(c), fmi2OK);
}

TEST(robot_fmu, profiles_give_their_documented_servo_and_explicit_sets_win) {
  raw_fmu f(robot_fmu_path());
  fmi2Component stiff = f.instantiate("stiff");  // the default
  enter_initialization(f, stiff);
  EXPECT_EQ(f.real(stiff, "servo_p_gain"), 18.0);
  EXPECT_EQ(f.real(stiff, "servo_max_acceleration"), 0.0);

  fmi2Component webots = f.instantiate("webots");
  ASSERT_EQ(f.set_string(webots, "profile", "webots"), fmi2OK);
  enter_initialization(f, webots);
  EXPECT_EQ(f.real(webots, "servo_p_gain"), 10.0);
  EXPECT_EQ(f.real(webots, "servo_max_acceleration"), 55.0);
  EXPECT_EQ(f.real(webots, "physics_step"), 0.016);  // shared by both profiles
  EXPECT_EQ(f.real(webots, "friction"), 1.0);

  // an explicit set wins, before or after the profile
  fmi2Component mixed = f.instantiate("mixed");
  ASSERT_EQ(f.set_real(mixed, "servo_p_gain", 12.0), fmi2OK);
  ASSERT_EQ(f.set_string(mixed, "profile", "webots"), fmi2OK);
  ASSERT_EQ(f.set_real(mixed, "servo_max_acceleration", 40.0), fmi2OK);
  enter_initialization(f, mixed);
  EXPECT_EQ(f.real(mixed, "servo_p_gain"), 12.0);
  EXPECT_EQ(f.real(mixed, "servo_max_acceleration"), 40.0);
  EXPECT_EQ(f.real(mixed, "servo_max_velocity"), 12.26);

  fmi2Component bad = f.instantiate("bad");
  EXPECT_EQ(f.set_string(bad, "profile", "soft"), fmi2Error);
  EXPECT_TRUE(f.logged("profile 'soft' is not a plant profile (stiff, webots)"))
      << f.last_message();
}

}  // namespace
}  // namespace stride::test
