// stride's master (execution + Gauss-Seidel algorithm) against a hand-written loop that makes
// the same FMI calls on the same two stride_test instances (a.y → b.u, a.vec_out → b.vec_in).
// The ratio of the two times per step is the orchestrator's overhead (target ≤ 1.03 for real
// components; stride_test steps take well under a microsecond, so this is the worst case).
#include <benchmark/benchmark.h>

#include <array>
#include <filesystem>
#include <string>

#include "stride/cosim/fmu.hpp"
#include "stride/cosim/system_builder.hpp"
#include "stride/cosim/system_structure.hpp"

namespace {

using namespace stride::cosim;
namespace fs = std::filesystem;

constexpr int k_steps = 10000;
const duration k_step{10'000'000};

log_sink quiet() {
  return [](log_level, std::string_view, std::string_view, std::string_view) {};
}

void hand_written_loop(benchmark::State& state) {
  const auto file = fs::path(STRIDE_FMU_DIR) / "stride_test.fmu";
  const auto interface = fmu::load(file);
  const auto& md = interface->model_description();
  auto vr = [&](const char* name) { return md.find(name)->reference; };
  variable_refs outs, ins;
  outs.reals = {vr("y"), vr("vec_out[1]"), vr("vec_out[2]"), vr("vec_out[3]")};
  ins.reals = {vr("u"), vr("vec_in[1]"), vr("vec_in[2]"), vr("vec_in[3]")};
  for (auto _ : state) {
    state.PauseTiming();
    // loaded afresh, as build_system does for stride_execution: both start on cold pages
    const auto f = fmu::load(file);
    auto a = f->instantiate("a", {quiet(), false});
    auto b = f->instantiate("b", {quiet(), false});
    a->expose({}, outs);
    b->expose(ins, outs);  // b's outputs: what a recorder of b would read
    for (auto* c : {a.get(), b.get()}) {
      c->setup(time_point{}, time_point{} + k_steps * k_step);
      c->enter_initialization();
      c->exit_initialization();
    }
    const value_block none;
    value_block a_out, b_out;
    a_out.resize_for(outs);
    b_out.resize_for(outs);
    state.ResumeTiming();
    for (int k = 0; k < k_steps; ++k) {
      const time_point t{k * k_step};
      a->step(t, k_step, none, a_out);
      b->step(t, k_step, a_out, b_out);
      benchmark::DoNotOptimize(b_out);
    }
  }
  state.SetItemsProcessed(state.iterations() * k_steps);
}

void stride_execution(benchmark::State& state) {
  system_structure s;
  s.stop = time_point{} + k_steps * k_step;
  s.base_step = k_step;
  s.add_component("a", "stride_test");
  s.add_component("b", "stride_test");
  s.connect("a.y", "b.u");
  s.connect("a.vec_out[*]", "b.vec_in[*]");
  build_options o;
  o.log = quiet();
  for (auto _ : state) {
    state.PauseTiming();
    auto built = build_system(s, o);
    auto& algo = *built.execution;
    for (const char* v : {"y", "vec_out[1]", "vec_out[2]", "vec_out[3]"}) {
      algo.observe(variable_id{1, *algo.component_at(1).model_description().index_of(v)});
    }
    built.execution->initialize(built.stop);
    state.ResumeTiming();
    benchmark::DoNotOptimize(built.execution->simulate_until(built.stop));
    state.PauseTiming();
    built.execution.reset();
    state.ResumeTiming();
  }
  state.SetItemsProcessed(state.iterations() * k_steps);
}

// The walking closed loop of models/walk.xml (gait + robot, 10 s): the figure the issue asks
// for, since real components dominate the cost there.
constexpr int k_walk_steps = 1250;
const duration k_walk_step{8'000'000};

void set_walk_parameters(component& gait, const model_description& md) {
  variable_refs refs;
  refs.reals = {md.find("x_move")->reference, md.find("balance_hip_roll_gain")->reference,
                md.find("balance_ankle_roll_gain")->reference};
  refs.booleans = {md.find("walking")->reference};
  value_block values;
  values.reals = {20.0, 0.0, 0.0};
  values.booleans = {true};
  gait.set_values(refs, values);
}

void hand_written_walk(benchmark::State& state) {
  const auto gait_file = fs::path(STRIDE_FMU_DIR) / "gait.fmu";
  const auto robot_file = fs::path(STRIDE_FMU_DIR) / "robot.fmu";
  // value references, from one load; every iteration below loads its own copies
  const auto gait_interface = fmu::load(gait_file);
  const auto robot_interface = fmu::load(robot_file);
  const auto& gm = gait_interface->model_description();
  const auto& rm = robot_interface->model_description();
  // what each component sets and returns with every step
  variable_refs gait_in, gait_out, robot_in, robot_out;
  for (int i = 1; i <= 20; ++i) {
    const std::string index = "[" + std::to_string(i) + "]";
    gait_out.reals.push_back(gm.find("joint_angle" + index)->reference);
    robot_in.reals.push_back(rm.find("joint_target" + index)->reference);
  }
  robot_out.integers = {rm.find("gyro_fb")->reference, rm.find("gyro_rl")->reference};
  gait_in.integers = {gm.find("gyro_fb")->reference, gm.find("gyro_rl")->reference};
  for (auto _ : state) {
    state.PauseTiming();
    // loaded afresh, as build_system does for stride_walk: both loops then start on cold
    // library pages (worth about 5 % of this 10 s walk)
    const auto gait_fmu = fmu::load(gait_file);
    const auto robot_fmu = fmu::load(robot_file);
    auto gait = gait_fmu->instantiate("gait", {quiet(), false});
    auto robot = robot_fmu->instantiate("robot", {quiet(), false});
    set_walk_parameters(*gait, gm);
    gait->expose(gait_in, gait_out);
    robot->expose(robot_in, robot_out);
    for (auto* c : {gait.get(), robot.get()}) {
      c->setup(time_point{}, time_point{} + k_walk_steps * k_walk_step);
      c->enter_initialization();
      c->exit_initialization();
    }
    value_block q, gyro;  // the gait's angles; the robot's gyro of the previous step
    q.resize_for(gait_out);
    gyro.resize_for(robot_out);
    state.ResumeTiming();
    for (int k = 0; k < k_walk_steps; ++k) {
      const time_point t{k * k_walk_step};
      gait->step(t, k_walk_step, gyro, q);
      robot->step(t, k_walk_step, q, gyro);
    }
  }
  state.SetItemsProcessed(state.iterations() * k_walk_steps);
}

// runs a system file for k_walk_steps base steps per iteration, built afresh each time; with
// `fmu_folder`, every component's FMU is taken from that folder of the build's FMUs
void run_system_file(benchmark::State& state, const char* file, int threads,
                     const char* fmu_folder = nullptr) {
  auto s = parse_system_file(fs::path(STRIDE_SOURCE_DIR) / "models" / file);
  if (fmu_folder != nullptr) {
    for (component_spec& c : s.components) {
      c.fmu = (fs::path(STRIDE_FMU_DIR) / fmu_folder / (c.fmu + ".fmu")).string();
    }
  }
  s.stop = time_point{} + k_walk_steps * k_walk_step;
  s.record = {};
  build_options o;
  o.log = quiet();
  o.threads = threads;
  for (auto _ : state) {
    state.PauseTiming();
    auto built = build_system(s, o);
    built.execution->initialize(built.stop);
    state.ResumeTiming();
    benchmark::DoNotOptimize(built.execution->simulate_until(built.stop));
    state.PauseTiming();
    built.execution.reset();
    state.ResumeTiming();
  }
  state.SetItemsProcessed(state.iterations() * k_walk_steps);
}

void stride_walk(benchmark::State& state) {
  run_system_file(state, "walk.xml", 1);
}

// the same walk with gait and robot from their FMI 3.0 FMUs
void stride_walk_fmi3(benchmark::State& state) {
  run_system_file(state, "walk.xml", 1, "fmi3");
}

// models/walkers.xml: four independent walkers (gait + robot each), 10 s, on 1 or 2 threads.
// Wall time: the point is that two threads finish sooner.
void stride_walkers(benchmark::State& state) {
  run_system_file(state, "walkers.xml", static_cast<int>(state.range(0)));
}

}  // namespace

BENCHMARK(hand_written_loop)->Unit(benchmark::kMillisecond);
BENCHMARK(stride_execution)->Unit(benchmark::kMillisecond);
BENCHMARK(hand_written_walk)->Unit(benchmark::kMillisecond)->MinTime(3.0);
BENCHMARK(stride_walk)->Unit(benchmark::kMillisecond)->MinTime(3.0);
BENCHMARK(stride_walk_fmi3)->Unit(benchmark::kMillisecond)->MinTime(3.0);
BENCHMARK(stride_walkers)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(5.0);
