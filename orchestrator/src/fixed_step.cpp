// The fixed-step master algorithm: value caches per component, wiring of connections to inputs,
// initialization, and the macro step (sequential, or spread over threads by a step_plan).
#include <algorithm>
#include <cmath>
#include <map>
#include <thread>

#include "state_bytes.hpp"
#include "stride/common/text.hpp"
#include "stride/cosim/algorithm.hpp"
#include "stride/cosim/error.hpp"
#include "task_runner.hpp"
#include "value_lanes.hpp"

namespace stride::cosim {

std::string_view to_string(algorithm_kind kind) noexcept {
  return kind == algorithm_kind::jacobi ? "jacobi" : "gauss-seidel";
}

int default_thread_count() noexcept {
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

namespace {

using detail::for_each_type;
using detail::lane;

constexpr std::size_t k_no_group = static_cast<std::size_t>(-1);

// where an input's value comes from: an output slot of a component
struct source {
  std::size_t component = 0;
  std::size_t slot = 0;
  bool previous = false;  // reads the previous communication point (delayed or Jacobi)
  // a Real connection's linear transformation (skipped when off: untransformed values stay
  // bit for bit what the source gave)
  bool transformed = false;
  double factor = 1.0;
  double offset = 0.0;
  std::size_t connection = 0;  // index into the wiring's connections, for messages
};

// inputs of one component with their sources, one list per type (parallel to `refs`)
struct input_wiring {
  variable_refs refs;
  std::vector<source> reals, integers, booleans, strings;
  value_block values;

  template <class T>
  std::vector<source>& sources() {
    if constexpr (std::is_same_v<T, double>) return reals;
    if constexpr (std::is_same_v<T, int>) return integers;
    if constexpr (std::is_same_v<T, bool>) return booleans;
    if constexpr (std::is_same_v<T, std::string>) return strings;
  }
};

struct entry {
  component* c = nullptr;
  int multiple = 1;
  time_point time{};
  variable_refs outputs;     // read after every step: connected sources and observed variables
  value_block latest;        // at the component's current time
  value_block published;     // at its previous communication point
  input_wiring step_inputs;  // inputs and tunable parameters: set with every step
  input_wiring init_inputs;  // fixed parameters: set during initialization only
  std::map<std::size_t, std::size_t> slot_of;  // variable index → slot in its type's lane
  bool needs_published = true;  // someone reads its previous values (delay, Jacobi, decimation)
  bool steps_now = false;       // it steps in the current macro step
  bool terminated = false;
  std::size_t group = k_no_group;  // the step group it belongs to
};

// a step group as the algorithm drives it
struct group_entry {
  step_group* stepper = nullptr;
  std::vector<std::size_t> members;  // component indices, ascending
  std::size_t first = 0;             // the member stepped first: the group steps in its place
  group_layout layout;
  bool prepared = false;  // the group has the members' current caches
  std::vector<const value_block*> inputs;
  std::vector<value_block*> outputs;
};

}  // namespace

class fixed_step_algorithm::impl {
 public:
  duration step{};
  algorithm_kind kind = algorithm_kind::gauss_seidel;
  int threads = 1;
  system_wiring wiring;
  std::vector<std::size_t> order;
  std::vector<entry> entries;
  std::vector<group_entry> groups;
  std::vector<std::pair<std::size_t, std::size_t>> observed;  // component, slot
  std::vector<variable_type> observed_type;
  step_plan plan;
  std::unique_ptr<task_runner> runner;
  bool initialized = false;
  time_point start{};
  time_point now{};
  std::int64_t steps = 0;

  const variable_description& var(variable_id id) const {
    return entries.at(id.component).c->model_description().variables.at(id.variable);
  }

  // the output slot of a variable in its component's caches, added once
  std::size_t add_output(variable_id id) {
    entry& e = entries[id.component];
    if (auto it = e.slot_of.find(id.variable); it != e.slot_of.end()) return it->second;
    const auto& v = var(id);
    const std::size_t slot = e.outputs.add(exchange_type(v.type), v.reference);
    e.slot_of.emplace(id.variable, slot);
    return slot;
  }

  bool reads_previous(const connection& c) const {
    return c.options.delayed || kind == algorithm_kind::jacobi;
  }

  // the input slot the connection feeds, in the lane of its type
  template <class T>
  std::size_t add_input(input_wiring& w, const connection& c, std::size_t slot, std::size_t index) {
    lane<T>(w.refs).push_back(var(c.to).reference);
    w.sources<T>().push_back({c.from.component, slot, reads_previous(c), c.options.transforms(),
                              c.options.factor, c.options.offset, index});
    return lane<T>(w.refs).size() - 1;
  }

  void wire_inputs() {
    for (std::size_t index = 0; index < wiring.connections.size(); ++index) {
      const connection& c = wiring.connections[index];
      const std::size_t slot = add_output(c.from);
      const auto& to = var(c.to);
      const bool init_only =
          to.causality == causality::parameter && to.variability != variability::tunable;
      entry& e = entries[c.to.component];
      input_wiring& w = init_only ? e.init_inputs : e.step_inputs;
      std::size_t to_slot = 0;
      detail::with_type(to.type, [&]<class T>() { to_slot = add_input<T>(w, c, slot, index); });
      // within a step group the group itself carries the value from member to member
      const std::size_t g = entries[c.from.component].group;
      if (!init_only && g != k_no_group && g == e.group) {
        if (c.options.transforms()) {
          throw validation_error(c.options.origin + ": a step group cannot carry a connection " +
                                 "with a linear transformation between its members");
        }
        const auto position = [&](std::size_t component) {
          const auto& m = groups[g].members;
          return static_cast<std::size_t>(std::find(m.begin(), m.end(), component) - m.begin());
        };
        groups[g].layout.links.push_back({position(c.from.component), slot,
                                          position(c.to.component), to_slot, exchange_type(to.type),
                                          reads_previous(c)});
      }
    }
  }

  // the value of a source as seen at time t (the rule is in value_lanes.hpp)
  template <class T>
  auto read(const source& s, time_point t) const {
    const entry& e = entries[s.component];
    const bool published = detail::reads_published(s.previous, e.steps_now, e.time, t);
    return lane<T>(published ? e.published : e.latest)[s.slot];
  }

  void transfer(input_wiring& w, time_point current, time_point previous) {
    for_each_type([&]<class T>() {
      auto& values = lane<T>(w.values);
      const auto& sources = w.sources<T>();
      for (std::size_t i = 0; i < sources.size(); ++i) {
        values[i] = read<T>(sources[i], sources[i].previous ? previous : current);
        if constexpr (std::is_same_v<T, double>) {
          if (sources[i].transformed) values[i] = transform(sources[i], values[i]);
        }
      }
    });
  }

  // factor × value + offset; an infinity or NaN reaches no component (as for outputs)
  double transform(const source& s, double value) const {
    const double out = s.factor * value + s.offset;
    if (!std::isfinite(out)) {
      const connection& c = wiring.connections[s.connection];
      const auto name = [&](variable_id id) {
        return entries[id.component].c->name() + "." + var(id).name;
      };
      throw component_error((c.options.origin.empty() ? "" : c.options.origin + ": ") +
                            "connection " + name(c.from) + " -> " + name(c.to) + ": " +
                            text::format_double(s.factor) + " * " + text::format_double(value) +
                            " + " + text::format_double(s.offset) + " is not a finite number");
    }
    return out;
  }

  // runs `f`, turning any exception into a component_error naming the component and the time
  template <class F>
  void guarded(const entry& e, time_point t, const char* phase, F&& f) {
    try {
      f();
    } catch (const component_error& ex) {
      throw component_error(std::string(ex.what()) + " (" + phase + " at t = " + format_seconds(t) +
                            " s)");
    } catch (const std::exception& ex) {
      throw component_error("component '" + e.c->name() + "': " + ex.what() + " (" + phase +
                            " at t = " + format_seconds(t) + " s)");
    }
  }

  // one component's part of the macro step from t; false when it asked to terminate
  bool step_entry(entry& e, time_point t, time_point next) {
    if (!e.steps_now) return true;
    const duration dt = step * e.multiple;
    step_result r = step_result::complete;
    guarded(e, t, "step", [&] {
      // Gauss-Seidel reads upstream values at the end of the step, Jacobi at its start
      transfer(e.step_inputs, kind == algorithm_kind::jacobi ? t : next, t);
      r = e.c->step(e.time, dt, e.step_inputs.values, e.latest);
    });
    if (r == step_result::terminate) {
      e.terminated = true;
      return false;
    }
    e.time += dt;
    return true;
  }

  // a step group's part of the macro step from t; false when a member asked to terminate
  bool step_group_entry(group_entry& g, time_point t, time_point next) {
    if (!g.prepared) {
      std::vector<member_cache> caches;
      for (std::size_t m : g.members) {
        caches.push_back({entries[m].time, entries[m].latest, entries[m].published});
      }
      guarded(entries[g.first], t, "step", [&] { g.stepper->prepare(caches); });
      g.prepared = true;
    }
    for (std::size_t k = 0; k < g.members.size(); ++k) {
      entry& e = entries[g.members[k]];
      // the slots fed by other members get what this side knows; the group overwrites them
      if (e.steps_now) transfer(e.step_inputs, kind == algorithm_kind::jacobi ? t : next, t);
      g.inputs[k] = &e.step_inputs.values;
      g.outputs[k] = &e.latest;
    }
    std::optional<std::size_t> ended;
    guarded(entries[g.first], t, "step",
            [&] { ended = g.stepper->step(t, steps, g.inputs, g.outputs); });
    for (std::size_t k : g.layout.order) {
      entry& e = entries[g.members[k]];
      if (ended == k) {
        e.terminated = true;
        return false;
      }
      if (e.steps_now) e.time += step * e.multiple;
    }
    return true;
  }

  // one unit of the macro step: a component alone, or the group it opens
  bool step_unit(std::size_t i, time_point t, time_point next) {
    entry& e = entries[i];
    if (e.group == k_no_group) return step_entry(e, t, next);
    group_entry& g = groups[e.group];
    return i != g.first || step_group_entry(g, t, next);
  }

  // units for the step groups: the stepping order and the thread plan are made over them
  step_units units() const {
    std::vector<std::vector<std::size_t>> members;
    for (const auto& g : wiring.groups) members.push_back(g.members);
    return make_units(wiring.components.size(), members);
  }
};

fixed_step_algorithm::fixed_step_algorithm(duration base_step, algorithm_kind kind, int threads)
    : pimpl_(std::make_unique<impl>()) {
  if (base_step <= duration::zero()) {
    throw validation_error("base step must be positive, got " + format_seconds(base_step) + " s");
  }
  if (threads < 1) {
    throw validation_error("thread count must be at least 1, got " + std::to_string(threads));
  }
  pimpl_->step = base_step;
  pimpl_->kind = kind;
  pimpl_->threads = threads;
}

fixed_step_algorithm::~fixed_step_algorithm() = default;

algorithm_kind fixed_step_algorithm::kind() const noexcept {
  return pimpl_->kind;
}
int fixed_step_algorithm::threads() const noexcept {
  return pimpl_->threads;
}
duration fixed_step_algorithm::base_step() const noexcept {
  return pimpl_->step;
}
std::string fixed_step_algorithm::describe() const {
  return std::string(to_string(pimpl_->kind));
}

std::vector<std::size_t> fixed_step_algorithm::stepping_order(const system_wiring& w) const {
  const bool gauss_seidel = pimpl_->kind == algorithm_kind::gauss_seidel;
  std::vector<std::vector<std::size_t>> groups;
  for (const auto& g : w.groups) groups.push_back(g.members);
  const step_units u = make_units(w.components.size(), groups);
  std::vector<std::size_t> unit_order(u.members.size());
  for (std::size_t k = 0; k < unit_order.size(); ++k) unit_order[k] = k;
  if (gauss_seidel)
    unit_order = gauss_seidel_order(u.members.size(), connections_between(u, w.connections));
  // a unit's members among themselves: the order they would have alone
  std::vector<std::size_t> order;
  for (std::size_t unit : unit_order) {
    const auto& members = u.members[unit];
    if (members.size() == 1 || !gauss_seidel) {
      order.insert(order.end(), members.begin(), members.end());
      continue;
    }
    std::vector<connection> inside;
    for (const auto& c : w.connections) {
      const auto from = std::find(members.begin(), members.end(), c.from.component);
      const auto to = std::find(members.begin(), members.end(), c.to.component);
      if (from == members.end() || to == members.end()) continue;
      connection local = c;
      local.from.component = static_cast<std::size_t>(from - members.begin());
      local.to.component = static_cast<std::size_t>(to - members.begin());
      inside.push_back(std::move(local));
    }
    for (std::size_t k : gauss_seidel_order(members.size(), inside)) order.push_back(members[k]);
  }
  return order;
}

void fixed_step_algorithm::setup(system_wiring wiring, std::vector<std::size_t> order) {
  auto& p = *pimpl_;
  if (!p.entries.empty()) throw validation_error("algorithm set up twice");
  if (p.kind == algorithm_kind::gauss_seidel) {
    // values travel within the step: a direct-feedthrough loop has no solution
    component_declarations d;
    for (component* c : wiring.components) {
      d.names.push_back(c->name());
      d.descriptions.push_back(&c->model_description());
    }
    check_algebraic_loops(d, wiring.connections);
  }
  p.wiring = std::move(wiring);
  p.order = std::move(order);
  for (std::size_t i = 0; i < p.wiring.components.size(); ++i) {
    entry e;
    e.c = p.wiring.components[i];
    e.multiple = p.wiring.step_multiples.at(i);
    p.entries.push_back(std::move(e));
  }
  const step_units units = p.units();  // checks that the groups are disjoint
  std::vector<std::size_t> position_in_order(p.entries.size());
  for (std::size_t k = 0; k < p.order.size(); ++k) position_in_order.at(p.order[k]) = k;
  for (const auto& gw : p.wiring.groups) {
    if (gw.stepper == nullptr || gw.members.empty()) {
      throw validation_error("a step group without members or stepper");
    }
    group_entry g;
    g.stepper = gw.stepper;
    g.members = gw.members;
    for (std::size_t k = 0; k < g.members.size(); ++k) {
      p.entries[g.members[k]].group = p.groups.size();
      g.layout.order.push_back(k);
      g.layout.multiples.push_back(p.entries[g.members[k]].multiple);
    }
    std::sort(g.layout.order.begin(), g.layout.order.end(), [&](std::size_t a, std::size_t b) {
      return position_in_order[g.members[a]] < position_in_order[g.members[b]];
    });
    g.first = g.members[g.layout.order.front()];
    g.layout.base_step = p.step;
    g.inputs.resize(g.members.size());
    g.outputs.resize(g.members.size());
    p.groups.push_back(std::move(g));
  }
  p.wire_inputs();
  for (auto& g : p.groups) g.stepper->arrange(g.layout);
  // previous values are read only through delays, Jacobi transfer or decimation
  for (auto& e : p.entries) e.needs_published = p.kind == algorithm_kind::jacobi || e.multiple > 1;
  for (const auto& c : p.wiring.connections) {
    if (c.options.delayed) p.entries[c.from.component].needs_published = true;
  }
  // the thread plan over units, each unit's members in stepping order
  std::vector<std::size_t> unit_order;
  for (std::size_t i : p.order) {
    const std::size_t u = units.unit_of[i];
    if (std::find(unit_order.begin(), unit_order.end(), u) == unit_order.end()) {
      unit_order.push_back(u);
    }
  }
  p.plan = plan_steps(unit_order, connections_between(units, p.wiring.connections),
                      p.kind == algorithm_kind::jacobi);
  for (auto& task : p.plan.tasks) {
    std::vector<std::size_t> components;
    for (std::size_t i : p.order) {
      if (std::find(task.begin(), task.end(), units.unit_of[i]) != task.end()) {
        components.push_back(i);
      }
    }
    task = std::move(components);
  }
  if (p.threads > 1 && p.plan.tasks.size() > 1) {
    p.runner = std::make_unique<task_runner>(
        std::min<int>(p.threads, static_cast<int>(p.plan.tasks.size())), p.plan.tasks.size());
  }
}

std::size_t fixed_step_algorithm::observe(variable_id id) {
  auto& p = *pimpl_;
  if (p.initialized) throw validation_error("cannot observe variables after initialize()");
  const std::size_t slot = p.add_output(id);
  p.observed.emplace_back(id.component, slot);
  p.observed_type.push_back(exchange_type(p.var(id).type));
  return p.observed.size() - 1;
}

void fixed_step_algorithm::initialize(time_point start, std::optional<time_point> stop) {
  auto& p = *pimpl_;
  if (p.initialized) throw validation_error("initialize() called twice");
  p.start = p.now = start;
  p.steps = 0;
  p.initialized = true;
  for (auto& e : p.entries) {
    e.latest.resize_for(e.outputs);
    e.published.resize_for(e.outputs);
    e.step_inputs.values.resize_for(e.step_inputs.refs);
    e.init_inputs.values.resize_for(e.init_inputs.refs);
  }
  // setup, start values, the exchange declaration
  for (std::size_t i = 0; i < p.entries.size(); ++i) {
    entry& e = p.entries[i];
    std::optional<time_point> own_stop;
    if (stop) {
      // a slow component's last step may end after the stop time
      const auto period = p.step * e.multiple;
      const auto periods = (*stop - start + period - duration(1)) / period;
      own_stop = start + periods * period;
    }
    e.time = start;
    p.guarded(e, start, "setup", [&] {
      e.c->setup(start, own_stop);
      const start_values& sv = p.wiring.starts.at(i);
      if (!sv.refs.empty()) e.c->set_values(sv.refs, sv.values);
      e.c->expose(e.step_inputs.refs, e.outputs);
      e.c->enter_initialization();
    });
  }
  // initial value exchange in stepping order, so feedthrough chains settle
  for (auto& e : p.entries) {
    p.guarded(e, start, "initialization", [&] { e.c->get_values(e.outputs, e.latest); });
  }
  for (std::size_t i : p.order) {
    entry& e = p.entries[i];
    p.guarded(e, start, "initialization", [&] {
      p.transfer(e.step_inputs, start, start);
      p.transfer(e.init_inputs, start, start);
      e.c->set_values(e.step_inputs.refs, e.step_inputs.values);
      e.c->set_values(e.init_inputs.refs, e.init_inputs.values);
      e.c->get_values(e.outputs, e.latest);
    });
  }
  for (auto& e : p.entries) {
    p.guarded(e, start, "initialization", [&] {
      e.c->exit_initialization();
      e.c->get_values(e.outputs, e.latest);
    });
    e.published = e.latest;
  }
}

step_outcome fixed_step_algorithm::step(time_point t) {
  auto& p = *pimpl_;
  if (!p.initialized) throw validation_error("step() before initialize()");
  const time_point next = p.start + (p.steps + 1) * p.step;
  // who steps now; their current values become the previous communication point's
  for (auto& e : p.entries) {
    e.steps_now = p.steps % e.multiple == 0;
    if (e.steps_now && e.needs_published) e.published = e.latest;
  }
  // a task stops at a component that asks to terminate, and holds back the tasks that wait
  // for it; the other tasks complete, whatever the thread count
  const auto run_task = [&](std::size_t task) {
    for (std::size_t i : p.plan.tasks[task]) {
      if (!p.step_unit(i, t, next)) return false;
    }
    return true;
  };
  if (p.runner) {
    p.runner->run(p.plan, run_task);
  } else {
    std::vector<bool> blocked(p.plan.tasks.size(), false);
    for (std::size_t task = 0; task < p.plan.tasks.size(); ++task) {
      const bool released = !blocked[task] && run_task(task);
      if (released) continue;
      for (std::size_t s : p.plan.successors[task]) blocked[s] = true;
    }
  }
  for (std::size_t i : p.order) {
    if (p.entries[i].terminated) return {true, i};
  }
  ++p.steps;
  p.now = next;
  return {};
}

namespace {

// what survives a restore: per component its time and cached values
struct cached_entry {
  time_point time{};
  value_block latest;
  value_block published;
};
struct cached_state {
  time_point now{};
  std::int64_t steps = 0;
  std::vector<cached_entry> entries;
};

}  // namespace

std::any fixed_step_algorithm::save_state() const {
  const auto& p = *pimpl_;
  if (!p.initialized) throw validation_error("save_state() before initialize()");
  cached_state s{p.now, p.steps, {}};
  for (const auto& e : p.entries) s.entries.push_back({e.time, e.latest, e.published});
  return s;
}

void fixed_step_algorithm::restore_state(const std::any& state) {
  auto& p = *pimpl_;
  const auto* s = std::any_cast<cached_state>(&state);
  if (s == nullptr || s->entries.size() != p.entries.size()) {
    throw validation_error("restore_state(): not a state of this algorithm");
  }
  p.now = s->now;
  p.steps = s->steps;
  for (std::size_t i = 0; i < p.entries.size(); ++i) {
    p.entries[i].time = s->entries[i].time;
    p.entries[i].latest = s->entries[i].latest;
    p.entries[i].published = s->entries[i].published;
    p.entries[i].terminated = false;
  }
  for (auto& g : p.groups) g.prepared = false;  // the groups get the restored caches
}

std::vector<std::byte> fixed_step_algorithm::state_to_bytes(const std::any& state) const {
  const auto* s = std::any_cast<cached_state>(&state);
  if (s == nullptr) throw validation_error("state_to_bytes(): not a state of this algorithm");
  detail::byte_writer w;
  w.put(static_cast<std::int64_t>(s->now.time_since_epoch().count()));
  w.put(static_cast<std::int64_t>(s->steps));
  w.put_size(s->entries.size());
  for (const auto& e : s->entries) {
    w.put(static_cast<std::int64_t>(e.time.time_since_epoch().count()));
    detail::put_block(w, e.latest);
    detail::put_block(w, e.published);
  }
  return w.take();
}

std::any fixed_step_algorithm::state_from_bytes(std::span<const std::byte> bytes) const {
  detail::byte_reader r(bytes, "the algorithm's saved state");
  cached_state s;
  s.now = time_point(duration(r.get<std::int64_t>()));
  s.steps = r.get<std::int64_t>();
  const std::size_t n = r.get_size();
  if (n != pimpl_->entries.size()) {
    throw validation_error("the algorithm's saved state has " + std::to_string(n) +
                           " components, the system " + std::to_string(pimpl_->entries.size()));
  }
  for (std::size_t i = 0; i < n; ++i) {
    cached_entry e;
    e.time = time_point(duration(r.get<std::int64_t>()));
    e.latest = detail::get_block(r);
    e.published = detail::get_block(r);
    const value_block& now = pimpl_->entries[i].latest;
    for (const value_block* b : {&e.latest, &e.published}) {
      if (b->reals.size() != now.reals.size() || b->integers.size() != now.integers.size() ||
          b->booleans.size() != now.booleans.size() || b->strings.size() != now.strings.size()) {
        throw validation_error("the algorithm's saved state does not fit component '" +
                               pimpl_->entries[i].c->name() + "': another system or wiring");
      }
    }
    s.entries.push_back(std::move(e));
  }
  if (!r.at_end()) r.fail();
  return s;
}

namespace {

template <class T>
decltype(auto) observed_value(const std::vector<entry>& entries,
                              const std::pair<std::size_t, std::size_t>& where, time_point now) {
  const entry& e = entries.at(where.first);
  return e.time <= now ? lane<T>(e.latest)[where.second] : lane<T>(e.published)[where.second];
}

}  // namespace

double fixed_step_algorithm::real_value(std::size_t k) const {
  return observed_value<double>(pimpl_->entries, pimpl_->observed.at(k), pimpl_->now);
}
int fixed_step_algorithm::integer_value(std::size_t k) const {
  return observed_value<int>(pimpl_->entries, pimpl_->observed.at(k), pimpl_->now);
}
bool fixed_step_algorithm::boolean_value(std::size_t k) const {
  return observed_value<bool>(pimpl_->entries, pimpl_->observed.at(k), pimpl_->now);
}
const std::string& fixed_step_algorithm::string_value(std::size_t k) const {
  return observed_value<std::string>(pimpl_->entries, pimpl_->observed.at(k), pimpl_->now);
}

}  // namespace stride::cosim
