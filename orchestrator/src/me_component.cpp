#include "me_component.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdlib>

#include "cvode_solver.hpp"
#include "euler_solver.hpp"
#include "fmi2_log.hpp"
#include "required_symbol.hpp"
#include "state_bytes.hpp"
#include "stride/common/text.hpp"
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

constexpr std::uint64_t state_magic = 0x3145444952545341;  // "ASTRIDE1" (little-endian)
constexpr int max_event_iterations = 1000;
constexpr int max_steps_per_communication_step = 100000;

std::string seconds(double t) {
  return text::format_double(t) + " s";
}

class me_component final : public component, private detail::ode_system {
 public:
  me_component(std::shared_ptr<fmu> owner, std::string name, const instance_options& options)
      : owner_(std::move(owner)),
        md_(owner_->model_description()),
        name_(std::move(name)),
        options_(options.model_exchange.value_or(model_exchange_options{})),
        log_(options.log ? options.log : stderr_log_sink()),
        callbacks_{&me_component::logger, std::calloc, std::free, nullptr, this} {
    if (!md_.model_exchange) {
      throw component_error("component '" + name_ + "': " + owner_->file().string() +
                            " has no <ModelExchange> interface (kind=\"model-exchange\")");
    }
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
    if (options_.solver == model_exchange_options::solver_kind::euler && !options_.max_step) {
      throw component_error("component '" + name_ +
                            "': solver \"euler\" needs max_step (its fixed step)");
    }
    x_.resize(md_.derivatives.size());
    instance_ = fn_.fmi2Instantiate(name_.c_str(), fmi2ModelExchange, md_.guid.c_str(),
                                    owner_->resource_uri().c_str(), &callbacks_, fmi2False,
                                    options.logging_on ? fmi2True : fmi2False);
    if (instance_ == nullptr) {
      throw component_error("component '" + name_ + "': fmi2Instantiate (Model Exchange) of " +
                            owner_->file().string() + " failed (GUID " + md_.guid + ")");
    }
  }

  ~me_component() override {
    if (instance_ == nullptr || fatal_) return;
    if (initialised_ && !failed_ && !terminate_called_) fn_.fmi2Terminate(instance_);
    fn_.fmi2FreeInstance(instance_);
  }

  const std::string& name() const noexcept override {
    return name_;
  }
  const stride::cosim::model_description& model_description() const noexcept override {
    return md_;
  }

  void setup(time_point start, std::optional<time_point> stop) override {
    rtol_ = options_.rtol.value_or(md_.default_experiment.tolerance.value_or(1e-6));
    check("fmi2SetupExperiment",
          fn_.fmi2SetupExperiment(instance_, fmi2True, rtol_, to_seconds(start),
                                  stop ? fmi2True : fmi2False, stop ? to_seconds(*stop) : 0.0));
  }
  void enter_initialization() override {
    check("fmi2EnterInitializationMode", fn_.fmi2EnterInitializationMode(instance_));
  }
  // FMI 2.0 leaves initialization in event mode: iterate, then continuous-time mode
  void exit_initialization() override {
    check("fmi2ExitInitializationMode", fn_.fmi2ExitInitializationMode(instance_));
    initialised_ = true;
    iterate_events();
    if (!terminated_)
      check("fmi2EnterContinuousTimeMode", fn_.fmi2EnterContinuousTimeMode(instance_));
    make_solver();
  }
  void terminate() override {
    if (!initialised_ || failed_ || terminate_called_) return;
    terminate_called_ = true;
    check("fmi2Terminate", fn_.fmi2Terminate(instance_));
  }

  void set_values(const variable_refs& refs, const value_block& values) override;
  void get_values(const variable_refs& refs, value_block& values) override;

  void expose(const variable_refs& inputs, const variable_refs& outputs) override {
    inputs_ = inputs;
    outputs_ = outputs;
  }

  step_result step(time_point t, duration dt, const value_block& inputs,
                   value_block& outputs) override;

  std::vector<std::byte> save_state() override;
  void restore_state(std::span<const std::byte> bytes) override;

 private:
  // ode_system: the FMU's equations at (t, x)
  std::size_t state_count() const noexcept override {
    return x_.size();
  }
  std::size_t indicator_count() const noexcept override {
    return md_.number_of_event_indicators;
  }
  void derivatives(double t, std::span<const double> x, std::span<double> dx) override;
  void indicators(double t, std::span<const double> x, std::span<double> z) override;

  void make_solver();
  void iterate_events();
  void handle_event(double t);
  bool completed_step();
  void read_states();
  [[noreturn]] void fail_at(double t, const std::string& reason);
  void require_state_support() const;
  void check(const char* function, fmi2Status s);
  void check_at(double t, const char* function, fmi2Status s);
  static void logger(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status,
                     fmi2String category, fmi2String message, ...);

  std::shared_ptr<fmu> owner_;
  const stride::cosim::model_description& md_;
  std::string name_;
  model_exchange_options options_;
  log_sink log_;
  fmi2CallbackFunctions callbacks_;
  me_functions fn_;
  fmi2Component instance_ = nullptr;
  std::unique_ptr<detail::ode_solver> solver_;
  double rtol_ = 1e-6;
  std::vector<double> x_;
  bool next_event_defined_ = false;
  double next_event_time_ = 0;
  bool initialised_ = false;
  bool terminated_ = false;  // the FMU asked to end the simulation
  bool terminate_called_ = false;
  bool failed_ = false;
  bool fatal_ = false;
  variable_refs inputs_;
  variable_refs outputs_;
  std::vector<fmi2Boolean> booleans_;
  std::vector<fmi2String> strings_;
};

void me_component::make_solver() {
  read_states();
  detail::ode_system& system = *this;
  if (options_.solver == model_exchange_options::solver_kind::euler) {
    solver_ = std::make_unique<detail::euler_solver>(system, *options_.max_step);
    return;
  }
  detail::cvode_settings s;
  s.method = options_.method;
  s.rtol = rtol_;
  s.max_step = options_.max_step;
  // the absolute tolerance is relative to each state's magnitude as the FMU declares it
  std::vector<double> nominal(x_.size(), 1.0);
  if (!x_.empty()) {
    check("fmi2GetNominalsOfContinuousStates",
          fn_.fmi2GetNominalsOfContinuousStates(instance_, nominal.data(), nominal.size()));
  }
  const double atol = options_.atol.value_or(rtol_);
  for (double n : nominal) s.atol.push_back(atol * (std::isfinite(n) && n > 0 ? n : 1.0));
  solver_ = std::make_unique<detail::cvode_solver>(system, s);
}

void me_component::read_states() {
  if (x_.empty()) return;
  check("fmi2GetContinuousStates", fn_.fmi2GetContinuousStates(instance_, x_.data(), x_.size()));
}

// Event iteration (FMI 2.0, 3.2.2): new discrete states until the FMU needs no more passes.
void me_component::iterate_events() {
  fmi2EventInfo info{};
  info.newDiscreteStatesNeeded = fmi2True;
  int passes = 0;
  while (info.newDiscreteStatesNeeded == fmi2True) {
    if (++passes > max_event_iterations) {
      failed_ = true;
      throw component_error("component '" + name_ + "': event iteration did not settle after " +
                            std::to_string(max_event_iterations) + " passes");
    }
    info = {};
    check("fmi2NewDiscreteStates", fn_.fmi2NewDiscreteStates(instance_, &info));
    if (info.terminateSimulation == fmi2True) {
      terminated_ = true;
      break;
    }
  }
  next_event_defined_ = info.nextEventTimeDefined == fmi2True;
  next_event_time_ = info.nextEventTime;
}

void me_component::handle_event(double t) {
  check("fmi2EnterEventMode", fn_.fmi2EnterEventMode(instance_));
  iterate_events();
  if (terminated_) return;
  check("fmi2EnterContinuousTimeMode", fn_.fmi2EnterContinuousTimeMode(instance_));
  read_states();
  solver_->reset(t, x_);
}

// fmi2CompletedIntegratorStep: whether the FMU asks for a step event.
bool me_component::completed_step() {
  if (md_.model_exchange->completed_integrator_step_not_needed) return false;
  fmi2Boolean enter = fmi2False;
  fmi2Boolean terminate = fmi2False;
  check("fmi2CompletedIntegratorStep",
        fn_.fmi2CompletedIntegratorStep(instance_, fmi2True, &enter, &terminate));
  if (terminate == fmi2True) terminated_ = true;
  return enter == fmi2True;
}

step_result me_component::step(time_point t, duration dt, const value_block& inputs,
                               value_block& outputs) {
  if (terminated_) return step_result::terminate;
  const double t0 = to_seconds(t);
  const double target = to_seconds(t + dt);
  check("fmi2SetTime", fn_.fmi2SetTime(instance_, t0));
  // inputs change only here: an event, so discrete inputs may change too
  if (!inputs_.empty()) {
    check("fmi2EnterEventMode", fn_.fmi2EnterEventMode(instance_));
    set_values(inputs_, inputs);
    iterate_events();
    if (terminated_) return step_result::terminate;
    check("fmi2EnterContinuousTimeMode", fn_.fmi2EnterContinuousTimeMode(instance_));
  }
  // a fresh start at every communication point: a resumed run continues identically
  read_states();
  try {
    solver_->reset(t0, x_);
    double now = t0;
    // closer than this is the same instant: CVODE cannot step across it
    const double instant = 1e-13 * std::max(1.0, std::abs(target));
    for (int steps = 0; target - now > instant; ++steps) {
      if (steps == max_steps_per_communication_step) {
        throw detail::solver_failure("more than " + std::to_string(steps) +
                                     " internal steps in one communication step (too much work: "
                                     "the system may be stiff for this method, or the tolerances "
                                     "too tight)");
      }
      if (next_event_defined_ && next_event_time_ - now <= instant) {
        handle_event(now);
        if (terminated_) return step_result::terminate;
        continue;
      }
      const double stop =
          next_event_defined_ && next_event_time_ < target ? next_event_time_ : target;
      const detail::ode_step s = solver_->step(stop, x_);
      now = s.t;
      check("fmi2SetTime", fn_.fmi2SetTime(instance_, now));
      if (!x_.empty()) {
        check("fmi2SetContinuousStates",
              fn_.fmi2SetContinuousStates(instance_, x_.data(), x_.size()));
      }
      const bool step_event = completed_step();
      if (terminated_) return step_result::terminate;
      const bool time_event = next_event_defined_ && now >= next_event_time_;
      if (step_event || time_event || s.root) {
        handle_event(now);
        if (terminated_) return step_result::terminate;
      }
    }
    check("fmi2SetTime", fn_.fmi2SetTime(instance_, target));
  } catch (const detail::solver_failure& e) {
    failed_ = true;
    fail_at(t0, e.what());
  }
  get_values(outputs_, outputs);
  return step_result::complete;
}

void me_component::derivatives(double t, std::span<const double> x, std::span<double> dx) {
  check_at(t, "fmi2SetTime", fn_.fmi2SetTime(instance_, t));
  check_at(t, "fmi2SetContinuousStates",
           fn_.fmi2SetContinuousStates(instance_, x.data(), x.size()));
  check_at(t, "fmi2GetDerivatives", fn_.fmi2GetDerivatives(instance_, dx.data(), dx.size()));
  for (std::size_t i = 0; i < dx.size(); ++i) {
    if (std::isnan(dx[i])) {
      fail_at(t, "fmi2GetDerivatives gave " + md_.variables[md_.derivatives[i]].name +
                     " = NaN (non-finite values are not passed on)");
    }
  }
}

void me_component::indicators(double t, std::span<const double> x, std::span<double> z) {
  check_at(t, "fmi2SetTime", fn_.fmi2SetTime(instance_, t));
  if (!x.empty()) {
    check_at(t, "fmi2SetContinuousStates",
             fn_.fmi2SetContinuousStates(instance_, x.data(), x.size()));
  }
  check_at(t, "fmi2GetEventIndicators", fn_.fmi2GetEventIndicators(instance_, z.data(), z.size()));
}

void me_component::fail_at(double t, const std::string& reason) {
  failed_ = true;
  throw component_error("component '" + name_ + "' at t = " + seconds(t) + ": " + reason);
}

// inside the integration: the time of the failing call is named
void me_component::check_at(double t, const char* function, fmi2Status s) {
  if (s == fmi2OK || s == fmi2Warning) return;
  if (s == fmi2Fatal) fatal_ = true;
  fail_at(t, std::string(function) + " returned " +
                 std::string(fmi2::to_string(static_cast<fmi2::status>(s))));
}

void me_component::check(const char* function, fmi2Status s) {
  if (s == fmi2OK || s == fmi2Warning) return;
  if (s == fmi2Fatal) fatal_ = true;
  failed_ = true;
  throw component_error("component '" + name_ + "': " + function + " returned " +
                        std::string(fmi2::to_string(static_cast<fmi2::status>(s))));
}

void me_component::set_values(const variable_refs& refs, const value_block& values) {
  if (!refs.reals.empty()) {
    check("fmi2SetReal",
          fn_.fmi2SetReal(instance_, refs.reals.data(), refs.reals.size(), values.reals.data()));
  }
  if (!refs.integers.empty()) {
    check("fmi2SetInteger", fn_.fmi2SetInteger(instance_, refs.integers.data(),
                                               refs.integers.size(), values.integers.data()));
  }
  if (!refs.booleans.empty()) {
    booleans_.resize(refs.booleans.size());
    for (std::size_t i = 0; i < booleans_.size(); ++i) {
      booleans_[i] = values.booleans[i] ? fmi2True : fmi2False;
    }
    check("fmi2SetBoolean", fn_.fmi2SetBoolean(instance_, refs.booleans.data(),
                                               refs.booleans.size(), booleans_.data()));
  }
  if (!refs.strings.empty()) {
    strings_.resize(refs.strings.size());
    for (std::size_t i = 0; i < strings_.size(); ++i) strings_[i] = values.strings[i].c_str();
    check("fmi2SetString",
          fn_.fmi2SetString(instance_, refs.strings.data(), refs.strings.size(), strings_.data()));
  }
}

void me_component::get_values(const variable_refs& refs, value_block& values) {
  values.resize_for(refs);
  if (!refs.reals.empty()) {
    check("fmi2GetReal",
          fn_.fmi2GetReal(instance_, refs.reals.data(), refs.reals.size(), values.reals.data()));
    for (std::size_t i = 0; i < refs.reals.size(); ++i) {
      if (std::isfinite(values.reals[i])) continue;
      failed_ = true;
      throw component_error("component '" + name_ + "': fmi2GetReal gave value reference " +
                            std::to_string(refs.reals[i]) +
                            " a non-finite value (non-finite values are not passed on)");
    }
  }
  if (!refs.integers.empty()) {
    check("fmi2GetInteger", fn_.fmi2GetInteger(instance_, refs.integers.data(),
                                               refs.integers.size(), values.integers.data()));
  }
  if (!refs.booleans.empty()) {
    booleans_.resize(refs.booleans.size());
    check("fmi2GetBoolean", fn_.fmi2GetBoolean(instance_, refs.booleans.data(),
                                               refs.booleans.size(), booleans_.data()));
    for (std::size_t i = 0; i < booleans_.size(); ++i) {
      values.booleans[i] = booleans_[i] != fmi2False;
    }
  }
  if (!refs.strings.empty()) {
    strings_.resize(refs.strings.size());
    check("fmi2GetString",
          fn_.fmi2GetString(instance_, refs.strings.data(), refs.strings.size(), strings_.data()));
    for (std::size_t i = 0; i < strings_.size(); ++i) {
      values.strings[i] = strings_[i] ? strings_[i] : "";
    }
  }
}

// The image: the runner's own state (the pending time event, termination), then the FMU's.
std::vector<std::byte> me_component::save_state() {
  require_state_support();
  fmi2FMUstate state = nullptr;
  check("fmi2GetFMUstate", fn_.fmi2GetFMUstate(instance_, &state));
  std::vector<std::byte> fmu_bytes;
  try {
    size_t size = 0;
    check("fmi2SerializedFMUstateSize", fn_.fmi2SerializedFMUstateSize(instance_, state, &size));
    fmu_bytes.resize(size);
    check("fmi2SerializeFMUstate",
          fn_.fmi2SerializeFMUstate(instance_, state, reinterpret_cast<fmi2Byte*>(fmu_bytes.data()),
                                    size));
  } catch (...) {
    fn_.fmi2FreeFMUstate(instance_, &state);
    throw;
  }
  check("fmi2FreeFMUstate", fn_.fmi2FreeFMUstate(instance_, &state));
  detail::byte_writer w;
  w.put(state_magic);
  w.put(static_cast<std::uint8_t>(next_event_defined_ ? 1 : 0));
  w.put(next_event_time_);
  w.put(static_cast<std::uint8_t>(terminated_ ? 1 : 0));
  w.put_bytes(fmu_bytes);
  return w.take();
}

void me_component::restore_state(std::span<const std::byte> bytes) {
  require_state_support();
  detail::byte_reader r(bytes, "component '" + name_ + "': saved Model Exchange state");
  if (r.get<std::uint64_t>() != state_magic) {
    throw validation_error("component '" + name_ +
                           "': the saved state is not a Model Exchange runner's");
  }
  const bool defined = r.get<std::uint8_t>() != 0;
  const double next = r.get<double>();
  const bool terminated = r.get<std::uint8_t>() != 0;
  const auto fmu_bytes = r.get_bytes();
  fmi2FMUstate state = nullptr;
  check("fmi2DeSerializeFMUstate",
        fn_.fmi2DeSerializeFMUstate(instance_, reinterpret_cast<const fmi2Byte*>(fmu_bytes.data()),
                                    fmu_bytes.size(), &state));
  const fmi2Status set = fn_.fmi2SetFMUstate(instance_, state);
  fn_.fmi2FreeFMUstate(instance_, &state);
  check("fmi2SetFMUstate", set);
  next_event_defined_ = defined;
  next_event_time_ = next;
  terminated_ = terminated;
}

void me_component::require_state_support() const {
  const auto& me = *md_.model_exchange;
  if (!me.can_get_and_set_fmu_state || !me.can_serialize_fmu_state) {
    throw component_error("component '" + name_ + "': " + owner_->file().string() +
                          " cannot save its state (canGetAndSetFMUstate and "
                          "canSerializeFMUstate of <ModelExchange> are not both true)");
  }
}

void me_component::logger(fmi2ComponentEnvironment env, fmi2String /*instance*/, fmi2Status status,
                          fmi2String category, fmi2String message, ...) {
  auto* self = static_cast<me_component*>(env);
  if (self == nullptr) return;
  std::va_list args;
  va_start(args, message);
  detail::forward_fmi2_log(self->log_, self->name_, status, category, message, args);
  va_end(args);
}

}  // namespace

std::unique_ptr<component> instantiate_model_exchange(std::shared_ptr<fmu> owner,
                                                      const std::string& instance_name,
                                                      const instance_options& options) {
  return std::make_unique<me_component>(std::move(owner), instance_name, options);
}

}  // namespace stride::cosim
