// One instance of an FMI 3.0 Co-Simulation FMU as a Stride component: the plain call sequence
// of docs/fmi3-rules.md §2 (no event mode, no early return, no intermediate update).
#include <cmath>
#include <cstdint>

#include "fmi3_fmu.hpp"
#include "fmi3_values.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim::fmi3 {

namespace {

class fmi3_component final : public component {
 public:
  fmi3_component(std::shared_ptr<const void> owner, const binary& bin, std::string name,
                 const instance_options& options)
      : owner_(std::move(owner)),
        bin_(bin),
        fn_(bin.fn),
        name_(std::move(name)),
        log_(options.log ? options.log : stderr_log_sink()),
        values_(bin, name_, &fmi3_component::check_status, this) {
    // a native path with a trailing separator (2.0 used a file:// URI)
    const std::string resources = bin_.resources.empty() ? "" : bin_.resources.string() + "/";
    instance_ = fn_.fmi3InstantiateCoSimulation(
        name_.c_str(), bin_.description.scalar.guid.c_str(),
        resources.empty() ? nullptr : resources.c_str(), /*visible*/ fmi3False,
        options.logging_on ? fmi3True : fmi3False, /*eventModeUsed*/ fmi3False,
        /*earlyReturnAllowed*/ fmi3False, nullptr, 0, this, &fmi3_component::logger, nullptr);
    if (instance_ == nullptr) {
      throw component_error("component '" + name_ + "': fmi3InstantiateCoSimulation of " +
                            bin_.file.string() + " failed (instantiationToken " +
                            bin_.description.scalar.guid + "; see the FMU's log messages above)");
    }
  }

  ~fmi3_component() override {
    if (instance_ == nullptr || fatal_) return;
    if (may_terminate()) fn_.fmi3Terminate(instance_);
    fn_.fmi3FreeInstance(instance_);
  }

  const std::string& name() const noexcept override { return name_; }
  const stride::cosim::model_description& model_description() const noexcept override {
    return bin_.description.scalar;
  }

  // FMI 3 has no fmi3SetupExperiment: the times go to fmi3EnterInitializationMode
  void setup(time_point start, std::optional<time_point> stop) override {
    start_ = to_seconds(start);
    stop_ = stop ? std::optional<double>(to_seconds(*stop)) : std::nullopt;
  }
  void enter_initialization() override {
    check("fmi3EnterInitializationMode",
          fn_.fmi3EnterInitializationMode(instance_, fmi3False, 0.0, start_,
                                          stop_ ? fmi3True : fmi3False, stop_.value_or(0.0)));
  }
  void exit_initialization() override {
    check("fmi3ExitInitializationMode", fn_.fmi3ExitInitializationMode(instance_));
    stepping_ = true;
  }
  void terminate() override {
    if (!may_terminate()) return;
    terminated_ = true;
    check("fmi3Terminate", fn_.fmi3Terminate(instance_));
  }

  void set_values(const variable_refs& refs, const value_block& values) override {
    values_.set(instance_, refs, values);
  }
  void get_values(const variable_refs& refs, value_block& values) override {
    values_.get(instance_, refs, values);
  }
  void expose(const variable_refs& inputs, const variable_refs& outputs) override {
    inputs_ = inputs;
    outputs_ = outputs;
  }

  step_result step(time_point t, duration dt, const value_block& inputs,
                   value_block& outputs) override {
    values_.set(instance_, inputs_, inputs);
    fmi3Boolean event = fmi3False;
    fmi3Boolean stop = fmi3False;
    fmi3Boolean early = fmi3False;
    fmi3Float64 reached = 0.0;
    const double now = to_seconds(t);
    const fmi3Status s =
        fn_.fmi3DoStep(instance_, now, to_seconds(dt), fmi3False, &event, &stop, &early, &reached);
    if ((s == fmi3OK || s == fmi3Warning || s == fmi3Discard) && stop) {
      // as fmi2Terminated in 2.0: the run ends here, and the log says who ended it and when
      log_(log_level::warning, name_, "",
           "fmi3DoStep at t = " + std::to_string(now) + " set terminateSimulation");
      return step_result::terminate;
    }
    if (s == fmi3Discard) {
      failed_ = true;
      throw component_error("component '" + name_ + "': fmi3DoStep at t = " + std::to_string(now) +
                            " returned fmi3Discard without requesting termination "
                            "(fixed-step masters cannot retry a step)");
    }
    check("fmi3DoStep", s);
    // without event mode and early return neither may be reported: the step is not trustworthy
    if (event || early) {
      failed_ = true;
      throw component_error("component '" + name_ + "': fmi3DoStep at t = " + std::to_string(now) +
                            " reported " + (event ? "eventHandlingNeeded" : "earlyReturn") +
                            ", which Stride did not allow (eventModeUsed and earlyReturnAllowed "
                            "are false)");
    }
    values_.get(instance_, outputs_, outputs);
    return step_result::complete;
  }

  std::vector<std::byte> save_state() override {
    require_state_support();
    return fmi3::save_state(fn_, instance_, &fmi3_component::check_status, this);
  }

  void restore_state(std::span<const std::byte> bytes) override {
    require_state_support();
    fmi3::restore_state(fn_, instance_, bytes, &fmi3_component::check_status, this);
    // the copies of settable arrays must follow the restored state
    if (stepping_) values_.refresh(instance_);
  }

 private:
  void require_state_support() const {
    const auto& cs = *bin_.description.scalar.co_simulation;
    if (!cs.can_get_and_set_fmu_state || !cs.can_serialize_fmu_state) {
      throw component_error("component '" + name_ + "': " + bin_.file.string() +
                            " cannot save its state (canGetAndSetFMUState and "
                            "canSerializeFMUState are not both true)");
    }
  }

  static void check_status(void* self, const char* function, fmi3Status s) {
    static_cast<fmi3_component*>(self)->check(function, s);
  }

  void check(const char* function, fmi3Status s) {
    if (s == fmi3OK || s == fmi3Warning) return;
    if (s == fmi3Fatal) fatal_ = true;
    if (s == fmi3Error || s == fmi3Discard) failed_ = true;
    throw component_error("component '" + name_ + "': " + function + " returned " + status_name(s));
  }

  static void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                     fmi3String message) {
    auto* self = static_cast<fmi3_component*>(env);
    if (self != nullptr) forward_log(self->log_, self->name_, status, category, message);
  }

  bool may_terminate() const { return stepping_ && !terminated_ && !failed_ && !fatal_; }

  std::shared_ptr<const void> owner_;
  const binary& bin_;
  const functions& fn_;
  std::string name_;
  log_sink log_;
  value_io values_;
  fmi3Instance instance_ = nullptr;
  double start_ = 0.0;
  std::optional<double> stop_;
  bool stepping_ = false;
  bool terminated_ = false;
  bool failed_ = false;
  bool fatal_ = false;
  variable_refs inputs_;
  variable_refs outputs_;
};

}  // namespace

std::unique_ptr<component> instantiate(std::shared_ptr<const void> owner, const binary& bin,
                                       const std::string& name, const instance_options& options) {
  return std::make_unique<fmi3_component>(std::move(owner), bin, name, options);
}

}  // namespace stride::cosim::fmi3
