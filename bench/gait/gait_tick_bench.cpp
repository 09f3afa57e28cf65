// One 8 ms tick of the walking generator: trajectories + both leg IKs + servo values for all 20
// servos, in a steady walk (all phases of the cycle visited in turn). Target: <= 1 us per tick.
#include <benchmark/benchmark.h>

#include "stride/gait/walking.hpp"

namespace {

using namespace stride::gait;

void run(benchmark::State& bench, ik_mode mode, double x, double y, double a) {
  const walking gen(mode);
  walking_params params;
  walking_state state = gen.initialize(params);
  gen.set_command(state, x, y, a, false);
  gen.start(state);
  const walking_feedback feedback{true, 3, -2};
  for (int i = 0; i < 300; ++i) gen.tick(state, params, feedback);  // warm-up: steady walk
  for (auto _ : bench) {
    gen.tick(state, params, feedback);
    benchmark::DoNotOptimize(state.servo_count);
  }
  bench.SetItemsProcessed(bench.iterations());
}

void gait_tick_forward_x20(benchmark::State& s) {
  run(s, ik_mode::darwin, 20, 0, 0);
}
void gait_tick_omni_darwin(benchmark::State& s) {
  run(s, ik_mode::darwin, 15, 20, 10);
}
void gait_tick_omni_geometric(benchmark::State& s) {
  run(s, ik_mode::geometric, 15, 20, 10);
}

}  // namespace

BENCHMARK(gait_tick_forward_x20);
BENCHMARK(gait_tick_omni_darwin);
BENCHMARK(gait_tick_omni_geometric);
