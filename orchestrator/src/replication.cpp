// Expansion of replica groups into plain components and connections.
#include <set>
#include <string_view>
#include <vector>

#include "stride/cosim/error.hpp"
#include "stride/cosim/system_structure.hpp"

namespace stride::cosim {

namespace {

// "gait.joint_angle[*]" inside copy k: the member "gait" becomes "gait[k]"
std::string in_copy(const std::string& name, const std::set<std::string>& members, int k) {
  const auto dot = name.find('.');
  const std::string comp = name.substr(0, dot);
  if (!members.contains(comp)) return name;
  return comp + "[" + std::to_string(k) + "]" + (dot == std::string::npos ? "" : name.substr(dot));
}

// "${copy}" → k, "${copy:a;b;c}" → the k-th item; other text unchanged. `what` names the
// attribute in errors ("parameter 'x_move'"), `at` its place in the file.
std::string substitute_copy(const std::string& value, int k, int count, const std::string& what,
                            const source_location& at) {
  static constexpr std::string_view k_open = "${copy";
  std::string out;
  std::string_view rest = value;
  for (auto pos = rest.find(k_open); pos != std::string_view::npos; pos = rest.find(k_open)) {
    out += rest.substr(0, pos);
    rest.remove_prefix(pos + k_open.size());
    const auto close = rest.find('}');
    const std::string place = at.str().empty() ? "" : at.str() + ": ";
    if (close == std::string_view::npos || (close > 0 && rest[0] != ':')) {
      throw validation_error(place + what + ": malformed ${copy} in '" + value +
                             "' (expected ${copy} or ${copy:a;b;...})");
    }
    if (close == 0) {
      out += std::to_string(k);
    } else {
      std::vector<std::string_view> items;
      std::string_view list = rest.substr(1, close - 1);
      for (auto semi = list.find(';');; semi = list.find(';')) {
        items.push_back(list.substr(0, semi));
        if (semi == std::string_view::npos) break;
        list.remove_prefix(semi + 1);
      }
      if (items.size() != static_cast<std::size_t>(count)) {
        throw validation_error(place + what + ": ${copy:...} has " + std::to_string(items.size()) +
                               " values for " + std::to_string(count) + " copies");
      }
      out += items[static_cast<std::size_t>(k - 1)];
    }
    rest.remove_prefix(close + 1);
  }
  out += rest;
  return out;
}

}  // namespace

system_structure on_worker(system_structure system, const std::string& worker) {
  for (auto& c : system.components) {
    if (c.worker.empty()) c.worker = worker;
  }
  for (auto& g : system.groups) {
    for (auto& c : g.components) {
      if (c.worker.empty()) c.worker = worker;
    }
  }
  return system;
}

system_structure expand_replicas(const system_structure& system) {
  system_structure out = system;
  out.groups.clear();
  std::set<std::string> taken;
  for (const auto& c : system.components) taken.insert(c.name);
  for (const auto& g : system.groups) {
    const std::string where = g.where.str().empty() ? "" : g.where.str() + ": ";
    if (g.count < 1) {
      throw validation_error(where + "group '" + g.name + "': count must be at least 1, got " +
                             std::to_string(g.count));
    }
    std::set<std::string> members;
    for (const auto& m : g.components) {
      if (taken.contains(m.name) || !members.insert(m.name).second) {
        throw validation_error(where + "group '" + g.name + "': member name '" + m.name +
                               "' is already used by another component");
      }
    }
    for (int k = 1; k <= g.count; ++k) {
      for (const auto& m : g.components) {
        component_spec copy = m;
        copy.name = m.name + "[" + std::to_string(k) + "]";
        for (auto& p : copy.parameters) {
          p.value = substitute_copy(p.value, k, g.count, "parameter '" + p.variable + "'", p.where);
        }
        // copies may go to different workers: worker="w${copy}"
        copy.worker = substitute_copy(m.worker, k, g.count, "worker of '" + m.name + "'", m.where);
        out.components.push_back(std::move(copy));
      }
      for (const auto& c : g.connections) {
        connection_spec copy = c;
        copy.from = in_copy(c.from, members, k);
        copy.to = in_copy(c.to, members, k);
        out.connections.push_back(std::move(copy));
      }
    }
    taken.insert(members.begin(), members.end());
  }
  return out;
}

}  // namespace stride::cosim
