// The FMI 3.0 leaf of the Model Exchange runner: one fmi3InstantiateModelExchange instance
// behind me_instance, its values through the same typed, array-aware channels as 3.0
// Co-Simulation (fmi3_values.hpp).
#include <string>

#include "fmi3_fmu.hpp"
#include "fmi3_values.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim::fmi3 {

namespace {

class fmi3_me_instance final : public cosim::detail::me_instance {
 public:
  fmi3_me_instance(std::shared_ptr<const void> owner, const binary& bin, std::string name,
                   const instance_options& options)
      : owner_(std::move(owner)),
        bin_(bin),
        fn_(bin.fn),
        name_(std::move(name)),
        log_(options.log ? options.log : stderr_log_sink()),
        values_(bin, name_, &fmi3_me_instance::check_status, this) {
    const std::string resources = bin_.resources.empty() ? "" : bin_.resources.string() + "/";
    instance_ = fn_.fmi3InstantiateModelExchange(
        name_.c_str(), bin_.description.scalar.guid.c_str(),
        resources.empty() ? nullptr : resources.c_str(), /*visible*/ fmi3False,
        options.logging_on ? fmi3True : fmi3False, this, &fmi3_me_instance::logger);
    if (instance_ == nullptr) {
      throw component_error("component '" + name_ + "': fmi3InstantiateModelExchange of " +
                            bin_.file.string() + " failed (instantiationToken " +
                            bin_.description.scalar.guid + "; see the FMU's log messages above)");
    }
  }

  ~fmi3_me_instance() override {
    if (instance_ != nullptr && !fatal_) fn_.fmi3FreeInstance(instance_);
  }

  const model_description& description() const noexcept override { return bin_.description.scalar; }
  const std::filesystem::path& file() const noexcept override { return bin_.file; }
  const char* derivatives_function() const noexcept override {
    return "fmi3GetContinuousStateDerivatives";
  }

  // 3.0 has no fmi3SetupExperiment: the times go to fmi3EnterInitializationMode
  void setup(double start, std::optional<double> stop, double tolerance) override {
    start_ = start;
    stop_ = stop;
    tolerance_ = tolerance;
  }
  void enter_initialization() override {
    check("fmi3EnterInitializationMode",
          fn_.fmi3EnterInitializationMode(instance_, fmi3True, tolerance_, start_,
                                          stop_ ? fmi3True : fmi3False, stop_.value_or(0.0)));
  }
  void exit_initialization() override {
    check("fmi3ExitInitializationMode", fn_.fmi3ExitInitializationMode(instance_));
    initialised_ = true;
    require_declared_sizes();
  }
  void terminate() override {
    if (!fatal_) check("fmi3Terminate", fn_.fmi3Terminate(instance_));
  }

  void enter_event_mode() override {
    check("fmi3EnterEventMode", fn_.fmi3EnterEventMode(instance_));
  }
  cosim::detail::discrete_update update_discrete_states() override {
    fmi3Boolean again = fmi3False;
    fmi3Boolean terminate = fmi3False;
    fmi3Boolean nominals_changed = fmi3False;
    fmi3Boolean values_changed = fmi3False;
    fmi3Boolean next_defined = fmi3False;
    fmi3Float64 next = 0.0;
    check("fmi3UpdateDiscreteStates",
          fn_.fmi3UpdateDiscreteStates(instance_, &again, &terminate, &nominals_changed,
                                       &values_changed, &next_defined, &next));
    return {again == fmi3True, terminate == fmi3True, next_defined == fmi3True, next};
  }
  void enter_continuous_time_mode() override {
    check("fmi3EnterContinuousTimeMode", fn_.fmi3EnterContinuousTimeMode(instance_));
  }
  bool needs_completed_integrator_step() const noexcept override {
    return !bin_.description.scalar.model_exchange->completed_integrator_step_not_needed;
  }
  cosim::detail::integrator_step_answer completed_integrator_step() override {
    fmi3Boolean enter = fmi3False;
    fmi3Boolean terminate = fmi3False;
    check("fmi3CompletedIntegratorStep",
          fn_.fmi3CompletedIntegratorStep(instance_, fmi3True, &enter, &terminate));
    return {enter == fmi3True, terminate == fmi3True};
  }

  void set_time(double t) override { check("fmi3SetTime", fn_.fmi3SetTime(instance_, t)); }
  void set_states(std::span<const double> x) override {
    check("fmi3SetContinuousStates", fn_.fmi3SetContinuousStates(instance_, x.data(), x.size()));
  }
  void get_states(std::span<double> x) override {
    check("fmi3GetContinuousStates", fn_.fmi3GetContinuousStates(instance_, x.data(), x.size()));
  }
  void get_derivatives(std::span<double> dx) override {
    check("fmi3GetContinuousStateDerivatives",
          fn_.fmi3GetContinuousStateDerivatives(instance_, dx.data(), dx.size()));
  }
  void get_indicators(std::span<double> z) override {
    check("fmi3GetEventIndicators", fn_.fmi3GetEventIndicators(instance_, z.data(), z.size()));
  }
  void get_nominals(std::span<double> nominals) override {
    check("fmi3GetNominalsOfContinuousStates",
          fn_.fmi3GetNominalsOfContinuousStates(instance_, nominals.data(), nominals.size()));
  }

  void set_values(const variable_refs& refs, const value_block& values) override {
    values_.set(instance_, refs, values);
  }
  void get_values(const variable_refs& refs, value_block& values) override {
    values_.get(instance_, refs, values);
    cosim::detail::require_finite_reals(refs, values, "fmi3GetFloat64");
  }

  std::vector<std::byte> save() override;
  void restore(std::span<const std::byte> bytes) override;

 private:
  // the runner sizes its vectors from ModelStructure; the binary must agree
  void require_declared_sizes() {
    const auto& md = bin_.description.scalar;
    std::size_t states = 0;
    std::size_t indicators = 0;
    check("fmi3GetNumberOfContinuousStates",
          fn_.fmi3GetNumberOfContinuousStates(instance_, &states));
    check("fmi3GetNumberOfEventIndicators",
          fn_.fmi3GetNumberOfEventIndicators(instance_, &indicators));
    if (states != md.derivatives.size() || indicators != md.number_of_event_indicators) {
      throw cosim::detail::fmu_call_failure(
          "the binary reports " + std::to_string(states) + " continuous states and " +
          std::to_string(indicators) + " event indicators, modelDescription.xml declares " +
          std::to_string(md.derivatives.size()) + " <ContinuousStateDerivative> and " +
          std::to_string(md.number_of_event_indicators) + " <EventIndicator> elements");
    }
  }

  static void check_status(void* self, const char* function, fmi3Status s) {
    static_cast<fmi3_me_instance*>(self)->check(function, s);
  }
  void check(const char* function, fmi3Status s) {
    if (s == fmi3OK || s == fmi3Warning) return;
    if (s == fmi3Fatal) fatal_ = true;
    throw cosim::detail::fmu_call_failure(std::string(function) + " returned " + status_name(s));
  }
  static void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                     fmi3String message) {
    auto* self = static_cast<fmi3_me_instance*>(env);
    if (self != nullptr) forward_log(self->log_, self->name_, status, category, message);
  }

  std::shared_ptr<const void> owner_;
  const binary& bin_;
  const functions& fn_;
  std::string name_;
  log_sink log_;
  value_io values_;
  fmi3Instance instance_ = nullptr;
  double start_ = 0.0;
  std::optional<double> stop_;
  double tolerance_ = 1e-6;
  bool initialised_ = false;
  bool fatal_ = false;
};

std::vector<std::byte> fmi3_me_instance::save() {
  return save_state(fn_, instance_, &fmi3_me_instance::check_status, this);
}

void fmi3_me_instance::restore(std::span<const std::byte> bytes) {
  restore_state(fn_, instance_, bytes, &fmi3_me_instance::check_status, this);
  // the copies of settable arrays must follow the restored state
  if (initialised_) values_.refresh(instance_);
}

}  // namespace

std::unique_ptr<cosim::detail::me_instance> instantiate_model_exchange(
    std::shared_ptr<const void> owner, const binary& bin, const std::string& name,
    const instance_options& options) {
  return std::make_unique<fmi3_me_instance>(std::move(owner), bin, name, options);
}

}  // namespace stride::cosim::fmi3
