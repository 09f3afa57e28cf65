// An SSD's tree flattened into a system_structure: components by dotted path, connections
// resolved through system connectors, parameter bindings by the SSP's precedence (docs/ssp.md).
#include <algorithm>
#include <set>

#include "ssp_model.hpp"
#include "stride/common/text.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim::detail::ssp {

const connector* element::find_connector(std::string_view connector_name) const {
  for (const auto& c : connectors) {
    if (c.name == connector_name) return &c;
  }
  return nullptr;
}

const element* element::find_child(std::string_view child_name) const {
  for (const auto& c : children) {
    if (c.name == child_name) return &c;
  }
  return nullptr;
}

namespace {

std::string dotted(const std::string& path, const std::string& name) {
  return path.empty() ? name : path + "." + name;
}

// a connector, wherever it is: a system's connector is one node seen from inside and outside
struct node {
  const element* owner = nullptr;
  const connector* port = nullptr;
  std::string name() const { return dotted(owner->path, port->name); }
  bool component() const { return !owner->system; }
  bool sink() const { return component() && (port->kind == "input" || port->kind == "parameter"); }
  // the declared unit, else (components) the FMU variable's
  std::string unit() const {
    if (!port->unit.empty() || !component()) return port->unit;
    const auto* v = owner->description->find(port->name);
    return v != nullptr ? v->unit : std::string();
  }
};

struct edge {
  std::size_t a = 0, b = 0;  // node indices
  const element::connection* via = nullptr;
};

class connection_graph {
 public:
  explicit connection_graph(const ssd_content& content) : units_(content.units) {
    add(content.top);
    adjacency_.resize(nodes_.size());
    for (std::size_t e = 0; e < edges_.size(); ++e) {
      adjacency_[edges_[e].a].push_back(e);
      if (edges_[e].b != edges_[e].a) adjacency_[edges_[e].b].push_back(e);
    }
  }

  std::vector<connection_spec> connections() const {
    std::vector<connection_spec> out;
    for (std::size_t n = 0; n < nodes_.size(); ++n) {
      if (!nodes_[n].sink()) continue;
      std::vector<route> found;
      std::vector<const edge*> path;
      std::set<std::size_t> visiting{n};
      search(n, path, visiting, found);
      if (found.size() > 1) {
        throw validation_error(found[1].edges.front()->via->origin + nodes_[n].name() +
                               " is driven twice: by " + nodes_[found[0].source].name() + " (" +
                               found[0].edges.front()->via->where.str() + ") and by " +
                               nodes_[found[1].source].name());
      }
      if (found.size() == 1) out.push_back(make(found.front(), n));
    }
    return out;
  }

 private:
  struct route {
    std::size_t source = 0;
    std::vector<const edge*> edges;  // from the sink back to the source
  };

  std::size_t node_of(const element* owner, const std::string& port) {
    const std::string key = dotted(owner->path, port);
    if (const auto it = index_.find(key); it != index_.end()) return it->second;
    index_.emplace(key, nodes_.size());
    nodes_.push_back({owner, owner->find_connector(port)});
    return nodes_.size() - 1;
  }

  void add(const element& system) {
    for (const auto& child : system.children) {
      for (const auto& c : child.connectors) node_of(&child, c.name);
      if (child.system) add(child);
    }
    for (const auto& c : system.connections) {
      const auto end = [&](const std::string& name, const std::string& port) {
        return node_of(name.empty() ? &system : system.find_child(name), port);
      };
      edges_.push_back(
          {end(c.start_element, c.start_connector), end(c.end_element, c.end_connector), &c});
      check_kinds(edges_.back());
    }
  }

  // between two components the data flows from an output into an input or parameter
  void check_kinds(const edge& e) const {
    const node& a = nodes_[e.a];
    const node& b = nodes_[e.b];
    if (!a.component() || !b.component() || a.sink() != b.sink()) return;
    throw validation_error(e.via->origin + "connects " + a.name() + " (" + a.port->kind +
                           ") with " + b.name() + " (" + b.port->kind +
                           "): a connection joins an output and an input or parameter");
  }

  // every component output that reaches sink `at` through system connectors
  void search(std::size_t at, std::vector<const edge*>& path, std::set<std::size_t>& visiting,
              std::vector<route>& found) const {
    for (std::size_t e : adjacency_[at]) {
      const edge& link = edges_[e];
      const std::size_t other = link.a == at ? link.b : link.a;
      if (visiting.contains(other)) continue;
      const node& n = nodes_[other];
      path.push_back(&link);
      if (n.component() && n.port->kind == "calculatedParameter") {
        throw validation_error(link.via->origin + "connections from calculatedParameter " +
                               n.name() + " are not supported (Stride connects outputs)");
      }
      if (n.component() && n.port->kind == "output") found.push_back({other, path});
      if (!n.component()) {
        visiting.insert(other);
        search(other, path, visiting, found);
        visiting.erase(other);
      }
      path.pop_back();
    }
  }

  // the connection of a route: unit conversions and linear transformations hop by hop
  connection_spec make(const route& r, std::size_t sink) const {
    linear_map map;
    bool delayed = false;
    std::size_t at = r.source;
    std::string unit = nodes_[at].unit();
    for (auto it = r.edges.rbegin(); it != r.edges.rend(); ++it) {
      const edge& link = **it;
      const std::size_t next = link.a == at ? link.b : link.a;
      const std::string next_unit = nodes_[next].unit();
      // units an FMU names without the SSD defining them are left to the build's warning
      if (!link.via->suppress_unit_conversion && !unit.empty() && !next_unit.empty() &&
          unit != next_unit && units_.contains(unit) && units_.contains(next_unit)) {
        map = compose(map, unit_conversion(unit, units_.at(unit), next_unit, units_.at(next_unit),
                                           link.via->origin));
      }
      if (!next_unit.empty()) unit = next_unit;
      if (link.via->transform) map = compose(map, *link.via->transform);
      delayed = delayed || link.via->delayed;
      at = next;
    }
    connection_spec c;
    c.from = nodes_[r.source].name();
    c.to = nodes_[sink].name();
    c.factor = map.factor;
    c.offset = map.offset;
    c.delayed = delayed;
    c.where = r.edges.front()->via->where;
    return c;
  }

  const unit_table& units_;
  std::vector<node> nodes_;
  std::map<std::string, std::size_t> index_;
  std::vector<edge> edges_;
  std::vector<std::vector<std::size_t>> adjacency_;
};

// a value a binding gives one variable of one component
struct assignment {
  std::string component;
  parameter_setting setting;
  int depth = 0;
};

class binder {
 public:
  binder(const ssd_content& content, const log_sink& log) : content_(content), log_(log) {}

  std::vector<assignment> assignments() {
    collect(content_.top, 0);
    // deeper bindings first, so that those of enclosing systems win (SSP 1.0)
    std::stable_sort(out_.begin(), out_.end(),
                     [](const assignment& a, const assignment& b) { return a.depth > b.depth; });
    return std::move(out_);
  }

 private:
  void collect(const element& e, int depth) {
    for (const auto& binding : e.bindings) {
      for (const auto& p : binding) bind(e, p.name, p, depth);
    }
    for (const auto& child : e.children) collect(child, depth + 1);
  }

  void bind(const element& e, std::string_view name, const parameter_value& p, int depth) {
    if (e.system) {
      for (const auto& child : e.children) {
        if (name.starts_with(child.name + ".")) {
          return bind(child, name.substr(child.name.size() + 1), p, depth);
        }
      }
      if (e.find_connector(name) != nullptr) {
        throw validation_error(p.origin + "parameterizing the system connector " +
                               dotted(e.path, std::string(name)) + " is not supported");
      }
      return ignore(
          p, "no element of system '" + (e.path.empty() ? e.name : e.path) + "' is named so");
    }
    const variable_description* v = e.description->find(name);
    if (v == nullptr) return ignore(p, "component '" + e.path + "' has no such variable");
    const bool fits = exchange_type(v->type) == exchange_type(p.type);
    if (!fits) {
      throw validation_error(p.origin + "a " + std::string(to_string(p.type)) + " value for " +
                             e.path + "." + v->name + ", which is " +
                             std::string(to_string(v->type)));
    }
    out_.push_back({e.path, {v->name, value_of(e, *v, p), p.where}, depth});
  }

  // the value as text, converted to the variable's unit and transformed as the mapping says
  std::string value_of(const element& e, const variable_description& v,
                       const parameter_value& p) const {
    if (p.type != variable_type::real) return p.value;
    double x = *text::parse_double(p.value);
    bool changed = false;
    const connector* port = e.find_connector(v.name);
    const std::string target = port != nullptr && !port->unit.empty() ? port->unit : v.unit;
    if (p.convert_units && !p.unit.empty() && !target.empty() && p.unit != target) {
      // the value's unit is defined in its parameter set (or the SSD), the target's in the SSD
      const auto defined = [&](const unit_table& first, const std::string& name) -> const unit& {
        if (const auto it = first.find(name); it != first.end()) return it->second;
        if (const auto it = content_.units.find(name); it != content_.units.end()) {
          return it->second;
        }
        throw validation_error(p.origin + "cannot convert from unit \"" + p.unit + "\" into \"" +
                               target + "\" of " + e.path + "." + v.name + ": \"" + name +
                               "\" has no ssc:Unit definition");
      };
      const linear_map m = unit_conversion(p.unit, defined(*p.units, p.unit), target,
                                           defined(content_.units, target), p.origin);
      x = m.factor * x + m.offset;
      changed = true;
    }
    if (p.transform) {
      x = p.transform->factor * x + p.transform->offset;
      changed = true;
    }
    return changed ? text::format_double(x) : p.value;
  }

  void ignore(const parameter_value& p, const std::string& why) const {
    log_(log_level::warning, "stride", "",
         p.origin + "ignored (" + why + "; SSP 1.0 ignores names without a match)");
  }

  const ssd_content& content_;
  const log_sink& log_;
  std::vector<assignment> out_;
};

// The components below `e`; `solver`: the integrator the nearest enclosing system gives its
// Model Exchange components (OMSimulator's solver annotation), which a component's own wins over.
void add_components(const element& e, system_structure& system,
                    const std::optional<model_exchange_options>& solver) {
  for (const auto& child : e.children) {
    if (child.system) {
      add_components(child, system, child.model_exchange ? child.model_exchange : solver);
      continue;
    }
    component_spec& c = system.add_component(child.path, child.fmu, child.step_multiple);
    c.worker = child.worker;
    c.parameters = child.stride_values;  // the bindings (applied next) replace or follow them
    c.where = child.where;
    c.kind = child.kind;
    c.model_exchange = child.model_exchange;
    if (!solver || c.model_exchange) continue;
    if (c.kind == "co-simulation" || !child.description->model_exchange) {
      throw validation_error(child.origin + "the system '" + (e.path.empty() ? e.name : e.path) +
                             "' integrates Model Exchange FMUs (OMSimulator's solver "
                             "annotation), but this component " +
                             (c.kind == "co-simulation" ? "has implementation=\"CoSimulation\""
                                                        : "has an FMU without Model Exchange"));
    }
    c.kind = "model-exchange";
    c.model_exchange = solver;
  }
}

}  // namespace

void flatten(const ssd_content& content, system_structure& system, const log_sink& log) {
  add_components(content.top, system, content.top.model_exchange);
  system.connections = connection_graph(content).connections();
  for (auto& a : binder(content, log).assignments()) {
    component_spec& c = *system.find_component(a.component);
    const auto same = [&](const parameter_setting& s) { return s.variable == a.setting.variable; };
    if (const auto it = std::find_if(c.parameters.begin(), c.parameters.end(), same);
        it != c.parameters.end()) {
      *it = std::move(a.setting);
    } else {
      c.parameters.push_back(std::move(a.setting));
    }
  }
}

}  // namespace stride::cosim::detail::ssp
