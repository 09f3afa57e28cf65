// Cost of one communication step of a Model Exchange FMU run by Stride's integrators (CVODE BDF,
// CVODE Adams) beside the same model as a Co-Simulation FMU that integrates itself (RK4 at
// 1 ms): the bouncing ball (two states, a state event about every 0.3 s) and the ten-state
// linear chain, both the project's own test FMUs (tests/orchestrator/me_fmus). One benchmark
// iteration is one communication step of 10 ms; the models run over [0, 2 s] again and again
// (the ball comes to rest at 2.6 s, where its bounces pile up).
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>

#include "stride/cosim/archive.hpp"
#include "stride/cosim/fmu.hpp"
#include "zip_writer.hpp"

namespace {

using namespace stride::cosim;
namespace fs = std::filesystem;

const duration k_step = duration_from_seconds(0.01);
const time_point k_window = time_from_seconds(2.0);

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The model's FMU offering both interfaces from its one library.
std::shared_ptr<fmu> both_kinds(const temp_dir& dir, const std::string& model,
                                const std::string& library) {
  std::string description = read_text(fs::path(STRIDE_ME_FMU_SOURCES) / (model + ".xml"));
  // after <ModelExchange/>: the schema orders the two
  description.insert(description.find("/>", description.find("<ModelExchange")) + 2,
                     "\n  <CoSimulation modelIdentifier=\"me_" + model + "\"/>");
  const fs::path file = dir.path() / (model + ".fmu");
  test::write_zip(file, {{"modelDescription.xml", description},
                         {"binaries/linux64/me_" + model + ".so", read_text(library)}});
  return fmu::load(file);
}

enum class runner { cvode_bdf, cvode_adams, co_simulation };

std::unique_ptr<component> start(fmu& f, runner r, const variable_refs& outputs) {
  instance_options io;
  io.log = [](log_level, std::string_view, std::string_view, std::string_view) {};
  if (r != runner::co_simulation) {
    model_exchange_options o;  // tolerances: the FMU's DefaultExperiment (1e-6)
    if (r == runner::cvode_adams) o.method = model_exchange_options::method_kind::adams;
    io.model_exchange = o;
  }
  auto c = f.instantiate("bench", io);
  c->setup(time_point{}, k_window);
  c->enter_initialization();
  c->exit_initialization();
  c->expose({}, outputs);
  return c;
}

// The ball behind the FMI 3.0 wrapper (Model Exchange only).
std::shared_ptr<fmu> ball3(const temp_dir& dir) {
  const fs::path file = dir.path() / "ball3.fmu";
  test::write_zip(
      file, {{"modelDescription.xml", read_text(fs::path(STRIDE_ME_FMU_SOURCES) / "ball3.xml")},
             {"binaries/x86_64-linux/me3_ball.so", read_text(STRIDE_ME3_BALL)}});
  return fmu::load(file);
}

void run_steps(benchmark::State& state, fmu& f, runner r, const variable_refs& outputs) {
  auto c = start(f, r, outputs);
  time_point t{};
  value_block out;
  out.resize_for(outputs);
  for (auto _ : state) {
    if (t + k_step > k_window) {
      state.PauseTiming();
      c = start(f, r, outputs);
      t = {};
      state.ResumeTiming();
    }
    c->step(t, k_step, {}, out);
    t += k_step;
  }
  benchmark::DoNotOptimize(out.reals.data());
}

void communication_step(benchmark::State& state, const std::string& model,
                        const std::string& library, runner r, const variable_refs& outputs) {
  const temp_dir dir("stride-me-bench-");
  run_steps(state, *both_kinds(dir, model, library), r, outputs);
}

variable_refs reals(std::initializer_list<std::uint32_t> refs) {
  variable_refs r;
  r.reals = refs;
  return r;
}

void ball(benchmark::State& state, runner r) {
  communication_step(state, "ball", STRIDE_ME_BALL, r, reals({0, 2}));
}
void chain(benchmark::State& state, runner r) {
  communication_step(state, "chain", STRIDE_ME_CHAIN, r, reals({0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
}

BENCHMARK_CAPTURE(ball, cvode_bdf, runner::cvode_bdf);
BENCHMARK_CAPTURE(ball, cvode_adams, runner::cvode_adams);
BENCHMARK_CAPTURE(ball, co_simulation_rk4, runner::co_simulation);
// the same equations through FMI 3.0 (h and v are ports 0 and 2 there too)
void ball_fmi3(benchmark::State& state) {
  const temp_dir dir("stride-me-bench-");
  run_steps(state, *ball3(dir), runner::cvode_bdf, reals({0, 2}));
}
BENCHMARK(ball_fmi3);
BENCHMARK_CAPTURE(chain, cvode_bdf, runner::cvode_bdf);
BENCHMARK_CAPTURE(chain, cvode_adams, runner::cvode_adams);
BENCHMARK_CAPTURE(chain, co_simulation_rk4, runner::co_simulation);

}  // namespace
