// Closed loop: the DARwIn-OP plant driven by the gait core (stride::gait_core) with gyro feedback.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "stride/gait/walking.hpp"
#include "stride/robot/darwin.hpp"
#include "stride/robot/robot_sim.hpp"

namespace {

namespace darwin = stride::robot::darwin;
namespace gait = stride::gait;
using stride::robot::robot_sim;

const std::string k_darwin = std::string(STRIDE_SOURCE_DIR) + "/models/darwin-op/darwin-op.urdf";

struct walk_result {
  bool fallen = false;
  double time = 0.0;      // s of walking
  double distance = 0.0;  // forward, m
};

// stands 1 s, then walks forward with x_move for `duration` s; the gait sends IDs 1..18 like the
// Webots gait manager, reading the gyro every 8 ms tick
walk_result walk(const gait::walking_params& params, double x_move, double duration,
                 double gyro_sign = 1.0,
                 darwin::plant_profile profile = darwin::plant_profile::stiff) {
  robot_sim sim(darwin::default_config(k_darwin, profile));
  const auto& o = sim.outputs();
  sim.step(1.0);
  const gait::walking gen;
  gait::walking_state s = gen.initialize(params);
  gen.set_command(s, x_move, 0, 0, false);
  gen.start(s);
  std::vector<double> targets(sim.config().initial_pose);
  const double x0 = o.base_position[0];
  const double t0 = o.time;
  while (o.time - t0 < duration - 1e-9 && !o.fallen) {
    gait::walking_feedback fb;
    fb.balance_on = true;
    const darwin::gyro_counts gyro = darwin::board_gyro(o.gyro);
    fb.gyro_fb = static_cast<int>(gyro_sign * gyro.fb);
    fb.gyro_rl = static_cast<int>(gyro_sign * gyro.rl);
    gen.set_command(s, x_move, 0, 0, false);
    gen.tick(s, params, fb);
    for (int i = 0; i < 18; ++i) {
      targets[static_cast<std::size_t>(i)] = gait::servo_count_to_rad(s.servo_count[i]);
    }
    sim.set_joint_targets(targets);
    sim.step(gait::tick_ms / 1000.0);
  }
  return {o.fallen, o.time - t0, o.base_position[0] - x0};
}

// framework defaults with the Webots walk/config.ini lateral gains
gait::walking_params webots_params() {
  gait::walking_params p;
  p.balance_hip_roll_gain = 0.0;
  p.balance_ankle_roll_gain = 0.0;
  return p;
}

TEST(darwin_walking, walks_a_minute_forward_with_default_parameters) {
  const walk_result r = walk(webots_params(), 20.0, 60.0);
  ASSERT_FALSE(r.fallen) << "fell after " << r.time << " s";
  const double speed = r.distance / r.time;
  std::printf("[ figure ] forward speed %.4f m/s over %.0f s (x_move 20 mm)\n", speed, r.time);
  EXPECT_GT(speed, 0.10);
  EXPECT_LT(speed, 0.30);
}

TEST(darwin_walking, falls_with_extreme_sway_and_period) {
  gait::walking_params p = webots_params();
  p.swing_right_left = 39.0;
  p.period_time = 450.0;
  const walk_result r = walk(p, 20.0, 60.0);
  std::printf("[ figure ] extreme gait fell after %.2f s\n", r.time);
  EXPECT_TRUE(r.fallen);
}

TEST(darwin_walking, the_webots_profile_walks_the_default_gait_and_falls_with_the_extreme_one) {
  const walk_result r = walk(webots_params(), 20.0, 60.0, 1.0, darwin::plant_profile::webots);
  ASSERT_FALSE(r.fallen) << "fell after " << r.time << " s";
  const double speed = r.distance / r.time;
  std::printf("[ figure ] webots profile: forward speed %.4f m/s over %.0f s\n", speed, r.time);
  // the lagging servo shortens the stride: slower than the stiff profile, above half the
  // kinematic 4 * x_move / period_time = 0.133 m/s
  EXPECT_GT(speed, 0.07);
  EXPECT_LT(speed, 0.12);
  gait::walking_params extreme = webots_params();
  extreme.swing_right_left = 39.0;
  extreme.period_time = 450.0;
  EXPECT_TRUE(walk(extreme, 20.0, 60.0, 1.0, darwin::plant_profile::webots).fallen);
}

TEST(darwin_walking, reversed_gyro_sign_destabilises_the_gait) {
  // the FB gyro feeds knees and ankle pitch; with the sign of darwin::board_gyro the loop
  // is stabilising, with the opposite sign the robot goes down within seconds
  const walk_result r = walk(webots_params(), 20.0, 20.0, -1.0);
  std::printf("[ figure ] reversed gyro sign fell after %.2f s\n", r.time);
  EXPECT_TRUE(r.fallen);
}

}  // namespace
