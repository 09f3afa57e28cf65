// A component for algorithm tests without FMUs (after libcosim's mock_slave): variables are
// declared in code, outputs are computed by lambdas from the inputs, and every call is logged.
#ifndef STRIDE_TESTS_ORCHESTRATOR_MOCK_COMPONENT_HPP
#define STRIDE_TESTS_ORCHESTRATOR_MOCK_COMPONENT_HPP

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "stride/cosim/component.hpp"

namespace stride::cosim::test {

/// Call log shared by several mocks, to check the order of steps across components.
struct call_log {
  std::vector<std::string> entries;  ///< "name:do_step@<ticks>" etc.
};

/// A mock with any number of variables; values live in maps keyed by value reference.
class mock_component : public component {
 public:
  /// Computes outputs after a step or a set: `self` gives access to values.
  using update_fn = std::function<void(mock_component& self)>;
  using step_fn = std::function<step_result(mock_component& self, time_point t, duration dt)>;

  mock_component(std::string name, std::shared_ptr<call_log> log = {})
      : name_(std::move(name)), log_(std::move(log)) {
    md_.model_name = name_;
    md_.guid = "{mock-" + name_ + "}";
  }

  /// Declares a variable; returns its value reference. `feedthrough`: for outputs, the names of
  /// inputs it depends on directly (nullopt = all, the FMI default).
  value_reference add(
      const std::string& var, variable_type type, causality c,
      std::optional<std::vector<std::string>> depends_on = std::vector<std::string>{},
      std::string unit = {}) {
    variable_description v;
    v.name = var;
    v.reference = static_cast<value_reference>(md_.variables.size());
    v.type = type;
    v.causality = c;
    v.variability = c == causality::parameter     ? variability::fixed
                    : type == variable_type::real ? variability::continuous
                                                  : variability::discrete;
    v.unit = std::move(unit);
    md_.variables.push_back(v);
    if (c == causality::output) {
      output_dependency dep;
      dep.output = md_.variables.size() - 1;
      if (depends_on) {
        dep.dependencies.emplace();
        for (const auto& d : *depends_on) dep.dependencies->push_back(*md_.index_of(d));
      }
      md_.outputs.push_back(dep);
    }
    return v.reference;
  }
  value_reference real(const std::string& var, causality c,
                       std::optional<std::vector<std::string>> deps = std::vector<std::string>{}) {
    return add(var, variable_type::real, c, std::move(deps));
  }

  update_fn on_update;  ///< called after every set (feedthrough) and after every step
  step_fn on_step;      ///< default: complete; called before on_update

  double& r(const std::string& var) { return reals_[ref(var)]; }
  int& i(const std::string& var) { return ints_[ref(var)]; }
  bool& b(const std::string& var) { return bools_[ref(var)]; }
  std::string& s(const std::string& var) { return strings_[ref(var)]; }

  std::vector<time_point> step_times;
  std::vector<duration> step_sizes;
  std::optional<time_point> setup_start;
  std::optional<time_point> setup_stop;
  bool terminated = false;

  const std::string& name() const noexcept override { return name_; }
  const stride::cosim::model_description& model_description() const noexcept override {
    return md_;
  }
  void setup(time_point start, std::optional<time_point> stop) override {
    setup_start = start;
    setup_stop = stop;
    note("setup");
  }
  void enter_initialization() override { note("enter_initialization"); }
  void exit_initialization() override {
    note("exit_initialization");
    update();
  }
  void terminate() override {
    terminated = true;
    note("terminate");
  }

  void set_values(const variable_refs& refs, const value_block& values) override {
    ++set_calls;
    store(refs, values);
    if (!refs.empty()) update();
  }
  void get_values(const variable_refs& refs, value_block& values) override {
    ++get_calls;
    values.resize_for(refs);
    for (std::size_t k = 0; k < refs.reals.size(); ++k) values.reals[k] = reals_[refs.reals[k]];
    for (std::size_t k = 0; k < refs.integers.size(); ++k) {
      values.integers[k] = ints_[refs.integers[k]];
    }
    for (std::size_t k = 0; k < refs.booleans.size(); ++k) {
      values.booleans[k] = bools_[refs.booleans[k]];
    }
    for (std::size_t k = 0; k < refs.strings.size(); ++k) {
      values.strings[k] = strings_[refs.strings[k]];
    }
  }
  void expose(const variable_refs& inputs, const variable_refs& outputs) override {
    exposed_inputs = inputs;
    exposed_outputs = outputs;
  }
  step_result step(time_point t, duration dt, const value_block& inputs,
                   value_block& outputs) override {
    ++step_calls;
    store(exposed_inputs, inputs);  // the inputs of the step, without set_values' extra update
    note("do_step@" + std::to_string(t.time_since_epoch().count()));
    step_times.push_back(t);
    step_sizes.push_back(dt);
    step_result r = on_step ? on_step(*this, t, dt) : step_result::complete;
    if (r != step_result::complete) return r;
    update();
    --get_calls;  // the outputs travel with the step, not as a get
    get_values(exposed_outputs, outputs);
    return r;
  }
  std::vector<std::byte> save_state() override {
    throw std::logic_error("mock " + name_ + " has no state");
  }
  void restore_state(std::span<const std::byte>) override {
    throw std::logic_error("mock " + name_ + " has no state");
  }

  variable_refs exposed_inputs;
  variable_refs exposed_outputs;
  int step_calls = 0;
  int set_calls = 0;  ///< set_values calls outside steps
  int get_calls = 0;  ///< get_values calls outside steps

 private:
  void store(const variable_refs& refs, const value_block& values) {
    for (std::size_t k = 0; k < refs.reals.size(); ++k) reals_[refs.reals[k]] = values.reals[k];
    for (std::size_t k = 0; k < refs.integers.size(); ++k) {
      ints_[refs.integers[k]] = values.integers[k];
    }
    for (std::size_t k = 0; k < refs.booleans.size(); ++k) {
      bools_[refs.booleans[k]] = values.booleans[k];
    }
    for (std::size_t k = 0; k < refs.strings.size(); ++k) {
      strings_[refs.strings[k]] = values.strings[k];
    }
  }
  value_reference ref(const std::string& var) const {
    const auto* v = md_.find(var);
    if (v == nullptr) throw std::out_of_range("mock " + name_ + " has no variable " + var);
    return v->reference;
  }
  void update() {
    if (on_update) on_update(*this);
  }
  void note(const std::string& what) {
    if (log_) log_->entries.push_back(name_ + ":" + what);
  }

  std::string name_;
  std::shared_ptr<call_log> log_;
  stride::cosim::model_description md_;
  std::map<value_reference, double> reals_;
  std::map<value_reference, int> ints_;
  std::map<value_reference, bool> bools_;
  std::map<value_reference, std::string> strings_;
};

}  // namespace stride::cosim::test

#endif  // STRIDE_TESTS_ORCHESTRATOR_MOCK_COMPONENT_HPP
