// The DARwIn-OP plant standing in the walk-ready pose: posture, contacts, falls, determinism and
// state images.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <thread>
#include <vector>

#include "stride/robot/darwin.hpp"
#include "stride/robot/robot_sim.hpp"

namespace {

namespace darwin = stride::robot::darwin;
using stride::robot::robot_outputs;
using stride::robot::robot_sim;

const std::string k_darwin = std::string(STRIDE_SOURCE_DIR) + "/models/darwin-op/darwin-op.urdf";
constexpr double k_deg = std::numbers::pi / 180.0;

TEST(darwin_op, reset_puts_the_robot_in_the_walk_ready_pose) {
  robot_sim sim(darwin::default_config(k_darwin));
  const robot_outputs& o = sim.outputs();
  // docs/robot-model.md §5.2: torso origin 0.317 m above the floor, 12.94 deg forward lean
  EXPECT_NEAR(o.base_position[2], darwin::k_walk_ready_torso_height, 0.002);
  EXPECT_NEAR(o.pitch, darwin::k_walk_ready_lean_deg * k_deg, 0.05 * k_deg);
  EXPECT_NEAR(o.roll, 0.0, 1e-9);
  EXPECT_NEAR(o.base_position[0], 0.0, 1e-12);
  EXPECT_NEAR(o.com[2], 0.201, 0.002);  // whole-body CoM height, docs/robot-model.md §5.2
  const auto pose = darwin::walk_ready_pose();
  for (int i = 0; i < darwin::k_servo_count; ++i) {
    EXPECT_NEAR(o.joint_angles[static_cast<std::size_t>(i)], pose[static_cast<std::size_t>(i)],
                1e-9)
        << i + 1;
  }
  // at rest the accelerometer reads the gravity reaction in the leaning torso frame
  EXPECT_NEAR(o.acc[0], -9.81 * std::sin(o.pitch), 1e-6);
  EXPECT_NEAR(o.acc[2], 9.81 * std::cos(o.pitch), 1e-6);
  EXPECT_FALSE(o.fallen);
}

TEST(darwin_op, stands_in_the_walk_ready_pose_for_a_minute) {
  robot_sim sim(darwin::default_config(k_darwin));
  const robot_outputs& o = sim.outputs();
  const auto pose = darwin::walk_ready_pose();
  double max_tracking = 0.0;
  double max_penetration = 0.0;
  double min_z = 1.0, max_z = 0.0, min_pitch = 1.0, max_pitch = -1.0;
  for (int k = 0; k < 7500; ++k) {  // 60 s in 8 ms control steps
    sim.step(0.008);
    ASSERT_FALSE(o.fallen) << "t = " << o.time;
    max_penetration = std::max(max_penetration, o.max_penetration);
    min_z = std::min(min_z, o.base_position[2]);
    max_z = std::max(max_z, o.base_position[2]);
    min_pitch = std::min(min_pitch, o.pitch);
    max_pitch = std::max(max_pitch, o.pitch);
    if (o.time > 0.5) {
      for (int i = 0; i < darwin::k_servo_count; ++i) {
        max_tracking = std::max(max_tracking, std::abs(o.joint_angles[static_cast<std::size_t>(i)] -
                                                       pose[static_cast<std::size_t>(i)]));
      }
    }
  }
  EXPECT_NEAR(o.time, 60.0, 1e-9);
  // torso height 0.317 m +- 3 mm, lean 12.94 deg +- 1 deg, feet not sinking
  EXPECT_GT(min_z, 0.314);
  EXPECT_LT(max_z, 0.320);
  EXPECT_GT(min_pitch, 11.94 * k_deg);
  EXPECT_LT(max_pitch, 13.94 * k_deg);
  EXPECT_LT(max_penetration, 0.005);
  EXPECT_LT(max_tracking, 0.01);
  // both feet carry the robot: standing still nothing accelerates, so the normal forces add up
  // to its weight (2.9253 kg, docs/robot-model.md §2.1), and the robot's mirror symmetry (the
  // arms differ only in pitch) shares it equally between the feet
  const double weight = 2.9253 * 9.81;
  EXPECT_NEAR(o.left_foot_force[2] + o.right_foot_force[2], weight, 0.001 * weight);
  EXPECT_NEAR(o.left_foot_force[2], o.right_foot_force[2], 0.01 * weight);
  // no drift while standing
  EXPECT_LT(std::hypot(o.base_position[0], o.base_position[1]), 0.005);
}

TEST(darwin_op, a_small_push_is_absorbed_and_a_large_one_topples_it) {
  robot_sim sim(darwin::default_config(k_darwin));
  const robot_outputs& o = sim.outputs();
  sim.step(0.5);
  // 2 N forward for 0.2 s: stays up
  sim.set_push(2.0, 0.0);
  sim.step(0.2);
  sim.set_push(0.0, 0.0);
  sim.step(3.0);
  EXPECT_FALSE(o.fallen);
  EXPECT_NEAR(o.pitch, darwin::k_walk_ready_lean_deg * k_deg, 1.0 * k_deg);

  // 20 N forward for 0.3 s: falls within 2 s of the start of the push
  const double t_push = o.time;
  sim.set_push(20.0, 0.0);
  sim.step(0.3);
  sim.set_push(0.0, 0.0);
  while (!o.fallen && o.time < t_push + 2.0) sim.step(0.008);
  EXPECT_TRUE(o.fallen);
  EXPECT_LT(o.time - t_push, 2.0);
  sim.step(1.0);
  EXPECT_TRUE(o.fallen);  // latched

  // reset brings it back upright
  sim.reset();
  EXPECT_FALSE(o.fallen);
  EXPECT_EQ(o.time, 0.0);
  EXPECT_NEAR(o.base_position[2], darwin::k_walk_ready_torso_height, 0.002);
  sim.step(2.0);
  EXPECT_FALSE(o.fallen);
  EXPECT_NEAR(o.pitch, darwin::k_walk_ready_lean_deg * k_deg, 0.5 * k_deg);
}

TEST(darwin_op, a_sideways_push_rolls_it_and_the_gyro_follows_the_board_mounting) {
  robot_sim sim(darwin::default_config(k_darwin));
  const robot_outputs& o = sim.outputs();
  sim.step(0.5);
  sim.set_push(0.0, -4.0);  // push towards the right: the torso rolls right (about +x)
  sim.step(0.1);
  EXPECT_GT(o.gyro[0], 0.0);
  // CM-730 mounting: counts = 512 - k * omega on x and y (docs/robot-model.md §1.4)
  const double k = 512.0 / 27.925;
  const darwin::gyro_counts board = darwin::board_gyro(o.gyro);
  EXPECT_DOUBLE_EQ(board.rl, -k * o.gyro[0]);
  EXPECT_DOUBLE_EQ(board.fb, -k * o.gyro[1]);
  EXPECT_LT(board.rl, 0.0);
}

TEST(darwin_op, board_gyro_counts_follow_the_cm730_mounting) {
  // the board is turned 180 deg about z: positive roll and pitch rates read below the centre
  const double k = 512.0 / 27.925;
  const darwin::gyro_counts roll = darwin::board_gyro({1.0, 0.0, 3.0});
  EXPECT_DOUBLE_EQ(roll.rl, -k);
  EXPECT_EQ(roll.fb, 0.0);
  const darwin::gyro_counts pitch = darwin::board_gyro({0.0, -0.5, 3.0});
  EXPECT_DOUBLE_EQ(pitch.fb, 0.5 * k);
  EXPECT_EQ(pitch.rl, 0.0);
  // the full range, 27.925 rad/s, is 512 counts
  EXPECT_DOUBLE_EQ(darwin::board_gyro({27.925, 27.925, 0.0}).rl, -512.0);
  // the board's integer is rounded down (Webots truncates 512 + x towards zero)
  EXPECT_EQ(darwin::board_integer(0.0), 0);
  EXPECT_EQ(darwin::board_integer(2.9), 2);
  EXPECT_EQ(darwin::board_integer(-0.1), -1);
  EXPECT_EQ(darwin::board_integer(-3.0), -3);
  EXPECT_EQ(darwin::board_integer(-511.5), -512);
}

// a scripted run with changing targets and pushes; returns the final state image and outputs
std::vector<std::uint8_t> scripted_run(robot_sim& sim, int steps) {
  std::vector<double> targets(darwin::k_servo_count);
  const auto pose = darwin::walk_ready_pose();
  for (int k = 0; k < steps; ++k) {
    const double t = 0.008 * k;
    for (int i = 0; i < darwin::k_servo_count; ++i) {
      targets[static_cast<std::size_t>(i)] =
          pose[static_cast<std::size_t>(i)] + 0.05 * std::sin(3.0 * t + i);
    }
    sim.set_joint_targets(targets);
    sim.set_push(k % 200 < 20 ? 3.0 : 0.0, 0.0);
    sim.step(0.008);
  }
  return sim.save_state();
}

TEST(darwin_op, identical_inputs_give_bit_identical_runs) {
  robot_sim a(darwin::default_config(k_darwin));
  robot_sim b(darwin::default_config(k_darwin));
  const auto image_a = scripted_run(a, 400);
  const auto image_b = scripted_run(b, 400);
  EXPECT_EQ(image_a, image_b);
  // reset restarts the same trajectory
  a.reset();
  EXPECT_EQ(scripted_run(a, 400), image_a);
}

TEST(darwin_op, instances_in_threads_match_the_single_thread_run) {
  robot_sim reference(darwin::default_config(k_darwin));
  const auto expected = scripted_run(reference, 300);
  constexpr int k_threads = 4;
  std::vector<std::vector<std::uint8_t>> images(k_threads);
  std::vector<std::thread> threads;
  for (int t = 0; t < k_threads; ++t) {
    threads.emplace_back([&images, t] {
      robot_sim sim(darwin::default_config(k_darwin));
      images[static_cast<std::size_t>(t)] = scripted_run(sim, 300);
    });
  }
  for (auto& th : threads) th.join();
  for (int t = 0; t < k_threads; ++t) EXPECT_EQ(images[static_cast<std::size_t>(t)], expected) << t;
}

TEST(darwin_op, restoring_a_state_reproduces_the_continuation_bit_exactly) {
  robot_sim sim(darwin::default_config(k_darwin));
  scripted_run(sim, 150);
  const auto snapshot = sim.save_state();
  const auto continued = scripted_run(sim, 250);
  const robot_outputs after = sim.outputs();

  // restore into the same instance and into a fresh one
  sim.restore_state(snapshot);
  EXPECT_EQ(sim.save_state(), snapshot);
  EXPECT_EQ(scripted_run(sim, 250), continued);
  robot_sim fresh(darwin::default_config(k_darwin));
  fresh.restore_state(snapshot);
  EXPECT_EQ(scripted_run(fresh, 250), continued);
  EXPECT_EQ(fresh.outputs().joint_angles, after.joint_angles);
  EXPECT_EQ(fresh.outputs().com, after.com);
  EXPECT_EQ(fresh.outputs().acc, after.acc);
  EXPECT_EQ(fresh.outputs().left_foot_force, after.left_foot_force);
}

}  // namespace
