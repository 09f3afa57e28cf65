#include "stride/cosim/connection_graph.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <queue>
#include <set>

#include "stride/cosim/error.hpp"

namespace stride::cosim {

const variable_description& component_declarations::variable(variable_id id) const {
  return descriptions.at(id.component)->variables.at(id.variable);
}

std::string component_declarations::full_name(variable_id id) const {
  return names.at(id.component) + "." + variable(id).name;
}

namespace {

std::string prefix(const connection_options& o) {
  return o.origin.empty() ? std::string() : o.origin + ": ";
}

[[noreturn]] void report_loop(const component_declarations& d,
                              const std::vector<variable_id>& nodes,
                              const std::vector<std::size_t>& cycle,
                              const std::vector<const connection*>& vias) {
  // start the text at the source of the first-declared connection on the cycle
  std::size_t start = 0;
  for (std::size_t i = 0; i < cycle.size(); ++i) {
    if (vias[i] != nullptr && (vias[start] == nullptr || vias[i] < vias[start])) start = i;
  }
  std::string path;
  std::string origins;
  for (std::size_t k = 0; k < cycle.size(); ++k) {
    const std::size_t i = (start + k) % cycle.size();
    path += d.full_name(nodes[cycle[i]]);
    path += vias[i] != nullptr ? " -> " : " => ";
    if (vias[i] != nullptr && !vias[i]->options.origin.empty()) {
      origins += (origins.empty() ? "" : ", ") + vias[i]->options.origin;
    }
  }
  path += d.full_name(nodes[cycle[start]]);
  throw validation_error("algebraic loop through direct feedthrough: " + path +
                         " ('->' connection, '=>' output depends directly on input)" +
                         (origins.empty() ? "" : "; connections at " + origins) +
                         "; mark one connection delay=\"true\" to break the loop");
}

// same-step dependencies between components: non-delayed connections
std::vector<std::set<std::size_t>> successors_of(std::size_t n,
                                                 const std::vector<connection>& connections) {
  std::vector<std::set<std::size_t>> succ(n);
  for (const auto& c : connections) {
    if (!c.options.delayed && c.from.component != c.to.component) {
      succ[c.from.component].insert(c.to.component);
    }
  }
  return succ;
}

// Tarjan's strongly connected components (small graphs: recursion is fine); the group of each
// component, groups numbered in reverse topological order
std::vector<std::size_t> strongly_connected(const std::vector<std::set<std::size_t>>& succ,
                                            std::size_t& group_count) {
  const std::size_t n = succ.size();
  std::vector<int> index(n, -1), low(n, 0);
  std::vector<std::size_t> group(n, 0);
  std::vector<bool> on_stack(n, false);
  std::vector<std::size_t> st;
  int counter = 0;
  group_count = 0;
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
        group[w] = group_count;
      } while (w != v);
      ++group_count;
    }
  };
  for (std::size_t v = 0; v < n; ++v) {
    if (index[v] < 0) visit(v);
  }
  return group;
}

}  // namespace

void validate_connections(const component_declarations& d,
                          const std::vector<connection>& connections, const log_sink& log) {
  std::map<std::pair<std::size_t, std::size_t>, const connection*> driven;
  for (const auto& c : connections) {
    const std::string p = prefix(c.options);
    const auto& from = d.variable(c.from);
    const auto& to = d.variable(c.to);
    const std::string what = "connection " + d.full_name(c.from) + " -> " + d.full_name(c.to);
    if (from.causality != causality::output) {
      throw validation_error(p + what + ": source " + d.full_name(c.from) + " is " +
                             std::string(to_string(from.causality)) +
                             ", a connection must start at an output");
    }
    if (to.causality != causality::input && to.causality != causality::parameter) {
      throw validation_error(p + what + ": target " + d.full_name(c.to) + " is " +
                             std::string(to_string(to.causality)) +
                             ", a connection must end at an input or a parameter");
    }
    if (to.causality == causality::parameter && to.variability == variability::constant) {
      throw validation_error(p + what + ": target is a constant");
    }
    if (exchange_type(from.type) != exchange_type(to.type)) {
      throw validation_error(p + what + ": type mismatch, " + d.full_name(c.from) + " is " +
                             std::string(to_string(from.type)) + " but " + d.full_name(c.to) +
                             " is " + std::string(to_string(to.type)));
    }
    if (c.options.transforms() && exchange_type(from.type) != variable_type::real) {
      throw validation_error(p + what + ": a linear transformation (factor, offset) applies to " +
                             "Real variables only, " + d.full_name(c.from) + " is " +
                             std::string(to_string(from.type)));
    }
    // a transformed connection converts on purpose (e.g. the units of an SSP connection)
    if (!c.options.transforms() && !from.unit.empty() && !to.unit.empty() && from.unit != to.unit) {
      if (log)
        log(log_level::warning, "stride", "",
            p + what + ": unit mismatch, '" + from.unit + "' -> '" + to.unit +
                "' (values are passed unconverted)");
    }
    const auto key = std::make_pair(c.to.component, c.to.variable);
    if (auto [it, inserted] = driven.emplace(key, &c); !inserted) {
      const auto& first = *it->second;
      throw validation_error(
          p + "input " + d.full_name(c.to) + " is driven twice: by " + d.full_name(first.from) +
          (first.options.origin.empty() ? "" : " (" + first.options.origin + ")") + " and by " +
          d.full_name(c.from));
    }
  }
}

void check_algebraic_loops(const component_declarations& d,
                           const std::vector<connection>& connections) {
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> node_of;
  std::vector<variable_id> nodes;
  auto node = [&](variable_id id) {
    auto [it, inserted] = node_of.emplace(std::make_pair(id.component, id.variable), nodes.size());
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
  for (const auto& c : connections) {
    if (!c.options.delayed) live.push_back(&c);
  }
  for (const auto* c : live) {
    const std::size_t from = node(c->from);
    const std::size_t to = node(c->to);
    add_edge(from, to, c);
  }
  // feedthrough edges: connected input → connected output of the same component
  for (const auto* in : live) {
    if (d.variable(in->to).causality != causality::input) continue;
    const auto& md = *d.descriptions[in->to.component];
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
        report_loop(d, nodes, cycle, vias);
      }
      if (colour[e.to] == 0) {
        colour[e.to] = 1;
        via_stack.push_back(e.via);
        stack.push_back({e.to, 0});
      }
    }
  }
}

std::vector<std::size_t> gauss_seidel_order(std::size_t n,
                                            const std::vector<connection>& connections) {
  const auto succ = successors_of(n, connections);
  std::size_t m = 0;
  const auto scc_of = strongly_connected(succ, m);
  // Kahn over the condensation, smallest declaration index first
  std::vector<std::vector<std::size_t>> members(m);
  for (std::size_t v = 0; v < n; ++v) members[scc_of[v]].push_back(v);
  std::vector<std::set<std::size_t>> scc_succ(m);
  std::vector<int> indegree(m, 0);
  for (std::size_t v = 0; v < n; ++v) {
    for (std::size_t w : succ[v]) {
      const std::size_t a = scc_of[v], b = scc_of[w];
      if (a != b && scc_succ[a].insert(b).second) ++indegree[b];
    }
  }
  using item = std::pair<std::size_t, std::size_t>;  // first member, scc
  std::priority_queue<item, std::vector<item>, std::greater<>> ready;
  for (std::size_t s = 0; s < m; ++s) {
    if (indegree[s] == 0) ready.push({members[s].front(), s});
  }
  std::vector<std::size_t> order;
  while (!ready.empty()) {
    const auto s = ready.top().second;
    ready.pop();
    for (std::size_t v : members[s]) order.push_back(v);
    for (std::size_t t : scc_succ[s]) {
      if (--indegree[t] == 0) ready.push({members[t].front(), t});
    }
  }
  return order;
}

step_plan plan_steps(const std::vector<std::size_t>& order,
                     const std::vector<connection>& connections, bool independent) {
  const std::size_t n = order.size();
  step_plan plan;
  if (independent) {
    for (std::size_t i : order) plan.tasks.push_back({i});
    plan.successors.resize(n);
    plan.predecessor_count.assign(n, 0);
    return plan;
  }
  const auto succ = successors_of(n, connections);
  std::size_t m = 0;
  const auto group = strongly_connected(succ, m);
  // one task per group, members in stepping order; tasks numbered by first appearance
  std::vector<std::size_t> task_of_group(m, m);
  std::vector<std::size_t> task_of(n);
  for (std::size_t v : order) {
    std::size_t& t = task_of_group[group[v]];
    if (t == m) {
      t = plan.tasks.size();
      plan.tasks.emplace_back();
    }
    plan.tasks[t].push_back(v);
    task_of[v] = t;
  }
  std::vector<std::set<std::size_t>> next(plan.tasks.size()), prev(plan.tasks.size());
  for (std::size_t v = 0; v < n; ++v) {
    for (std::size_t w : succ[v]) {
      if (task_of[v] != task_of[w]) {
        next[task_of[v]].insert(task_of[w]);
        prev[task_of[w]].insert(task_of[v]);
      }
    }
  }
  // merge chains: a task whose only successor has it as its only predecessor absorbs it
  std::vector<bool> absorbed(plan.tasks.size(), false);
  for (std::size_t a = 0; a < plan.tasks.size(); ++a) {
    if (absorbed[a]) continue;
    while (next[a].size() == 1) {
      const std::size_t b = *next[a].begin();
      if (prev[b].size() != 1) break;
      plan.tasks[a].insert(plan.tasks[a].end(), plan.tasks[b].begin(), plan.tasks[b].end());
      next[a] = next[b];
      for (std::size_t c : next[b]) {
        prev[c].erase(b);
        prev[c].insert(a);
      }
      absorbed[b] = true;
    }
  }
  std::vector<std::size_t> renumber(plan.tasks.size());
  std::vector<std::vector<std::size_t>> tasks;
  for (std::size_t t = 0; t < plan.tasks.size(); ++t) {
    if (absorbed[t]) continue;
    renumber[t] = tasks.size();
    tasks.push_back(std::move(plan.tasks[t]));
  }
  plan.successors.assign(tasks.size(), {});
  plan.predecessor_count.assign(tasks.size(), 0);
  for (std::size_t t = 0; t < next.size(); ++t) {
    if (absorbed[t]) continue;
    for (std::size_t s : next[t]) {
      plan.successors[renumber[t]].push_back(renumber[s]);
      ++plan.predecessor_count[renumber[s]];
    }
  }
  plan.tasks = std::move(tasks);
  return plan;
}

step_units make_units(std::size_t n, const std::vector<std::vector<std::size_t>>& groups) {
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> group_of(n, none);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    for (std::size_t c : groups[g]) {
      if (c >= n || group_of[c] != none) {
        throw validation_error("step groups: component " + std::to_string(c) +
                               " is not a component or is in two groups");
      }
      group_of[c] = g;
    }
  }
  step_units u;
  u.unit_of.assign(n, none);
  std::vector<std::size_t> unit_of_group(groups.size(), none);
  for (std::size_t c = 0; c < n; ++c) {
    if (group_of[c] == none) {
      u.unit_of[c] = u.members.size();
      u.members.push_back({c});
      continue;
    }
    std::size_t& unit = unit_of_group[group_of[c]];
    if (unit == none) {
      unit = u.members.size();
      u.members.emplace_back();
    }
    u.unit_of[c] = unit;
    u.members[unit].push_back(c);
  }
  return u;
}

std::vector<connection> connections_between(const step_units& units,
                                            const std::vector<connection>& connections) {
  std::vector<connection> result;
  for (const auto& c : connections) {
    const std::size_t from = units.unit_of.at(c.from.component);
    const std::size_t to = units.unit_of.at(c.to.component);
    if (from == to) continue;
    connection between = c;
    between.from.component = from;
    between.to.component = to;
    result.push_back(std::move(between));
  }
  return result;
}

std::vector<bool> steppable_groups(std::size_t n, const std::vector<connection>& connections,
                                   const std::vector<std::vector<std::size_t>>& groups) {
  std::vector<bool> kept(groups.size(), true);
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<std::vector<std::size_t>> candidates;
    std::vector<std::size_t> position;  // candidate → index in groups
    for (std::size_t g = 0; g < groups.size(); ++g) {
      if (kept[g]) {
        candidates.push_back(groups[g]);
        position.push_back(g);
      }
    }
    const step_units units = make_units(n, candidates);
    const auto succ = successors_of(units.members.size(), connections_between(units, connections));
    std::size_t count = 0;
    const auto scc = strongly_connected(succ, count);
    std::vector<std::size_t> size(count, 0);
    for (std::size_t u = 0; u < units.members.size(); ++u) ++size[scc[u]];
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      if (size[scc[units.unit_of[candidates[k].front()]]] > 1) {
        kept[position[k]] = false;
        changed = true;
      }
    }
  }
  return kept;
}

}  // namespace stride::cosim
