#include "stride/cosim/execution.hpp"

#include <algorithm>

#include "state_bytes.hpp"
#include "stride/common/text.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim {

execution::execution(std::unique_ptr<stride::cosim::algorithm> algo, time_point start, log_sink log)
    : algo_(std::move(algo)),
      log_(log ? std::move(log) : stderr_log_sink()),
      start_(start),
      now_(start) {
  if (!algo_) throw validation_error("execution: null algorithm");
}

execution::~execution() {
  end();
  // the algorithm refers to the components: it goes first
  algo_.reset();
}

std::size_t execution::add_component(std::unique_ptr<component> c, int step_multiple) {
  if (frozen_) throw validation_error("cannot add a component after freeze()");
  if (!c) throw validation_error("add_component: null component");
  if (step_multiple < 1) {
    throw validation_error("component '" + c->name() + "': step multiple must be >= 1, got " +
                           std::to_string(step_multiple));
  }
  if (find_component(c->name())) {
    throw validation_error("duplicate component name '" + c->name() + "'");
  }
  components_.push_back(std::move(c));
  multiples_.push_back(step_multiple);
  starts_.emplace_back();
  return components_.size() - 1;
}

void execution::check_variable(variable_id id, const std::string& context) const {
  if (id.component >= components_.size()) {
    throw validation_error(context + "unknown component index " + std::to_string(id.component));
  }
  if (id.variable >= components_[id.component]->model_description().variables.size()) {
    throw validation_error(context + "component '" + components_[id.component]->name() +
                           "' has no variable #" + std::to_string(id.variable));
  }
}

void execution::connect(variable_id from, variable_id to, connection_options options) {
  if (frozen_) throw validation_error("cannot connect after freeze()");
  const std::string p = options.origin.empty() ? std::string() : options.origin + ": ";
  check_variable(from, p);
  check_variable(to, p);
  connections_.push_back({from, to, std::move(options)});
}

namespace {

// A value outside the variable's declared min..max: the FMU would refuse it at fmi2Set with a
// status that names no variable, so it is refused here, named.
void check_range(const variable_description& v, const scalar_value& value,
                 const std::string& what) {
  double x = 0;
  if (const auto* d = std::get_if<double>(&value)) {
    x = *d;
  } else if (const auto* i = std::get_if<int>(&value)) {
    x = *i;
  } else {
    return;
  }
  const auto bound = [](const std::optional<std::string>& limit) -> std::optional<double> {
    return limit ? text::parse_double(*limit) : std::nullopt;
  };
  if (const auto lo = bound(v.min); lo && x < *lo) {
    throw validation_error(what + " = " + format_scalar(value) + " is below its minimum " + *v.min);
  }
  if (const auto hi = bound(v.max); hi && x > *hi) {
    throw validation_error(what + " = " + format_scalar(value) + " is above its maximum " + *v.max);
  }
}

}  // namespace

void execution::set_start_value(variable_id id, scalar_value value, const std::string& origin) {
  const std::string where = origin.empty() ? std::string() : origin + ": ";
  if (initialized_) throw validation_error(where + "cannot set start values after initialize()");
  check_variable(id, where);
  const auto& v = components_[id.component]->model_description().variables[id.variable];
  const std::string name = full_name(id);
  if (v.causality != causality::parameter && v.causality != causality::input) {
    throw validation_error(where + name + " is " + std::string(to_string(v.causality)) +
                           "; only parameters and inputs can be given values");
  }
  if (v.variability == variability::constant) {
    throw validation_error(where + name + " is a constant");
  }
  check_range(v, value, where + name);
  start_values& s = starts_[id.component];
  const auto mismatch = [&] {
    throw validation_error(where + name + " is " + std::string(to_string(v.type)) + ", the value " +
                           format_scalar(value) + " has another type");
  };
  switch (exchange_type(v.type)) {
    case variable_type::real:
      if (const auto* d = std::get_if<double>(&value)) {
        s.values.reals.push_back(*d);
      } else if (const auto* i = std::get_if<int>(&value)) {
        s.values.reals.push_back(*i);
      } else {
        mismatch();
      }
      break;
    case variable_type::integer:
      if (const auto* i = std::get_if<int>(&value)) {
        s.values.integers.push_back(*i);
      } else {
        mismatch();
      }
      break;
    case variable_type::boolean:
      if (const auto* b = std::get_if<bool>(&value)) {
        s.values.booleans.push_back(*b);
      } else {
        mismatch();
      }
      break;
    case variable_type::string:
      if (const auto* str = std::get_if<std::string>(&value)) {
        s.values.strings.push_back(*str);
      } else {
        mismatch();
      }
      break;
    case variable_type::enumeration:
      break;
  }
  s.refs.add(v.type, v.reference);
  start_origins_.emplace_back(id, origin);
}

void execution::add_group(std::vector<std::size_t> members, std::unique_ptr<step_group> group) {
  if (frozen_) throw validation_error("cannot add a step group after freeze()");
  if (!group) throw validation_error("add_group: null group");
  if (members.size() < 2) throw validation_error("a step group needs at least two members");
  std::sort(members.begin(), members.end());
  for (std::size_t k = 0; k < members.size(); ++k) {
    if (members[k] >= components_.size()) {
      throw validation_error("add_group: no component " + std::to_string(members[k]));
    }
    if (k > 0 && members[k] == members[k - 1]) {
      throw validation_error("add_group: component '" + components_[members[k]]->name() +
                             "' named twice");
    }
    for (const auto& other : group_members_) {
      if (std::find(other.begin(), other.end(), members[k]) != other.end()) {
        throw validation_error("component '" + components_[members[k]]->name() +
                               "' is already in a step group");
      }
    }
  }
  group_members_.push_back(std::move(members));
  groups_.push_back(std::move(group));
}

component_declarations execution::declarations() const {
  component_declarations d;
  for (const auto& c : components_) {
    d.names.push_back(c->name());
    d.descriptions.push_back(&c->model_description());
  }
  return d;
}

void execution::freeze() {
  if (frozen_) return;
  if (components_.empty()) throw validation_error("the system has no components");
  const component_declarations d = declarations();
  validate_connections(d, connections_, log_);
  // the connection sets a driven variable at initialization: a value given to it would be lost
  for (const auto& [id, origin] : start_origins_) {
    for (const auto& c : connections_) {
      if (!(c.to == id)) continue;
      throw validation_error(
          (origin.empty() ? "" : origin + ": ") + full_name(id) +
          " is given a value, but the connection " + full_name(c.from) + " -> " + full_name(c.to) +
          (c.options.origin.empty() ? "" : " (" + c.options.origin + ")") +
          " drives it and would overwrite it: remove the value or the connection");
    }
  }
  system_wiring w;
  for (const auto& c : components_) w.components.push_back(c.get());
  w.step_multiples = multiples_;
  w.connections = connections_;
  w.starts = starts_;
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    w.groups.push_back({group_members_[g], groups_[g].get()});
  }
  order_ = algo_->stepping_order(w);
  algo_->setup(std::move(w), order_);
  frozen_ = true;
}

observed_variable execution::observe(variable_id id) {
  if (initialized_) throw validation_error("cannot observe variables after initialize()");
  check_variable(id, {});
  freeze();
  const auto& v = components_[id.component]->model_description().variables[id.variable];
  return {id, exchange_type(v.type), algo_->observe(id)};
}

void execution::add_observer(std::shared_ptr<observer> obs) {
  if (initialized_) throw validation_error("cannot add an observer after initialization");
  freeze();
  obs->attach(*this);
  observers_.push_back(std::move(obs));
}

void execution::stop_when(variable_id id) {
  if (initialized_) throw validation_error("cannot add a stop condition after initialize()");
  check_variable(id, {});
  const auto& v = components_[id.component]->model_description().variables[id.variable];
  const std::string name = full_name(id);
  if (v.causality != causality::output) {
    throw validation_error(name + " is " + std::string(to_string(v.causality)) +
                           "; a stop condition needs an output");
  }
  if (exchange_type(v.type) == variable_type::string) {
    throw validation_error(name +
                           " is a String output; a stop condition needs a Boolean, "
                           "Integer or Real output");
  }
  for (const auto& c : stop_conditions_) {
    if (c.id == id) return;
  }
  stop_conditions_.push_back(observe(id));
}

const observed_variable* execution::stop_condition_met() const {
  for (const auto& c : stop_conditions_) {
    switch (c.type) {
      case variable_type::boolean:
        if (boolean_value(c)) return &c;
        break;
      case variable_type::integer:
      case variable_type::enumeration:
        if (integer_value(c) != 0) return &c;
        break;
      case variable_type::real:
        if (real_value(c) != 0.0) return &c;
        break;
      case variable_type::string:
        break;
    }
  }
  return nullptr;
}

std::optional<std::size_t> execution::find_component(std::string_view name) const noexcept {
  for (std::size_t i = 0; i < components_.size(); ++i) {
    if (components_[i]->name() == name) return i;
  }
  return std::nullopt;
}

std::string execution::full_name(variable_id var) const {
  const auto& c = *components_.at(var.component);
  return c.name() + "." + c.model_description().variables.at(var.variable).name;
}

void execution::initialize(std::optional<time_point> stop) {
  if (initialized_) return;
  freeze();
  initialized_ = true;
  try {
    algo_->initialize(start_, stop);
  } catch (const std::exception& e) {
    finish(start_, e.what());
    throw;
  }
  for (auto& o : observers_) o->simulation_initialized(*this, start_);
}

step_outcome execution::step() {
  if (finished_) throw validation_error("the simulation has already ended");
  if (!initialized_) initialize(std::nullopt);
  const step_outcome outcome = algo_->step(now_);
  if (outcome.terminated) return outcome;
  ++steps_;
  now_ = start_ + steps_ * algo_->base_step();
  for (auto& o : observers_) o->step_complete(*this, steps_, now_);
  return outcome;
}

execution_state execution::save_state() const {
  if (!initialized_ || finished_) {
    throw validation_error("save_state() needs an initialized execution that has not ended");
  }
  execution_state s;
  s.steps = steps_;
  for (const auto& c : components_) s.components.push_back(c->save_state());
  s.algorithm = algo_->save_state();
  return s;
}

void execution::restore_state(const execution_state& s) {
  if (!initialized_ || finished_) {
    throw validation_error("restore_state() needs an initialized execution that has not ended");
  }
  if (s.components.size() != components_.size()) {
    throw validation_error("restore_state(): the state has " + std::to_string(s.components.size()) +
                           " components, the execution " + std::to_string(components_.size()));
  }
  for (std::size_t i = 0; i < components_.size(); ++i) {
    components_[i]->restore_state(s.components[i]);
  }
  algo_->restore_state(s.algorithm);
  steps_ = s.steps;
  now_ = start_ + steps_ * algo_->base_step();
}

namespace {

constexpr std::string_view k_state_magic = "stride execution state 1";

struct parsed_state {
  std::int64_t steps = 0;
  std::vector<saved_component> components;
  std::vector<std::byte> algorithm;
};

parsed_state parse_state(std::span<const std::byte> bytes) {
  detail::byte_reader r(bytes, "saved execution state");
  if (r.get_string() != k_state_magic) {
    throw validation_error("saved execution state: not a state written by this version");
  }
  parsed_state s;
  s.steps = r.get<std::int64_t>();
  s.components.resize(r.get_size(2 * sizeof(std::uint64_t)));  // two lengths each at least
  for (saved_component& c : s.components) {
    c.name = r.get_string();
    const auto b = r.get_bytes();
    c.image.assign(b.begin(), b.end());
  }
  const auto algorithm = r.get_bytes();
  s.algorithm.assign(algorithm.begin(), algorithm.end());
  if (!r.at_end()) r.fail();
  return s;
}

}  // namespace

std::vector<saved_component> saved_components(std::span<const std::byte> state_bytes) {
  return parse_state(state_bytes).components;
}

std::vector<std::byte> execution::save_state_bytes() const {
  const execution_state s = save_state();
  detail::byte_writer w;
  w.put_string(std::string(k_state_magic));
  w.put(static_cast<std::int64_t>(s.steps));
  w.put_size(s.components.size());
  for (std::size_t i = 0; i < s.components.size(); ++i) {
    w.put_string(components_[i]->name());
    w.put_bytes(s.components[i]);
  }
  w.put_bytes(algo_->state_to_bytes(s.algorithm));
  return w.take();
}

void execution::restore_state_bytes(std::span<const std::byte> bytes) {
  parsed_state saved = parse_state(bytes);
  if (saved.components.size() != components_.size()) {
    throw validation_error("saved execution state: " + std::to_string(saved.components.size()) +
                           " components, the system has " + std::to_string(components_.size()));
  }
  execution_state s;
  s.steps = saved.steps;
  for (std::size_t i = 0; i < components_.size(); ++i) {
    if (saved.components[i].name != components_[i]->name()) {
      throw validation_error("saved execution state: component " + std::to_string(i + 1) + " is '" +
                             saved.components[i].name + "', in the system '" +
                             components_[i]->name() + "'");
    }
    s.components.push_back(std::move(saved.components[i].image));
  }
  s.algorithm = algo_->state_from_bytes(saved.algorithm);
  restore_state(s);
}

void execution::terminate_components() noexcept {
  for (auto& c : components_) {
    try {
      c->terminate();
    } catch (const std::exception& ex) {
      log_(log_level::warning, "stride", "", ex.what());
    }
  }
}

void execution::finish(time_point t, const std::string& error) noexcept {
  if (finished_) return;
  finished_ = true;
  for (auto& o : observers_) {
    try {
      o->simulation_ended(*this, t, error);
    } catch (...) {
      // observers must not stop the shutdown of the others
    }
  }
  terminate_components();
}

void execution::end() noexcept {
  if (initialized_) finish(now_, {});
}

run_result execution::simulate_until(time_point stop, const std::atomic<bool>* interrupt) {
  if (finished_) throw validation_error("the simulation has already ended");
  if (!initialized_) initialize(stop);
  run_result result;
  const duration h = algo_->base_step();
  const auto condition_met = [&] {
    const observed_variable* met = stop_condition_met();
    if (met != nullptr) result.stopped_by = full_name(met->id);
    return met != nullptr;
  };
  try {
    if (!condition_met()) {
      while (now_ + h <= stop) {
        if (interrupt != nullptr && interrupt->load(std::memory_order_relaxed)) {
          result.interrupted = true;
          break;
        }
        const step_outcome outcome = step();
        if (outcome.terminated) {
          result.terminated_by_component = true;
          result.terminated_by = components_[outcome.terminated_by]->name();
          break;
        }
        if (condition_met()) break;
      }
    }
  } catch (const std::exception& e) {
    finish(now_, e.what());
    throw;
  }
  result.end_time = now_;
  result.steps = steps_;
  if (result.terminated_by_component || !result.stopped_by.empty()) finish(result.end_time, {});
  return result;
}

}  // namespace stride::cosim
