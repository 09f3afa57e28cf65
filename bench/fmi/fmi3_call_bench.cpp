// Cost of one fmi3SetFloat64 + fmi3DoStep + fmi3GetFloat64 triple on the stride_test FMU's FMI 3.0
// binary, through dlopen/dlsym as any importer calls it; the FMI 2.0 triple (fmi_call_bench) is
// the reference. Goal: within 10 % of it.
#include <benchmark/benchmark.h>
#include <dlfcn.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "stride/fmi3/fmi3_api.h"

namespace {

template <class F>
F* resolve(void* handle, const char* name) {
  void* f = dlsym(handle, name);
  if (f == nullptr) throw std::runtime_error(std::string("missing ") + name);
  return reinterpret_cast<F*>(f);
}

struct loaded_fmu3 {
  void* handle = dlopen(STRIDE_TEST_FMU3_LIBRARY, RTLD_NOW | RTLD_LOCAL);
  fmi3InstantiateCoSimulationTYPE* instantiate =
      resolve<fmi3InstantiateCoSimulationTYPE>(handle, "fmi3InstantiateCoSimulation");
  fmi3EnterInitializationModeTYPE* enter_init =
      resolve<fmi3EnterInitializationModeTYPE>(handle, "fmi3EnterInitializationMode");
  fmi3ExitInitializationModeTYPE* exit_init =
      resolve<fmi3ExitInitializationModeTYPE>(handle, "fmi3ExitInitializationMode");
  fmi3SetFloat64TYPE* set = resolve<fmi3SetFloat64TYPE>(handle, "fmi3SetFloat64");
  fmi3GetFloat64TYPE* get = resolve<fmi3GetFloat64TYPE>(handle, "fmi3GetFloat64");
  fmi3DoStepTYPE* do_step = resolve<fmi3DoStepTYPE>(handle, "fmi3DoStep");
  fmi3TerminateTYPE* terminate = resolve<fmi3TerminateTYPE>(handle, "fmi3Terminate");
  fmi3FreeInstanceTYPE* free_instance = resolve<fmi3FreeInstanceTYPE>(handle, "fmi3FreeInstance");

  ~loaded_fmu3() { dlclose(handle); }
};

std::string model_description() {
  std::ifstream in(STRIDE_TEST_FMU3_MODEL_DESCRIPTION);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string instantiation_token(const std::string& xml) {
  const auto start = xml.find("instantiationToken=\"") + 20;
  return xml.substr(start, xml.find('"', start) - start);
}

// the FMI 3.0 value reference of a scalar (the generator writes valueReference right after name)
fmi3ValueReference value_reference(const std::string& xml, const std::string& variable) {
  const std::string key = "name=\"" + variable + "\" valueReference=\"";
  const auto at = xml.find(key);
  if (at == std::string::npos) throw std::runtime_error("no variable " + variable);
  return static_cast<fmi3ValueReference>(std::stoul(xml.substr(at + key.size())));
}

void ignore_log(fmi3InstanceEnvironment, fmi3Status, fmi3String, fmi3String) {}

void set_step_get3(benchmark::State& state) {
  loaded_fmu3 fmu;
  const std::string xml = model_description();
  fmi3Instance c =
      fmu.instantiate("bench", instantiation_token(xml).c_str(), nullptr, fmi3False, fmi3False,
                      fmi3False, fmi3False, nullptr, 0, nullptr, &ignore_log, nullptr);
  if (c == nullptr) {
    state.SkipWithError("fmi3InstantiateCoSimulation failed");
    return;
  }
  fmu.enter_init(c, fmi3False, 0, 0, fmi3False, 0);
  fmu.exit_init(c);
  const fmi3ValueReference u = value_reference(xml, "u"), y = value_reference(xml, "y");
  double t = 0, in = 0, out = 0;
  fmi3Boolean event, terminate, early;
  fmi3Float64 last;
  for (auto _ : state) {
    in += 1e-3;
    fmu.set(c, &u, 1, &in, 1);
    fmu.do_step(c, t, 0.01, fmi3True, &event, &terminate, &early, &last);
    fmu.get(c, &y, 1, &out, 1);
    benchmark::DoNotOptimize(out);
    t += 0.01;
  }
  fmu.terminate(c);
  fmu.free_instance(c);
}
BENCHMARK(set_step_get3);

}  // namespace
