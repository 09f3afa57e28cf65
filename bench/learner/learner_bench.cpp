// The gait-parameter learner in its closed loop: robot.fmu + gait.fmu + learner.fmu as in
// models/experiments/demo.xml (Experiment 1 grid and Table 2 settings), single-threaded, no files
// written. One iteration = one RL step (W = 4 measured + 1 settle footstep, or a fall).
// Counters: rl_steps_per_s (wall), sim_s_per_rl_step, exp1_300k_h = projected wall time of
// Experiment 1 (300 000 RL steps) in hours at the measured rate.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "stride/cosim/observers.hpp"
#include "stride/cosim/run.hpp"

namespace {

using namespace stride::cosim;

void closed_loop_rl_steps(benchmark::State& state) {
  auto system =
      parse_system_file(std::filesystem::path(STRIDE_SOURCE_DIR) / "models/experiments/demo.xml");
  system.set("learner.output_dir", "");
  system.set("learner.resume", "");
  system.set("learner.total_steps", "0");
  system.set("learner.log_progress", "false");
  system.set("learner.seed", std::to_string(state.range(0)));
  build_options options;
  options.log = stderr_log_sink(log_level::warning);
  built_system built = build_system(system, options);
  auto& algo = *built.execution;
  const auto rl_vars = find_variables(algo, "learner.rl_step");
  if (rl_vars.size() != 1) {
    state.SkipWithError("no learner.rl_step");
    return;
  }
  const observed_variable rl = algo.observe(rl_vars[0]);
  built.execution->initialize(built.stop);
  const auto sim_start = algo.current_time();
  std::int64_t steps = 0;
  for (auto _ : state) {
    const int before = algo.integer_value(rl);
    while (algo.integer_value(rl) == before) algo.step();
    ++steps;
  }
  const double sim = to_seconds(algo.current_time() - sim_start);
  state.counters["rl_steps_per_s"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
  state.counters["sim_s_per_rl_step"] = sim / static_cast<double>(steps);
  // elapsed * 300000 / steps, in hours
  state.counters["exp1_300k_h"] =
      benchmark::Counter(static_cast<double>(steps) / 300000.0 * 3600.0,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  built.execution->end();
}

}  // namespace

BENCHMARK(closed_loop_rl_steps)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(30.0)
    ->UseRealTime();
