#include "me_component.hpp"

#include <algorithm>
#include <cmath>

#include "cvode_solver.hpp"
#include "euler_solver.hpp"
#include "state_bytes.hpp"
#include "stride/common/text.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim {

namespace {

constexpr std::uint64_t state_magic = 0x3145444952545341;  // "ASTRIDE1" (little-endian)
constexpr int max_event_iterations = 1000;
constexpr int max_steps_per_communication_step = 100000;

std::string seconds(double t) {
  return text::format_double(t) + " s";
}

class me_component final : public component, private detail::ode_system {
 public:
  me_component(std::unique_ptr<detail::me_instance> instance, std::string name,
               const instance_options& options)
      : fmu_(std::move(instance)),
        md_(fmu_->description()),
        name_(std::move(name)),
        options_(options.model_exchange.value_or(model_exchange_options{})) {
    if (options_.solver == model_exchange_options::solver_kind::euler && !options_.max_step) {
      throw component_error("component '" + name_ +
                            "': solver \"euler\" needs max_step (its fixed step)");
    }
    x_.resize(md_.derivatives.size());
  }

  ~me_component() override {
    if (!initialised_ || failed_ || terminate_called_) return;
    try {
      fmu_->terminate();
    } catch (const std::exception&) {
      // the run is over; the FMU's own log said why
    }
  }

  const std::string& name() const noexcept override { return name_; }
  const stride::cosim::model_description& model_description() const noexcept override {
    return md_;
  }

  void setup(time_point start, std::optional<time_point> stop) override {
    rtol_ = options_.rtol.value_or(md_.default_experiment.tolerance.value_or(1e-6));
    guarded([&] {
      fmu_->setup(to_seconds(start), stop ? std::optional(to_seconds(*stop)) : std::nullopt, rtol_);
    });
  }
  void enter_initialization() override {
    guarded([&] { fmu_->enter_initialization(); });
  }
  // initialization ends in event mode: iterate, then continuous-time mode
  void exit_initialization() override {
    guarded([&] {
      fmu_->exit_initialization();
      initialised_ = true;
      iterate_events();
      if (!terminated_) fmu_->enter_continuous_time_mode();
      make_solver();
    });
  }
  void terminate() override {
    if (!initialised_ || failed_ || terminate_called_) return;
    terminate_called_ = true;
    guarded([&] { fmu_->terminate(); });
  }

  void set_values(const variable_refs& refs, const value_block& values) override {
    guarded([&] { fmu_->set_values(refs, values); });
  }
  void get_values(const variable_refs& refs, value_block& values) override {
    guarded([&] { fmu_->get_values(refs, values); });
  }

  void expose(const variable_refs& inputs, const variable_refs& outputs) override {
    inputs_ = inputs;
    outputs_ = outputs;
  }

  step_result step(time_point t, duration dt, const value_block& inputs,
                   value_block& outputs) override {
    if (terminated_) return step_result::terminate;
    const step_result r = guarded([&] { return advance(t, dt, inputs); });
    if (r == step_result::complete) get_values(outputs_, outputs);
    return r;
  }

  std::vector<std::byte> save_state() override;
  void restore_state(std::span<const std::byte> bytes) override;

 private:
  // ode_system: the FMU's equations at (t, x)
  std::size_t state_count() const noexcept override { return x_.size(); }
  std::size_t indicator_count() const noexcept override { return md_.number_of_event_indicators; }
  void derivatives(double t, std::span<const double> x, std::span<double> dx) override;
  void indicators(double t, std::span<const double> x, std::span<double> z) override;

  step_result advance(time_point t, duration dt, const value_block& inputs);
  step_result integrate(double t0, double target);
  void make_solver();
  void iterate_events();
  void handle_event(double t);
  bool completed_step();
  void read_states();
  void require_state_support() const;

  // Runs `f`; a refused call becomes a component_error naming this component and, inside a
  // step, the time of the call.
  template <class F>
  auto guarded(F&& f) -> decltype(f()) {
    try {
      return f();
    } catch (const detail::fmu_call_failure& e) {
      failed_ = true;
      const std::string when = at_ ? " at t = " + seconds(*at_) : "";
      at_.reset();
      throw component_error("component '" + name_ + "'" + when + ": " + e.what());
    } catch (...) {
      failed_ = true;
      at_.reset();
      throw;
    }
  }

  std::unique_ptr<detail::me_instance> fmu_;
  const stride::cosim::model_description& md_;
  std::string name_;
  model_exchange_options options_;
  std::unique_ptr<detail::ode_solver> solver_;
  double rtol_ = 1e-6;
  std::vector<double> x_;
  std::optional<double> at_;  // the time of the FMU call in progress inside a step
  bool next_event_defined_ = false;
  double next_event_time_ = 0;
  bool initialised_ = false;
  bool terminated_ = false;  // the FMU asked to end the simulation
  bool terminate_called_ = false;
  bool failed_ = false;
  variable_refs inputs_;
  variable_refs outputs_;
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
  if (!x_.empty()) fmu_->get_nominals(nominal);
  const double atol = options_.atol.value_or(rtol_);
  for (double n : nominal) s.atol.push_back(atol * (std::isfinite(n) && n > 0 ? n : 1.0));
  solver_ = std::make_unique<detail::cvode_solver>(system, s);
}

void me_component::read_states() {
  if (!x_.empty()) fmu_->get_states(x_);
}

// Event iteration (FMI 2.0 §3.2.2, FMI 3.0 §3.2.5): new discrete states until the FMU needs
// no more passes.
void me_component::iterate_events() {
  detail::discrete_update u;
  u.again = true;
  for (int passes = 1; u.again; ++passes) {
    if (passes > max_event_iterations) {
      throw component_error("component '" + name_ + "': event iteration did not settle after " +
                            std::to_string(max_event_iterations) + " passes");
    }
    u = fmu_->update_discrete_states();
    if (u.terminate) {
      terminated_ = true;
      break;
    }
  }
  next_event_defined_ = u.next_time_defined;
  next_event_time_ = u.next_time;
}

void me_component::handle_event(double t) {
  fmu_->enter_event_mode();
  iterate_events();
  if (terminated_) return;
  fmu_->enter_continuous_time_mode();
  read_states();
  solver_->reset(t, x_);
}

// whether the FMU asks for a step event after an accepted integrator step
bool me_component::completed_step() {
  if (!fmu_->needs_completed_integrator_step()) return false;
  const detail::integrator_step_answer a = fmu_->completed_integrator_step();
  if (a.terminate) terminated_ = true;
  return a.enter_event_mode;
}

step_result me_component::advance(time_point t, duration dt, const value_block& inputs) {
  const double t0 = to_seconds(t);
  at_ = t0;
  fmu_->set_time(t0);
  // inputs change only here: an event, so discrete inputs may change too
  if (!inputs_.empty()) {
    fmu_->enter_event_mode();
    fmu_->set_values(inputs_, inputs);
    iterate_events();
    if (terminated_) return step_result::terminate;
    fmu_->enter_continuous_time_mode();
  }
  // a fresh start at every communication point: a resumed run continues identically
  read_states();
  step_result r = step_result::complete;
  try {
    r = integrate(t0, to_seconds(t + dt));
  } catch (const detail::solver_failure& e) {
    failed_ = true;
    at_.reset();
    throw component_error("component '" + name_ + "' at t = " + seconds(t0) + ": " + e.what());
  }
  at_.reset();
  return r;
}

step_result me_component::integrate(double t0, double target) {
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
    at_ = now;
    fmu_->set_time(now);
    if (!x_.empty()) fmu_->set_states(x_);
    const bool step_event = completed_step();
    if (terminated_) return step_result::terminate;
    const bool time_event = next_event_defined_ && now >= next_event_time_;
    if (step_event || time_event || s.root) {
      handle_event(now);
      if (terminated_) return step_result::terminate;
    }
  }
  at_ = target;
  fmu_->set_time(target);
  return step_result::complete;
}

void me_component::derivatives(double t, std::span<const double> x, std::span<double> dx) {
  at_ = t;
  fmu_->set_time(t);
  fmu_->set_states(x);
  fmu_->get_derivatives(dx);
  for (std::size_t i = 0; i < dx.size(); ++i) {
    if (!std::isnan(dx[i])) continue;
    throw detail::fmu_call_failure(std::string(fmu_->derivatives_function()) + " gave " +
                                   md_.variables[md_.derivatives[i]].name +
                                   " = NaN (non-finite values are not passed on)");
  }
}

void me_component::indicators(double t, std::span<const double> x, std::span<double> z) {
  at_ = t;
  fmu_->set_time(t);
  if (!x.empty()) fmu_->set_states(x);
  fmu_->get_indicators(z);
}

// The image: the runner's own state (the pending time event, termination), then the FMU's.
std::vector<std::byte> me_component::save_state() {
  require_state_support();
  const std::vector<std::byte> fmu_bytes = guarded([&] { return fmu_->save(); });
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
  guarded([&] { fmu_->restore(fmu_bytes); });
  next_event_defined_ = defined;
  next_event_time_ = next;
  terminated_ = terminated;
}

void me_component::require_state_support() const {
  const auto& me = *md_.model_exchange;
  if (!me.can_get_and_set_fmu_state || !me.can_serialize_fmu_state) {
    throw component_error("component '" + name_ + "': " + fmu_->file().string() +
                          " cannot save its state (canGetAndSetFMUstate and "
                          "canSerializeFMUstate of <ModelExchange> are not both true)");
  }
}

}  // namespace

namespace detail {

void require_finite_reals(const variable_refs& refs, const value_block& values,
                          const char* function) {
  for (std::size_t i = 0; i < refs.reals.size(); ++i) {
    if (std::isfinite(values.reals[i])) continue;
    throw fmu_call_failure(std::string(function) + " gave value reference " +
                           std::to_string(refs.reals[i]) +
                           " a non-finite value (non-finite values are not passed on)");
  }
}

}  // namespace detail

std::unique_ptr<component> run_model_exchange(std::unique_ptr<detail::me_instance> instance,
                                              const std::string& instance_name,
                                              const instance_options& options) {
  return std::make_unique<me_component>(std::move(instance), instance_name, options);
}

}  // namespace stride::cosim
