#include "stride/cosim/algorithm.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <map>
#include <queue>
#include <set>
#include <stdexcept>

#include "stride/cosim/error.hpp"

namespace stride::cosim {

std::string_view to_string(algorithm_kind kind) noexcept {
  return kind == algorithm_kind::jacobi ? "jacobi" : "gauss-seidel";
}

scalar_value parse_scalar(variable_type type, std::string_view text) {
  const std::string s(text);
  const char* first = s.data();
  const char* last = s.data() + s.size();
  switch (type) {
    case variable_type::real: {
      double v = 0;
      auto [end, ec] = std::from_chars(first, last, v);
      if (ec != std::errc() || end != last || !std::isfinite(v)) {
        throw std::invalid_argument("'" + s + "' is not a Real");
      }
      return v;
    }
    case variable_type::integer:
    case variable_type::enumeration: {
      int v = 0;
      auto [end, ec] = std::from_chars(first, last, v);
      if (ec != std::errc() || end != last) {
        throw std::invalid_argument("'" + s + "' is not an Integer");
      }
      return v;
    }
    case variable_type::boolean:
      if (s == "true" || s == "1") return true;
      if (s == "false" || s == "0") return false;
      throw std::invalid_argument("'" + s + "' is not a Boolean (true, false, 1 or 0)");
    case variable_type::string:
      return s;
  }
  throw std::invalid_argument("unknown type");
}

std::string format_scalar(const scalar_value& value) {
  struct visitor {
    std::string operator()(double d) const {
      char buf[32];
      auto [end, ec] = std::to_chars(buf, buf + sizeof buf, d);
      return ec == std::errc() ? std::string(buf, end) : std::to_string(d);
    }
    std::string operator()(int i) const { return std::to_string(i); }
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(const std::string& s) const { return s; }
  };
  return std::visit(visitor{}, value);
}

namespace {

// Fixed-size array usable with std::span for every value type (std::vector<bool> is not).
template <class T>
class array_buffer {
 public:
  array_buffer() = default;
  array_buffer(const array_buffer& o) : data_(std::make_unique<T[]>(o.size_)), size_(o.size_) {
    std::copy(o.data_.get(), o.data_.get() + size_, data_.get());
  }
  array_buffer& operator=(const array_buffer& o) {
    if (this != &o) {
      if (size_ != o.size_) {
        data_ = std::make_unique<T[]>(o.size_);
        size_ = o.size_;
      }
      std::copy(o.data_.get(), o.data_.get() + size_, data_.get());
    }
    return *this;
  }
  void push_back(T v) {
    auto next = std::make_unique<T[]>(size_ + 1);
    std::move(data_.get(), data_.get() + size_, next.get());
    next[size_] = std::move(v);
    data_ = std::move(next);
    ++size_;
  }
  std::size_t size() const noexcept { return size_; }
  bool empty() const noexcept { return size_ == 0; }
  T& operator[](std::size_t i) noexcept { return data_[i]; }
  const T& operator[](std::size_t i) const noexcept { return data_[i]; }
  std::span<T> span() noexcept { return {data_.get(), size_}; }
  std::span<const T> cspan() const noexcept { return {data_.get(), size_}; }

 private:
  std::unique_ptr<T[]> data_;
  std::size_t size_ = 0;
};

// The observed values of one type of one component.
template <class T>
struct value_cache {
  std::vector<value_reference> vrs;
  std::vector<std::size_t> variables;  // model description index per slot
  array_buffer<T> latest;              // at the component's current time
  array_buffer<T> published;           // at the component's previous communication point
};

struct source_ref {
  std::size_t component = 0;
  std::size_t slot = 0;
  bool delayed = false;
};

// Values to set on one component before a step (or during initialization).
template <class T>
struct input_set {
  std::vector<value_reference> vrs;
  std::vector<source_ref> sources;
  array_buffer<T> values;
};

template <class T>
struct typed_io {
  value_cache<T> cache;
  input_set<T> step_inputs;  // inputs and tunable parameters: set before every step
  input_set<T> init_inputs;  // fixed parameters: set during initialization only
  std::vector<value_reference> start_vrs;
  array_buffer<T> start_values;
};

struct entry {
  std::unique_ptr<stride::cosim::component> c;
  int multiple = 1;
  time_point time{};
  typed_io<double> reals;
  typed_io<int> ints;
  typed_io<bool> bools;
  typed_io<std::string> strings;
  std::map<std::size_t, std::size_t> slot_of;  // variable index → slot in its type's cache
  bool terminated = false;
  // whether anyone may read this component's previous values (see read())
  bool needs_published = true;

  template <class T>
  typed_io<T>& io() {
    if constexpr (std::is_same_v<T, double>) return reals;
    if constexpr (std::is_same_v<T, int>) return ints;
    if constexpr (std::is_same_v<T, bool>) return bools;
    if constexpr (std::is_same_v<T, std::string>) return strings;
  }
  template <class T>
  const typed_io<T>& io() const {
    return const_cast<entry*>(this)->io<T>();
  }
};

template <class T>
void component_get(component& c, std::span<const value_reference> vr, std::span<T> out) {
  if (vr.empty()) return;
  if constexpr (std::is_same_v<T, double>) c.get_real(vr, out);
  if constexpr (std::is_same_v<T, int>) c.get_integer(vr, out);
  if constexpr (std::is_same_v<T, bool>) c.get_boolean(vr, out);
  if constexpr (std::is_same_v<T, std::string>) c.get_string(vr, out);
}

template <class T>
void component_set(component& c, std::span<const value_reference> vr, std::span<const T> in) {
  if (vr.empty()) return;
  if constexpr (std::is_same_v<T, double>) c.set_real(vr, in);
  if constexpr (std::is_same_v<T, int>) c.set_integer(vr, in);
  if constexpr (std::is_same_v<T, bool>) c.set_boolean(vr, in);
  if constexpr (std::is_same_v<T, std::string>) c.set_string(vr, in);
}

}  // namespace

class fixed_step_algorithm::impl {
 public:
  duration step;
  algorithm_kind kind;
  log_sink log;
  std::vector<entry> entries;
  std::vector<connection> conns;
  std::vector<std::size_t> order;
  bool is_frozen = false;
  bool is_initialized = false;
  bool is_terminated = false;
  time_point start{};
  time_point now{};
  std::int64_t steps = 0;

  const variable_description& var(variable_id id) const {
    return entries.at(id.component).c->model_description().variables.at(id.variable);
  }
  std::string full_name(variable_id id) const {
    return entries.at(id.component).c->name() + "." + var(id).name;
  }

  void warn(const std::string& message) const {
    if (log) log(log_level::warning, "stride", "", message);
  }

  // adds `variable` to its component's value cache (once) and returns the slot
  std::size_t add_to_cache(variable_id id) {
    auto& e = entries[id.component];
    if (auto it = e.slot_of.find(id.variable); it != e.slot_of.end()) return it->second;
    const auto& v = var(id);
    std::size_t slot = 0;
    auto add = [&](auto& io) {
      slot = io.cache.vrs.size();
      io.cache.vrs.push_back(v.reference);
      io.cache.variables.push_back(id.variable);
      io.cache.latest.push_back({});
      io.cache.published.push_back({});
    };
    switch (exchange_type(v.type)) {
      case variable_type::real:
        add(e.reals);
        break;
      case variable_type::integer:
        add(e.ints);
        break;
      case variable_type::boolean:
        add(e.bools);
        break;
      case variable_type::string:
        add(e.strings);
        break;
      case variable_type::enumeration:
        break;
    }
    e.slot_of.emplace(id.variable, slot);
    return slot;
  }

  void check_variable(variable_id id, const std::string& context) const {
    if (id.component >= entries.size()) {
      throw validation_error(context + "unknown component index " + std::to_string(id.component));
    }
    if (id.variable >= entries[id.component].c->model_description().variables.size()) {
      throw validation_error(context + "component '" + entries[id.component].c->name() +
                             "' has no variable #" + std::to_string(id.variable));
    }
  }

  static std::string prefix(const connection_options& o) {
    return o.origin.empty() ? std::string() : o.origin + ": ";
  }

  void validate_connections() {
    std::map<std::pair<std::size_t, std::size_t>, const connection*> driven;
    for (const auto& c : conns) {
      const std::string p = prefix(c.options);
      check_variable(c.from, p);
      check_variable(c.to, p);
      const auto& from = var(c.from);
      const auto& to = var(c.to);
      const std::string what = "connection " + full_name(c.from) + " -> " + full_name(c.to);
      if (from.causality != causality::output) {
        throw validation_error(p + what + ": source " + full_name(c.from) + " is " +
                               std::string(to_string(from.causality)) +
                               ", a connection must start at an output");
      }
      if (to.causality != causality::input && to.causality != causality::parameter) {
        throw validation_error(p + what + ": target " + full_name(c.to) + " is " +
                               std::string(to_string(to.causality)) +
                               ", a connection must end at an input or a parameter");
      }
      if (to.causality == causality::parameter && to.variability == variability::constant) {
        throw validation_error(p + what + ": target is a constant");
      }
      if (exchange_type(from.type) != exchange_type(to.type)) {
        throw validation_error(p + what + ": type mismatch, " + full_name(c.from) + " is " +
                               std::string(to_string(from.type)) + " but " + full_name(c.to) +
                               " is " + std::string(to_string(to.type)));
      }
      if (!from.unit.empty() && !to.unit.empty() && from.unit != to.unit) {
        warn(p + what + ": unit mismatch, '" + from.unit + "' -> '" + to.unit +
             "' (values are passed unconverted)");
      }
      const auto key = std::make_pair(c.to.component, c.to.variable);
      if (auto [it, inserted] = driven.emplace(key, &c); !inserted) {
        const auto& first = *it->second;
        throw validation_error(
            p + "input " + full_name(c.to) + " is driven twice: by " + full_name(first.from) +
            (first.options.origin.empty() ? "" : " (" + first.options.origin + ")") + " and by " +
            full_name(c.from));
      }
    }
  }

  // direct-feedthrough loops over non-delayed connections, spelled out
  void check_algebraic_loops() const {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> node_of;
    std::vector<variable_id> nodes;
    auto node = [&](variable_id id) {
      auto [it, inserted] =
          node_of.emplace(std::make_pair(id.component, id.variable), nodes.size());
      if (inserted) nodes.push_back(id);
      return it->second;
    };
    struct edge {
      std::size_t to;
      const connection* via;  // nullptr: feedthrough inside a component
    };
    std::vector<std::vector<edge>> adjacency;
    auto add_edge = [&](std::size_t a, std::size_t b, const connection* via) {
      if (adjacency.size() < nodes.size()) adjacency.resize(nodes.size());
      adjacency[a].push_back({b, via});
    };
    std::vector<const connection*> live;
    for (const auto& c : conns) {
      if (!c.options.delayed) live.push_back(&c);
    }
    for (const auto* c : live) {
      const std::size_t from = node(c->from);
      const std::size_t to = node(c->to);
      add_edge(from, to, c);
    }
    // feedthrough edges: connected input → connected output of the same component
    for (const auto* in : live) {
      if (var(in->to).causality != causality::input) continue;
      const auto& md = entries[in->to.component].c->model_description();
      for (const auto* out : live) {
        if (out->from.component != in->to.component) continue;
        if (md.has_feedthrough(out->from.variable, in->to.variable)) {
          add_edge(node(in->to), node(out->from), nullptr);
        }
      }
    }
    adjacency.resize(nodes.size());

    // iterative DFS; a grey successor closes a cycle
    std::vector<int> colour(nodes.size(), 0);
    std::vector<std::pair<std::size_t, std::size_t>> stack;  // node, next edge
    std::vector<const connection*> via_stack;
    for (std::size_t root = 0; root < nodes.size(); ++root) {
      if (colour[root] != 0) continue;
      stack.push_back({root, 0});
      colour[root] = 1;
      while (!stack.empty()) {
        auto& [n, next] = stack.back();
        if (next == adjacency[n].size()) {
          colour[n] = 2;
          stack.pop_back();
          if (!via_stack.empty()) via_stack.pop_back();
          continue;
        }
        const edge e = adjacency[n][next++];
        if (colour[e.to] == 1) {
          // the cycle is the stack from e.to upwards, closed by e
          std::size_t first = 0;
          while (stack[first].first != e.to) ++first;
          std::vector<std::size_t> cycle;
          std::vector<const connection*> vias;
          for (std::size_t i = first; i < stack.size(); ++i) cycle.push_back(stack[i].first);
          for (std::size_t i = first; i < via_stack.size(); ++i) vias.push_back(via_stack[i]);
          vias.push_back(e.via);
          report_loop(nodes, cycle, vias);
        }
        if (colour[e.to] == 0) {
          colour[e.to] = 1;
          via_stack.push_back(e.via);
          stack.push_back({e.to, 0});
        }
      }
    }
  }

  [[noreturn]] void report_loop(const std::vector<variable_id>& nodes,
                                const std::vector<std::size_t>& cycle,
                                const std::vector<const connection*>& vias) const {
    // start the text at the source of the first-declared connection on the cycle
    std::size_t start = 0;
    for (std::size_t i = 0; i < cycle.size(); ++i) {
      if (vias[i] != nullptr && (vias[start] == nullptr || vias[i] < vias[start])) start = i;
    }
    std::string path;
    std::string origins;
    for (std::size_t k = 0; k < cycle.size(); ++k) {
      const std::size_t i = (start + k) % cycle.size();
      path += full_name(nodes[cycle[i]]);
      path += vias[i] != nullptr ? " -> " : " => ";
      if (vias[i] != nullptr && !vias[i]->options.origin.empty()) {
        origins += (origins.empty() ? "" : ", ") + vias[i]->options.origin;
      }
    }
    path += full_name(nodes[cycle[start]]);
    throw validation_error("algebraic loop through direct feedthrough: " + path +
                           " ('->' connection, '=>' output depends directly on input)" +
                           (origins.empty() ? "" : "; connections at " + origins) +
                           "; mark one connection delay=\"true\" to break the loop");
  }

  // Gauss-Seidel: upstream before downstream; strongly connected groups keep declaration order
  void compute_order() {
    const std::size_t n = entries.size();
    order.clear();
    if (kind == algorithm_kind::jacobi) {
      for (std::size_t i = 0; i < n; ++i) order.push_back(i);
      return;
    }
    std::vector<std::set<std::size_t>> succ(n);
    for (const auto& c : conns) {
      if (!c.options.delayed && c.from.component != c.to.component) {
        succ[c.from.component].insert(c.to.component);
      }
    }
    // Tarjan's strongly connected components (small graphs: recursion is fine)
    std::vector<int> index(n, -1), low(n, 0), scc_of(n, -1);
    std::vector<bool> on_stack(n, false);
    std::vector<std::size_t> st;
    int counter = 0, scc_count = 0;
    std::function<void(std::size_t)> visit = [&](std::size_t v) {
      index[v] = low[v] = counter++;
      st.push_back(v);
      on_stack[v] = true;
      for (std::size_t w : succ[v]) {
        if (index[w] < 0) {
          visit(w);
          low[v] = std::min(low[v], low[w]);
        } else if (on_stack[w]) {
          low[v] = std::min(low[v], index[w]);
        }
      }
      if (low[v] == index[v]) {
        std::size_t w;
        do {
          w = st.back();
          st.pop_back();
          on_stack[w] = false;
          scc_of[w] = scc_count;
        } while (w != v);
        ++scc_count;
      }
    };
    for (std::size_t v = 0; v < n; ++v) {
      if (index[v] < 0) visit(v);
    }
    // Kahn over the condensation, smallest declaration index first
    const auto m = static_cast<std::size_t>(scc_count);
    std::vector<std::vector<std::size_t>> members(m);
    for (std::size_t v = 0; v < n; ++v) members[static_cast<std::size_t>(scc_of[v])].push_back(v);
    std::vector<std::set<std::size_t>> scc_succ(m);
    std::vector<int> indegree(m, 0);
    for (std::size_t v = 0; v < n; ++v) {
      for (std::size_t w : succ[v]) {
        const auto a = static_cast<std::size_t>(scc_of[v]);
        const auto b = static_cast<std::size_t>(scc_of[w]);
        if (a != b && scc_succ[a].insert(b).second) ++indegree[b];
      }
    }
    using item = std::pair<std::size_t, std::size_t>;  // first member, scc
    std::priority_queue<item, std::vector<item>, std::greater<>> ready;
    for (std::size_t s = 0; s < m; ++s) {
      if (indegree[s] == 0) ready.push({members[s].front(), s});
    }
    while (!ready.empty()) {
      const auto s = ready.top().second;
      ready.pop();
      for (std::size_t v : members[s]) order.push_back(v);
      for (std::size_t t : scc_succ[s]) {
        if (--indegree[t] == 0) ready.push({members[t].front(), t});
      }
    }
  }

  template <class T>
  void add_input(entry& e, const connection& c) {
    auto& io = e.io<T>();
    const auto& to = var(c.to);
    const bool init_only =
        to.causality == causality::parameter && to.variability != variability::tunable;
    auto& set = init_only ? io.init_inputs : io.step_inputs;
    set.vrs.push_back(to.reference);
    const std::size_t slot = add_to_cache(c.from);
    set.sources.push_back({c.from.component, slot, c.options.delayed});
    set.values.push_back({});
  }

  void wire_inputs() {
    for (const auto& c : conns) add_to_cache(c.from);
    for (const auto& c : conns) {
      auto& e = entries[c.to.component];
      switch (exchange_type(var(c.to).type)) {
        case variable_type::real:
          add_input<double>(e, c);
          break;
        case variable_type::integer:
          add_input<int>(e, c);
          break;
        case variable_type::boolean:
          add_input<bool>(e, c);
          break;
        case variable_type::string:
          add_input<std::string>(e, c);
          break;
        case variable_type::enumeration:
          break;
      }
    }
  }

  // the value of a source as seen at time `t`: the latest value of its component at a time ≤ t
  template <class T>
  const T& read(const source_ref& s, time_point t) const {
    const auto& e = entries[s.component];
    const auto& cache = e.io<T>().cache;
    return e.time <= t ? cache.latest[s.slot] : cache.published[s.slot];
  }

  template <class T>
  void transfer(entry& e, input_set<T>& set, time_point gs_time, time_point previous) {
    if (set.vrs.empty()) return;
    for (std::size_t i = 0; i < set.vrs.size(); ++i) {
      const auto& s = set.sources[i];
      set.values[i] = read<T>(s, s.delayed ? previous : gs_time);
    }
    component_set<T>(*e.c, set.vrs, set.values.cspan());
  }

  void transfer_all(entry& e, time_point gs_time, time_point previous, bool initializing) {
    transfer(e, e.reals.step_inputs, gs_time, previous);
    transfer(e, e.ints.step_inputs, gs_time, previous);
    transfer(e, e.bools.step_inputs, gs_time, previous);
    transfer(e, e.strings.step_inputs, gs_time, previous);
    if (initializing) {
      transfer(e, e.reals.init_inputs, gs_time, previous);
      transfer(e, e.ints.init_inputs, gs_time, previous);
      transfer(e, e.bools.init_inputs, gs_time, previous);
      transfer(e, e.strings.init_inputs, gs_time, previous);
    }
  }

  static void read_outputs(entry& e) {
    component_get<double>(*e.c, e.reals.cache.vrs, e.reals.cache.latest.span());
    component_get<int>(*e.c, e.ints.cache.vrs, e.ints.cache.latest.span());
    component_get<bool>(*e.c, e.bools.cache.vrs, e.bools.cache.latest.span());
    component_get<std::string>(*e.c, e.strings.cache.vrs, e.strings.cache.latest.span());
  }

  static void publish(entry& e) {
    e.reals.cache.published = e.reals.cache.latest;
    e.ints.cache.published = e.ints.cache.latest;
    e.bools.cache.published = e.bools.cache.latest;
    e.strings.cache.published = e.strings.cache.latest;
  }

  template <class T>
  const T& observed(const observed_variable& v) const {
    const auto& e = entries.at(v.id.component);
    const auto& cache = e.io<T>().cache;
    return e.time <= now ? cache.latest[v.slot] : cache.published[v.slot];
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
};

fixed_step_algorithm::fixed_step_algorithm(duration base_step, algorithm_kind kind, log_sink log)
    : pimpl_(std::make_unique<impl>()) {
  if (base_step <= duration::zero()) {
    throw validation_error("base step must be positive, got " + format_seconds(base_step) + " s");
  }
  pimpl_->step = base_step;
  pimpl_->kind = kind;
  pimpl_->log = log ? std::move(log) : stderr_log_sink();
}

fixed_step_algorithm::~fixed_step_algorithm() {
  terminate_all();
}

std::size_t fixed_step_algorithm::add_component(std::unique_ptr<component> c, int step_multiple) {
  auto& p = *pimpl_;
  if (p.is_frozen) throw validation_error("cannot add a component after freeze()");
  if (!c) throw validation_error("add_component: null component");
  if (step_multiple < 1) {
    throw validation_error("component '" + c->name() + "': step multiple must be >= 1, got " +
                           std::to_string(step_multiple));
  }
  if (find_component(c->name())) {
    throw validation_error("duplicate component name '" + c->name() + "'");
  }
  entry e;
  e.c = std::move(c);
  e.multiple = step_multiple;
  p.entries.push_back(std::move(e));
  return p.entries.size() - 1;
}

void fixed_step_algorithm::connect(variable_id from, variable_id to, connection_options options) {
  if (pimpl_->is_frozen) throw validation_error("cannot connect after freeze()");
  const std::string p = impl::prefix(options);
  pimpl_->check_variable(from, p);
  pimpl_->check_variable(to, p);
  pimpl_->conns.push_back({from, to, std::move(options)});
}

void fixed_step_algorithm::set_start_value(variable_id id, scalar_value value,
                                           const std::string& origin) {
  auto& p = *pimpl_;
  const std::string where = origin.empty() ? std::string() : origin + ": ";
  if (p.is_initialized)
    throw validation_error(where + "cannot set start values after initialize()");
  p.check_variable(id, where);
  const auto& v = p.var(id);
  const std::string name = p.full_name(id);
  if (v.causality != causality::parameter && v.causality != causality::input) {
    throw validation_error(where + name + " is " + std::string(to_string(v.causality)) +
                           "; only parameters and inputs can be given values");
  }
  if (v.variability == variability::constant) {
    throw validation_error(where + name + " is a constant");
  }
  auto& e = p.entries[id.component];
  auto mismatch = [&] {
    throw validation_error(where + name + " is " + std::string(to_string(v.type)) + ", the value " +
                           format_scalar(value) + " has another type");
  };
  switch (exchange_type(v.type)) {
    case variable_type::real:
      if (auto* d = std::get_if<double>(&value)) {
        e.reals.start_vrs.push_back(v.reference);
        e.reals.start_values.push_back(*d);
      } else if (auto* i = std::get_if<int>(&value)) {
        e.reals.start_vrs.push_back(v.reference);
        e.reals.start_values.push_back(*i);
      } else {
        mismatch();
      }
      break;
    case variable_type::integer:
      if (auto* i = std::get_if<int>(&value)) {
        e.ints.start_vrs.push_back(v.reference);
        e.ints.start_values.push_back(*i);
      } else {
        mismatch();
      }
      break;
    case variable_type::boolean:
      if (auto* b = std::get_if<bool>(&value)) {
        e.bools.start_vrs.push_back(v.reference);
        e.bools.start_values.push_back(*b);
      } else {
        mismatch();
      }
      break;
    case variable_type::string:
      if (auto* s = std::get_if<std::string>(&value)) {
        e.strings.start_vrs.push_back(v.reference);
        e.strings.start_values.push_back(*s);
      } else {
        mismatch();
      }
      break;
    case variable_type::enumeration:
      break;
  }
}

observed_variable fixed_step_algorithm::observe(variable_id id) {
  auto& p = *pimpl_;
  if (p.is_initialized) throw validation_error("cannot observe variables after initialize()");
  p.check_variable(id, {});
  const std::size_t slot = p.add_to_cache(id);
  return {id, exchange_type(p.var(id).type), slot};
}

void fixed_step_algorithm::freeze() {
  auto& p = *pimpl_;
  if (p.is_frozen) return;
  if (p.entries.empty()) throw validation_error("the system has no components");
  p.validate_connections();
  if (p.kind == algorithm_kind::gauss_seidel) p.check_algebraic_loops();
  p.compute_order();
  p.wire_inputs();
  // previous values are read only through delays, Jacobi transfer or decimation
  for (auto& e : p.entries) {
    e.needs_published = p.kind == algorithm_kind::jacobi || e.multiple > 1;
  }
  for (const auto& c : p.conns) {
    if (c.options.delayed) p.entries[c.from.component].needs_published = true;
  }
  p.is_frozen = true;
}

bool fixed_step_algorithm::frozen() const noexcept {
  return pimpl_->is_frozen;
}

void fixed_step_algorithm::initialize(time_point start, std::optional<time_point> stop) {
  auto& p = *pimpl_;
  if (p.is_initialized) throw validation_error("initialize() called twice");
  freeze();
  p.start = p.now = start;
  p.steps = 0;
  p.is_initialized = true;
  // setup and start values
  for (auto& e : p.entries) {
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
      component_set<double>(*e.c, e.reals.start_vrs, e.reals.start_values.cspan());
      component_set<int>(*e.c, e.ints.start_vrs, e.ints.start_values.cspan());
      component_set<bool>(*e.c, e.bools.start_vrs, e.bools.start_values.cspan());
      component_set<std::string>(*e.c, e.strings.start_vrs, e.strings.start_values.cspan());
      e.c->enter_initialization();
    });
  }
  // initial value exchange in stepping order, so feedthrough chains settle
  for (auto& e : p.entries) p.guarded(e, start, "initialization", [&] { impl::read_outputs(e); });
  for (std::size_t i : p.order) {
    auto& e = p.entries[i];
    p.guarded(e, start, "initialization", [&] {
      p.transfer_all(e, start, start, true);
      impl::read_outputs(e);
    });
  }
  for (auto& e : p.entries) {
    p.guarded(e, start, "initialization", [&] {
      e.c->exit_initialization();
      impl::read_outputs(e);
    });
    impl::publish(e);
  }
}

step_outcome fixed_step_algorithm::step() {
  auto& p = *pimpl_;
  if (!p.is_initialized) throw validation_error("step() before initialize()");
  if (p.is_terminated) throw validation_error("step() after the simulation ended");
  const time_point t = p.now;
  const time_point next = p.start + (p.steps + 1) * p.step;
  // Jacobi reads every source at t, Gauss-Seidel at the end of the step
  const time_point gs_time = p.kind == algorithm_kind::jacobi ? t : next;
  for (std::size_t i : p.order) {
    auto& e = p.entries[i];
    if (p.steps % e.multiple != 0) continue;
    step_result r = step_result::complete;
    const duration dt = p.step * e.multiple;
    p.guarded(e, t, "step", [&] {
      p.transfer_all(e, gs_time, t, false);
      if (e.needs_published) impl::publish(e);
      r = e.c->do_step(e.time, dt);
    });
    if (r == step_result::terminate) {
      e.terminated = true;
      return {true, i};
    }
    e.time += dt;
    p.guarded(e, t, "step", [&] { impl::read_outputs(e); });
  }
  ++p.steps;
  p.now = next;
  return {};
}

void fixed_step_algorithm::terminate_all() noexcept {
  auto& p = *pimpl_;
  if (!p.is_initialized || p.is_terminated) return;
  p.is_terminated = true;
  for (auto& e : p.entries) {
    try {
      e.c->terminate();
    } catch (const std::exception& ex) {
      p.warn(ex.what());
    }
  }
}

time_point fixed_step_algorithm::current_time() const noexcept {
  return pimpl_->now;
}
std::int64_t fixed_step_algorithm::step_count() const noexcept {
  return pimpl_->steps;
}
duration fixed_step_algorithm::base_step() const noexcept {
  return pimpl_->step;
}
algorithm_kind fixed_step_algorithm::kind() const noexcept {
  return pimpl_->kind;
}
std::size_t fixed_step_algorithm::component_count() const noexcept {
  return pimpl_->entries.size();
}
component& fixed_step_algorithm::component_at(std::size_t index) {
  return *pimpl_->entries.at(index).c;
}
const component& fixed_step_algorithm::component_at(std::size_t index) const {
  return *pimpl_->entries.at(index).c;
}
int fixed_step_algorithm::step_multiple(std::size_t index) const {
  return pimpl_->entries.at(index).multiple;
}
std::optional<std::size_t> fixed_step_algorithm::find_component(
    std::string_view name) const noexcept {
  for (std::size_t i = 0; i < pimpl_->entries.size(); ++i) {
    if (pimpl_->entries[i].c->name() == name) return i;
  }
  return std::nullopt;
}
const std::vector<std::size_t>& fixed_step_algorithm::order() const noexcept {
  return pimpl_->order;
}
const std::vector<connection>& fixed_step_algorithm::connections() const noexcept {
  return pimpl_->conns;
}
std::string fixed_step_algorithm::full_name(variable_id var) const {
  return pimpl_->full_name(var);
}

double fixed_step_algorithm::real_value(const observed_variable& v) const {
  return pimpl_->observed<double>(v);
}
int fixed_step_algorithm::integer_value(const observed_variable& v) const {
  return pimpl_->observed<int>(v);
}
bool fixed_step_algorithm::boolean_value(const observed_variable& v) const {
  return pimpl_->observed<bool>(v);
}
const std::string& fixed_step_algorithm::string_value(const observed_variable& v) const {
  return pimpl_->observed<std::string>(v);
}

}  // namespace stride::cosim
