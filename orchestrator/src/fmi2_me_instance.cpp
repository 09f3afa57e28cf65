// The FMI 2.0 leaf of the Model Exchange runner: one fmi2ModelExchange instance behind
// me_instance.
#include <cstdarg>
#include <cstdlib>

#include "fmi2_calls.hpp"
#include "fmi2_log.hpp"
#include "me_component.hpp"
#include "required_symbol.hpp"
#include "stride/cosim/error.hpp"
#include "stride/fmi2/fmi2_me_api.h"
#include "stride/fmi2/vocabulary.hpp"

namespace stride::cosim {

namespace {

// The functions Model Exchange uses besides its own ten.
// (one function per line; clang-format would reflow the list differently on every run)
// clang-format off
#define STRIDE_ME_COMMON_FUNCTIONS(X) \
  X(fmi2Instantiate)                  \
  X(fmi2FreeInstance)                 \
  X(fmi2SetupExperiment)              \
  X(fmi2EnterInitializationMode)      \
  X(fmi2ExitInitializationMode)       \
  X(fmi2Terminate)                    \
  X(fmi2GetReal)                      \
  X(fmi2GetInteger)                   \
  X(fmi2GetBoolean)                   \
  X(fmi2GetString)                    \
  X(fmi2SetReal)                      \
  X(fmi2SetInteger)                   \
  X(fmi2SetBoolean)                   \
  X(fmi2SetString)                    \
  X(fmi2GetFMUstate)                  \
  X(fmi2SetFMUstate)                  \
  X(fmi2FreeFMUstate)                 \
  X(fmi2SerializedFMUstateSize)       \
  X(fmi2SerializeFMUstate)            \
  X(fmi2DeSerializeFMUstate)
// clang-format on

struct me_functions {
#define STRIDE_DECLARE_POINTER(name) name##TYPE* name = nullptr;
  STRIDE_ME_COMMON_FUNCTIONS(STRIDE_DECLARE_POINTER)
  STRIDE_FMI2_ME_FUNCTIONS(STRIDE_DECLARE_POINTER)
#undef STRIDE_DECLARE_POINTER
};

class fmi2_me_instance final : public detail::me_instance {
 public:
  fmi2_me_instance(std::shared_ptr<fmu> owner, std::string name, const instance_options& options)
      : owner_(std::move(owner)),
        md_(owner_->model_description()),
        name_(std::move(name)),
        log_(options.log ? options.log : stderr_log_sink()),
        callbacks_{&fmi2_me_instance::logger, std::calloc, std::free, nullptr, this} {
    if (md_.co_simulation &&
        md_.co_simulation->model_identifier != md_.model_exchange->model_identifier) {
      throw component_error("component '" + name_ + "': " + owner_->file().string() +
                            " has different Co-Simulation and Model Exchange binaries; only one "
                            "binary per FMU is supported");
    }
    const std::string binary_name =
        "component '" + name_ + "': the binary of " + owner_->file().string();
#define STRIDE_RESOLVE(fn) \
  fn_.fn =                 \
      reinterpret_cast<fn##TYPE*>(detail::required_symbol(owner_->symbol(#fn), #fn, binary_name));
    STRIDE_ME_COMMON_FUNCTIONS(STRIDE_RESOLVE)
    STRIDE_FMI2_ME_FUNCTIONS(STRIDE_RESOLVE)
#undef STRIDE_RESOLVE
    instance_ = fn_.fmi2Instantiate(name_.c_str(), fmi2ModelExchange, md_.guid.c_str(),
                                    owner_->resource_uri().c_str(), &callbacks_, fmi2False,
                                    options.logging_on ? fmi2True : fmi2False);
    if (instance_ == nullptr) {
      throw component_error("component '" + name_ + "': fmi2Instantiate (Model Exchange) of " +
                            owner_->file().string() + " failed (GUID " + md_.guid + ")");
    }
  }

  ~fmi2_me_instance() override {
    if (instance_ != nullptr && !fatal_) fn_.fmi2FreeInstance(instance_);
  }

  const model_description& description() const noexcept override {
    return md_;
  }
  const std::filesystem::path& file() const noexcept override {
    return owner_->file();
  }
  const char* derivatives_function() const noexcept override {
    return "fmi2GetDerivatives";
  }

  void setup(double start, std::optional<double> stop, double tolerance) override {
    check("fmi2SetupExperiment",
          fn_.fmi2SetupExperiment(instance_, fmi2True, tolerance, start,
                                  stop ? fmi2True : fmi2False, stop.value_or(0.0)));
  }
  void enter_initialization() override {
    check("fmi2EnterInitializationMode", fn_.fmi2EnterInitializationMode(instance_));
  }
  void exit_initialization() override {
    check("fmi2ExitInitializationMode", fn_.fmi2ExitInitializationMode(instance_));
  }
  void terminate() override {
    if (!fatal_) check("fmi2Terminate", fn_.fmi2Terminate(instance_));
  }

  void enter_event_mode() override {
    check("fmi2EnterEventMode", fn_.fmi2EnterEventMode(instance_));
  }
  detail::discrete_update update_discrete_states() override {
    fmi2EventInfo info{};
    check("fmi2NewDiscreteStates", fn_.fmi2NewDiscreteStates(instance_, &info));
    return {info.newDiscreteStatesNeeded == fmi2True, info.terminateSimulation == fmi2True,
            info.nextEventTimeDefined == fmi2True, info.nextEventTime};
  }
  void enter_continuous_time_mode() override {
    check("fmi2EnterContinuousTimeMode", fn_.fmi2EnterContinuousTimeMode(instance_));
  }
  bool needs_completed_integrator_step() const noexcept override {
    return !md_.model_exchange->completed_integrator_step_not_needed;
  }
  detail::integrator_step_answer completed_integrator_step() override {
    fmi2Boolean enter = fmi2False;
    fmi2Boolean terminate = fmi2False;
    check("fmi2CompletedIntegratorStep",
          fn_.fmi2CompletedIntegratorStep(instance_, fmi2True, &enter, &terminate));
    return {enter == fmi2True, terminate == fmi2True};
  }

  void set_time(double t) override {
    check("fmi2SetTime", fn_.fmi2SetTime(instance_, t));
  }
  void set_states(std::span<const double> x) override {
    check("fmi2SetContinuousStates", fn_.fmi2SetContinuousStates(instance_, x.data(), x.size()));
  }
  void get_states(std::span<double> x) override {
    check("fmi2GetContinuousStates", fn_.fmi2GetContinuousStates(instance_, x.data(), x.size()));
  }
  void get_derivatives(std::span<double> dx) override {
    check("fmi2GetDerivatives", fn_.fmi2GetDerivatives(instance_, dx.data(), dx.size()));
  }
  void get_indicators(std::span<double> z) override {
    check("fmi2GetEventIndicators", fn_.fmi2GetEventIndicators(instance_, z.data(), z.size()));
  }
  void get_nominals(std::span<double> nominals) override {
    check("fmi2GetNominalsOfContinuousStates",
          fn_.fmi2GetNominalsOfContinuousStates(instance_, nominals.data(), nominals.size()));
  }

  void set_values(const variable_refs& refs, const value_block& values) override;
  void get_values(const variable_refs& refs, value_block& values) override;
  std::vector<std::byte> save() override;
  void restore(std::span<const std::byte> bytes) override;

 private:
  void check(const char* function, fmi2Status s) {
    if (s == fmi2OK || s == fmi2Warning) return;
    if (s == fmi2Fatal) fatal_ = true;
    throw detail::fmu_call_failure(std::string(function) + " returned " +
                                   std::string(fmi2::to_string(static_cast<fmi2::status>(s))));
  }
  // check() as the shared calls of fmi2_calls.hpp take it
  struct status_check {
    fmi2_me_instance* self;
    void operator()(const char* function, fmi2Status s) const { self->check(function, s); }
  };
  status_check checker() {
    return {this};
  }
  static void logger(fmi2ComponentEnvironment env, fmi2String /*instance*/, fmi2Status status,
                     fmi2String category, fmi2String message, ...) {
    auto* self = static_cast<fmi2_me_instance*>(env);
    if (self == nullptr) return;
    std::va_list args;
    va_start(args, message);
    detail::forward_fmi2_log(self->log_, self->name_, status, category, message, args);
    va_end(args);
  }

  std::shared_ptr<fmu> owner_;
  const model_description& md_;
  std::string name_;
  log_sink log_;
  fmi2CallbackFunctions callbacks_;
  me_functions fn_;
  fmi2Component instance_ = nullptr;
  bool fatal_ = false;
  detail::fmi2_scratch scratch_;
};

void fmi2_me_instance::set_values(const variable_refs& refs, const value_block& values) {
  detail::fmi2_set_values(fn_, instance_, refs, values, scratch_, checker());
}

void fmi2_me_instance::get_values(const variable_refs& refs, value_block& values) {
  detail::fmi2_get_values(fn_, instance_, refs, values, scratch_, checker());
  detail::require_finite_reals(refs, values, "fmi2GetReal");
}

std::vector<std::byte> fmi2_me_instance::save() {
  return detail::fmi2_save_state(fn_, instance_, checker());
}

void fmi2_me_instance::restore(std::span<const std::byte> bytes) {
  detail::fmi2_restore_state(fn_, instance_, bytes, checker());
}

}  // namespace

std::unique_ptr<detail::me_instance> instantiate_fmi2_model_exchange(
    std::shared_ptr<fmu> owner, const std::string& instance_name, const instance_options& options) {
  return std::make_unique<fmi2_me_instance>(std::move(owner), instance_name, options);
}

}  // namespace stride::cosim
