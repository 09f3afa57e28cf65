// DARwIn-OP plant speed: simulated seconds per wall second (counter "rtf") on one core, at the
// default DARwIn configuration (physics step and solver are reported as counters).
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "stride/robot/darwin.hpp"
#include "stride/robot/robot_sim.hpp"
#if defined(STRIDE_HAVE_GAIT_CORE)
#include "stride/gait/walking.hpp"
#endif

namespace {

namespace darwin = stride::robot::darwin;
using stride::robot::robot_config;
using stride::robot::robot_sim;

const std::string k_darwin = std::string(STRIDE_SOURCE_DIR) + "/models/darwin-op/darwin-op.urdf";
constexpr double k_control_step = 0.008;
constexpr double k_sim_seconds = 10.0;

robot_config bench_config(const benchmark::State& state) {
  robot_config c = darwin::default_config(k_darwin);
  c.physics_step = static_cast<double>(state.range(0)) / 1000.0;
  if (state.range(1) == 0) c.rigid_servos.clear();
  return c;
}

void report(benchmark::State& state, const robot_config& c) {
  state.counters["rtf"] = benchmark::Counter(
      k_sim_seconds * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["physics_step_ms"] = c.physics_step * 1000.0;
  state.counters["bodies"] = static_cast<double>(21 - c.rigid_servos.size());
}

// standing in the walk-ready pose, 8 ms control steps
void bm_stand(benchmark::State& state) {
  const robot_config c = bench_config(state);
  robot_sim sim(c);
  for (auto _ : state) {
    state.PauseTiming();
    sim.reset();
    state.ResumeTiming();
    for (int k = 0; k < static_cast<int>(k_sim_seconds / k_control_step); ++k) {
      sim.step(k_control_step);
    }
    benchmark::DoNotOptimize(sim.outputs().com);
  }
  report(state, c);
}

#if defined(STRIDE_HAVE_GAIT_CORE)
namespace gait = stride::gait;

// closed loop with the gait core: x_move 20 mm, Webots lateral gains 0, gyro every 8 ms tick;
// the gait's own cost is included
void bm_walk(benchmark::State& state) {
  const robot_config c = bench_config(state);
  robot_sim sim(c);
  const gait::walking gen;
  gait::walking_params params;
  params.balance_hip_roll_gain = 0.0;
  params.balance_ankle_roll_gain = 0.0;
  std::vector<double> targets(c.initial_pose);
  for (auto _ : state) {
    state.PauseTiming();
    sim.reset();
    gait::walking_state s = gen.initialize(params);
    gen.set_command(s, 20.0, 0, 0, false);
    gen.start(s);
    state.ResumeTiming();
    for (int k = 0; k < static_cast<int>(k_sim_seconds / k_control_step); ++k) {
      gait::walking_feedback fb;
      const darwin::gyro_counts gyro = darwin::board_gyro(sim.outputs().gyro);
      fb.gyro_fb = static_cast<int>(gyro.fb);
      fb.gyro_rl = static_cast<int>(gyro.rl);
      gen.set_command(s, 20.0, 0, 0, false);
      gen.tick(s, params, fb);
      for (int i = 0; i < 18; ++i) {
        targets[static_cast<std::size_t>(i)] = gait::servo_count_to_rad(s.servo_count[i]);
      }
      sim.set_joint_targets(targets);
      sim.step(k_control_step);
    }
    if (sim.outputs().fallen) state.SkipWithError("the robot fell");
    benchmark::DoNotOptimize(sim.outputs().com);
  }
  report(state, c);
}
#endif

// args: physics step in ms (16 = DARwIn default), rigid arms/head (1 = DARwIn default, 0 = all
// 20 servos driven)
void arguments(benchmark::internal::Benchmark* b) {
  b->Args({16, 1})->Args({16, 0})->Args({8, 1})->Args({4, 1});
  b->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
}

}  // namespace

BENCHMARK(bm_stand)->Apply(arguments);
#if defined(STRIDE_HAVE_GAIT_CORE)
BENCHMARK(bm_walk)->Apply(arguments);
#endif
