// robot.fmu through its C interface: standing, push and reset, FMU state snapshots, errors;
// every published output against an independent value (hand formulas from docs/robot-model.md,
// statics, the URDF read afresh by oracle.hpp).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <vector>

#include "oracle.hpp"
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
  // standing still the feet carry the weight (2.9253 kg, docs/robot-model.md §2.1)
  const double weight = f.real(c, "left_foot_force") + f.real(c, "right_foot_force");
  EXPECT_NEAR(weight, 2.9253 * 9.81, 0.001 * 2.9253 * 9.81);
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
  EXPECT_TRUE(f.logged("no preset 'soft' (presets: stiff, webots)")) << f.last_message();
}

const std::string k_darwin = std::string(STRIDE_SOURCE_DIR) + "/models/darwin-op/darwin-op.urdf";

double index_real(raw_fmu& f, fmi2Component c, const char* name, int i) {
  return f.real(c, std::string(name) + "[" + std::to_string(i) + "]");
}

// the published whole-body CoM against the URDF's masses at the published joint angles, placed
// by the published base pose (R = Rz(yaw)·Ry(pitch)·Rx(roll))
void expect_com_matches_the_urdf(raw_fmu& f, fmi2Component c, double tolerance) {
  std::vector<double> q;
  for (int i = 1; i <= 20; ++i) q.push_back(index_real(f, c, "joint_angle", i));
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(f.real(c, "yaw"), Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(f.real(c, "pitch"), Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(f.real(c, "roll"), Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  const Eigen::Vector3d base(f.real(c, "base_x"), f.real(c, "base_y"), f.real(c, "base_z"));
  const Eigen::Vector3d com = base + r * urdf_oracle(k_darwin).com_in_root(q);
  EXPECT_NEAR(f.real(c, "com_x"), com.x(), tolerance);
  EXPECT_NEAR(f.real(c, "com_y"), com.y(), tolerance);
  EXPECT_NEAR(f.real(c, "com_z"), com.z(), tolerance);
}

TEST(robot_fmu, every_output_at_initialization_matches_the_documented_stance) {
  raw_fmu f(robot_fmu_path());
  fmi2Component c = f.instantiate();
  f.initialize(c);
  const double lean = walk_ready_lean();  // 12.94°
  const std::vector<double> q = page_9();
  for (int i = 1; i <= 20; ++i) {
    EXPECT_NEAR(index_real(f, c, "joint_angle", i), q[static_cast<std::size_t>(i - 1)], 1e-9) << i;
  }
  // docs/robot-model.md §5.2: torso origin 0.317 m above the floor's origin, leaning forward
  EXPECT_NEAR(f.real(c, "base_x"), 0.0, 1e-12);
  EXPECT_NEAR(f.real(c, "base_y"), 0.0, 1e-12);
  EXPECT_NEAR(f.real(c, "base_z"), 0.317, 0.002);
  EXPECT_NEAR(f.real(c, "roll"), 0.0, 1e-3);
  EXPECT_NEAR(f.real(c, "pitch"), lean, 1e-3);
  EXPECT_NEAR(f.real(c, "yaw"), 0.0, 1e-3);
  expect_com_matches_the_urdf(f, c, 1e-9);
  // at rest: the accelerometer reads gravity in the leaning torso, in m/s²
  EXPECT_NEAR(index_real(f, c, "acc", 1), -k_gravity * std::sin(lean), 1e-3);
  EXPECT_NEAR(index_real(f, c, "acc", 2), 0.0, 1e-3);
  EXPECT_NEAR(index_real(f, c, "acc", 3), k_gravity * std::cos(lean), 1e-3);
  for (int i = 1; i <= 3; ++i) EXPECT_EQ(index_real(f, c, "gyro", i), 0.0) << i;
  EXPECT_EQ(f.integer(c, "gyro_fb"), 0);
  EXPECT_EQ(f.integer(c, "gyro_rl"), 0);
  EXPECT_FALSE(f.boolean(c, "fallen"));
}

TEST(robot_fmu, every_output_standing_still_matches_gravity_statics_and_the_urdf) {
  raw_fmu f(robot_fmu_path());
  fmi2Component c = f.instantiate();
  f.initialize(c);
  double t = 0;
  run(f, c, t, 2.0);
  double left = 0.0, right = 0.0;  // averaged over 0.5 s: no single step's settling counts
  constexpr int k_samples = 62;
  for (int k = 0; k < k_samples; ++k) {
    run(f, c, t, h);
    left += f.real(c, "left_foot_force") / k_samples;
    right += f.real(c, "right_foot_force") / k_samples;
  }
  const double lean = walk_ready_lean();
  const double weight = urdf_oracle(k_darwin).total_mass() * k_gravity;
  // at rest nothing accelerates: the floor carries the weight, in N, half on each foot by the
  // robot's mirror symmetry (the arms differ only in pitch, which moves no mass sideways)
  EXPECT_NEAR(left + right, weight, 0.001 * weight);
  EXPECT_NEAR(left, 0.5 * weight, 0.005 * weight);
  EXPECT_NEAR(right, 0.5 * weight, 0.005 * weight);
  // the feet settle 0.5 mm into the soft contact; the torso stays put
  EXPECT_GT(f.real(c, "max_penetration"), 0.0001);
  EXPECT_LT(f.real(c, "max_penetration"), 0.002);
  EXPECT_NEAR(f.real(c, "base_x"), 0.0, 0.002);
  EXPECT_NEAR(f.real(c, "base_y"), 0.0, 0.002);
  EXPECT_NEAR(f.real(c, "base_z"), 0.317, 0.002);
  EXPECT_NEAR(f.real(c, "roll"), 0.0, 2e-3);
  EXPECT_NEAR(f.real(c, "pitch"), lean, 2e-3);
  EXPECT_NEAR(f.real(c, "yaw"), 0.0, 2e-3);
  expect_com_matches_the_urdf(f, c, 1e-4);
  EXPECT_NEAR(index_real(f, c, "acc", 1), -k_gravity * std::sin(lean), 0.005);
  EXPECT_NEAR(index_real(f, c, "acc", 2), 0.0, 0.005);
  EXPECT_NEAR(index_real(f, c, "acc", 3), k_gravity * std::cos(lean), 0.005);
  for (int i = 1; i <= 3; ++i) EXPECT_NEAR(index_real(f, c, "gyro", i), 0.0, 1e-3) << i;
  // the board reads its 512 centre: counts − 512 of a rate that small are 0 or −1 (rounded down)
  EXPECT_GE(f.integer(c, "gyro_fb"), -1);
  EXPECT_LE(f.integer(c, "gyro_fb"), 0);
  EXPECT_GE(f.integer(c, "gyro_rl"), -1);
  EXPECT_LE(f.integer(c, "gyro_rl"), 0);
}

// Statics on two soles (see contacts_test.cpp): the left sole's contacts lie in y ∈ [a, b], the
// right's in [−b, −a] (a = 15 mm, b = 81 mm from docs/robot-model.md §1.3, §3.3, widened by
// 3 mm), so Σ y·F = W·y_com gives F_left ≥ W·(y_com + a)/(a + b).
void expect_the_foot_under_the_body_is_loaded(double phi) {
  raw_fmu f(robot_fmu_path());
  fmi2Component c = f.instantiate();
  f.initialize(c);
  double t = 0;
  run(f, c, t, 0.5);
  // hip and ankle rolls +phi each, within 1 s: both legs tilt sideways, the torso stays level
  for (int k = 1; k <= 125; ++k) {
    for (int id : {9, 10, 17, 18}) {
      const double target = page_9()[static_cast<std::size_t>(id - 1)] + phi * k / 125.0;
      ASSERT_EQ(f.set_real(c, "joint_target[" + std::to_string(id) + "]", target), fmi2OK);
    }
    run(f, c, t, h);
  }
  run(f, c, t, 1.0);
  ASSERT_FALSE(f.boolean(c, "fallen"));
  const double y_com = f.real(c, "com_y");
  double left = 0.0, right = 0.0;
  constexpr int k_samples = 62;
  for (int k = 0; k < k_samples; ++k) {
    run(f, c, t, h);
    left += f.real(c, "left_foot_force") / k_samples;
    right += f.real(c, "right_foot_force") / k_samples;
  }
  const double weight = urdf_oracle(k_darwin).total_mass() * k_gravity;
  constexpr double a = 0.012, b = 0.084;
  // the side the body moved to carries at least this much
  const double bearing = phi > 0 ? left : right;
  const double other = phi > 0 ? right : left;
  const double bearing_min = weight * (std::abs(y_com) + a) / (a + b);
  EXPECT_GT(phi > 0 ? y_com : -y_com, 0.035);
  EXPECT_GT(bearing_min, 0.55 * weight);
  EXPECT_GE(bearing, bearing_min);
  EXPECT_LE(other, weight - bearing_min + 0.001 * weight);
}

TEST(robot_fmu, the_body_moved_over_the_left_foot_loads_left_foot_force) {
  expect_the_foot_under_the_body_is_loaded(0.35);
}

TEST(robot_fmu, the_body_moved_over_the_right_foot_loads_right_foot_force) {
  expect_the_foot_under_the_body_is_loaded(-0.35);
}

// roll, pitch and yaw integrated from the gyro (body rates ω in the torso frame) with the
// kinematics of R = Rz(yaw)·Ry(pitch)·Rx(roll): roll' = ω_x + tan(pitch)·(sin(roll)·ω_y +
// cos(roll)·ω_z), pitch' = cos(roll)·ω_y − sin(roll)·ω_z, yaw' = (sin(roll)·ω_y +
// cos(roll)·ω_z)/cos(pitch). Outputs change once per 16 ms physics step, so summing them every
// 8 ms is the trapezoidal rule.
struct euler_integral {
  double roll = 0.0, pitch = 0.0, yaw = 0.0;
  void add(raw_fmu& f, fmi2Component c) {
    const double r = f.real(c, "roll"), p = f.real(c, "pitch");
    const double wx = index_real(f, c, "gyro", 1), wy = index_real(f, c, "gyro", 2),
                 wz = index_real(f, c, "gyro", 3);
    const double about_z = std::sin(r) * wy + std::cos(r) * wz;
    roll += (wx + std::tan(p) * about_z) * h;
    pitch += (std::cos(r) * wy - std::sin(r) * wz) * h;
    yaw += about_z / std::cos(p) * h;
  }
};

TEST(robot_fmu, a_push_to_the_right_rolls_the_torso_as_the_gyro_says_and_the_board_reads_it) {
  raw_fmu f(robot_fmu_path());
  fmi2Component c = f.instantiate();
  f.initialize(c);
  double t = 0;
  run(f, c, t, 0.5);
  const double roll_0 = f.real(c, "roll"), pitch_0 = f.real(c, "pitch");
  const double y_0 = f.real(c, "base_y");
  // a push towards the robot's right and a little forward for 0.1 s: it rolls right, about +x
  ASSERT_EQ(f.set_real(c, "push_y", -8.0), fmi2OK);
  ASSERT_EQ(f.set_real(c, "push_x", 2.0), fmi2OK);
  euler_integral integral;
  int distinct_channels = 0;
  for (int k = 1; k <= 40; ++k) {
    if (k == 13) {
      ASSERT_EQ(f.set_real(c, "push_y", 0.0), fmi2OK);
      ASSERT_EQ(f.set_real(c, "push_x", 0.0), fmi2OK);
      // at the end of the push: rolled right, as far as the gyro integrates to
      EXPECT_GT(index_real(f, c, "gyro", 1), 0.03);  // rad/s
      EXPECT_LT(f.real(c, "base_y"), y_0);           // it moves the way it is pushed
      const double roll = f.real(c, "roll") - roll_0;
      EXPECT_GT(roll, 0.005);  // rad
      EXPECT_NEAR(roll, integral.roll, 0.05 * roll);
      const double pitch = f.real(c, "pitch") - pitch_0;
      EXPECT_NEAR(pitch, integral.pitch, 0.1 * std::abs(pitch) + 2e-4);
    }
    run(f, c, t, h);
    integral.add(f, c);
    // the CM-730 reads 512 − k·ω_x (RL) and 512 − k·ω_y (FB), rounded down
    // (docs/robot-model.md §1.4, models/darwin-op/README.md "Sensors")
    const int rl =
        static_cast<int>(std::floor(-k_gyro_counts_per_rad_s * index_real(f, c, "gyro", 1)));
    const int fb =
        static_cast<int>(std::floor(-k_gyro_counts_per_rad_s * index_real(f, c, "gyro", 2)));
    EXPECT_EQ(f.integer(c, "gyro_rl"), rl) << k;
    EXPECT_EQ(f.integer(c, "gyro_fb"), fb) << k;
    if (rl != fb) ++distinct_channels;
  }
  EXPECT_GT(distinct_channels, 5);  // the two channels were told apart
}

TEST(robot_fmu, turning_both_hips_turns_the_torso_left_as_the_gyro_says) {
  raw_fmu f(robot_fmu_path());
  fmi2Component c = f.instantiate();
  f.initialize(c);
  double t = 0;
  run(f, c, t, 0.5);
  const double yaw_0 = f.real(c, "yaw"), roll_0 = f.real(c, "roll");
  // both hip yaws to +0.3 rad: the legs turn right against the torso (axis −z,
  // docs/robot-model.md §1.3); with the feet on the floor the torso turns left instead, by less
  // than 0.3 rad since the soles twist on the floor
  ASSERT_EQ(f.set_real(c, "joint_target[7]", 0.3), fmi2OK);
  ASSERT_EQ(f.set_real(c, "joint_target[8]", 0.3), fmi2OK);
  euler_integral integral;
  for (int k = 0; k < 125; ++k) {
    run(f, c, t, h);
    integral.add(f, c);
  }
  ASSERT_FALSE(f.boolean(c, "fallen"));
  const double yaw = f.real(c, "yaw") - yaw_0;
  EXPECT_GT(yaw, 0.1);
  EXPECT_LT(yaw, 0.3);
  EXPECT_NEAR(yaw, integral.yaw, 0.01 * yaw);
  // the leaning torso turned about the vertical also rolls (its lean partly becomes roll)
  const double roll = f.real(c, "roll") - roll_0;
  EXPECT_GT(roll, 0.01);
  EXPECT_NEAR(roll, integral.roll, 0.05 * roll);
}

TEST(robot_fmu, the_fall_parameters_set_each_condition_alone) {
  raw_fmu f(robot_fmu_path());
  // the walk-ready torso stands at 0.317 m, leaning 0.226 rad (docs/robot-model.md §5.2)
  const auto falls = [&](const char* name, double fall_tilt, double fall_height) {
    fmi2Component c = f.instantiate(name);
    EXPECT_EQ(f.set_real(c, "fall_tilt", fall_tilt), fmi2OK);
    EXPECT_EQ(f.set_real(c, "fall_height", fall_height), fmi2OK);
    f.initialize(c);
    double t = 0;
    run(f, c, t, 2 * h);
    return f.boolean(c, "fallen");
  };
  EXPECT_TRUE(falls("height", 3.2, 0.33));
  EXPECT_FALSE(falls("under the torso", 3.2, 0.30));
  EXPECT_TRUE(falls("tilt", 0.20, -1.0));
  EXPECT_FALSE(falls("within tilt", 0.25, -1.0));
}

}  // namespace
}  // namespace stride::test
