// Cost of one fmi2SetReal + fmi2DoStep + fmi2GetReal triple on the stride_test FMU, called
// through function pointers obtained with dlopen/dlsym, as any importer does. Target: ≤ 100 ns.
#include <benchmark/benchmark.h>
#include <dlfcn.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "stride/fmi2/fmi2_api.h"

namespace {

struct loaded_fmu {
  void* handle = nullptr;
#define STRIDE_DECLARE(name) name##TYPE* name = nullptr;
  STRIDE_FMI2_CS_FUNCTIONS(STRIDE_DECLARE)
#undef STRIDE_DECLARE

  loaded_fmu() {
    handle = dlopen(STRIDE_TEST_FMU_LIBRARY, RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) throw std::runtime_error(dlerror());
#define STRIDE_RESOLVE(name) name = reinterpret_cast<name##TYPE*>(dlsym(handle, #name));
    STRIDE_FMI2_CS_FUNCTIONS(STRIDE_RESOLVE)
#undef STRIDE_RESOLVE
  }
  ~loaded_fmu() {
    dlclose(handle);
  }
};

std::string read_guid() {
  std::ifstream in(STRIDE_TEST_FMU_MODEL_DESCRIPTION);
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  const auto start = xml.find("guid=\"") + 6;
  return xml.substr(start, xml.find('"', start) - start);
}

void ignore_log(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String, fmi2String, ...) {}

void set_step_get(benchmark::State& state) {
  loaded_fmu fmu;
  const fmi2CallbackFunctions callbacks{&ignore_log, nullptr, nullptr, nullptr, nullptr};
  fmi2Component c = fmu.fmi2Instantiate("bench", fmi2CoSimulation, read_guid().c_str(), nullptr,
                                        &callbacks, fmi2False, fmi2False);
  if (c == nullptr) {
    state.SkipWithError("fmi2Instantiate failed");
    return;
  }
  fmu.fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0);
  fmu.fmi2EnterInitializationMode(c);
  fmu.fmi2ExitInitializationMode(c);
  const fmi2ValueReference u = 2, y = 3;  // stride_test: u and y
  double t = 0, in = 0, out = 0;
  for (auto _ : state) {
    in += 1e-3;
    fmu.fmi2SetReal(c, &u, 1, &in);
    fmu.fmi2DoStep(c, t, 0.01, fmi2True);
    fmu.fmi2GetReal(c, &y, 1, &out);
    benchmark::DoNotOptimize(out);
    t += 0.01;
  }
  fmu.fmi2Terminate(c);
  fmu.fmi2FreeInstance(c);
}
BENCHMARK(set_step_get);

}  // namespace
