// stride's master (execution + Gauss-Seidel algorithm) against a hand-written loop that makes
// the same FMI calls on the same two stride_test instances (a.y → b.u, a.vec_out → b.vec_in).
// The ratio of the two times per step is the orchestrator's overhead (target ≤ 1.03 for real
// components; stride_test steps take well under a microsecond, so this is the worst case).
#include <benchmark/benchmark.h>

#include <array>
#include <filesystem>

#include "stride/cosim/fmu.hpp"
#include "stride/cosim/system_builder.hpp"

namespace {

using namespace stride::cosim;
namespace fs = std::filesystem;

constexpr int k_steps = 10000;
const duration k_step{10'000'000};

log_sink quiet() {
  return [](log_level, std::string_view, std::string_view, std::string_view) {};
}

void hand_written_loop(benchmark::State& state) {
  auto f = fmu::load(fs::path(STRIDE_FMU_DIR) / "stride_test.fmu");
  const auto& md = f->model_description();
  auto vr = [&](const char* name) { return md.find(name)->reference; };
  const std::array<value_reference, 4> outs{vr("y"), vr("vec_out[1]"), vr("vec_out[2]"),
                                            vr("vec_out[3]")};
  const std::array<value_reference, 4> ins{vr("u"), vr("vec_in[1]"), vr("vec_in[2]"),
                                           vr("vec_in[3]")};
  for (auto _ : state) {
    state.PauseTiming();
    auto a = f->instantiate("a", {quiet(), false});
    auto b = f->instantiate("b", {quiet(), false});
    for (auto* c : {a.get(), b.get()}) {
      c->setup(time_point{}, time_point{} + k_steps * k_step);
      c->enter_initialization();
      c->exit_initialization();
    }
    std::array<double, 4> values{};
    state.ResumeTiming();
    for (int k = 0; k < k_steps; ++k) {
      const time_point t{k * k_step};
      a->do_step(t, k_step);
      a->get_real(outs, values);
      b->set_real(ins, values);
      b->do_step(t, k_step);
      b->get_real(outs, values);  // what a recorder of b would read
      benchmark::DoNotOptimize(values);
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
    auto& algo = built.execution->algorithm();
    for (const char* v : {"y", "vec_out[1]", "vec_out[2]", "vec_out[3]"}) {
      algo.observe({1, *algo.component_at(1).model_description().index_of(v)});
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

}  // namespace

BENCHMARK(hand_written_loop)->Unit(benchmark::kMillisecond);
BENCHMARK(stride_execution)->Unit(benchmark::kMillisecond);
