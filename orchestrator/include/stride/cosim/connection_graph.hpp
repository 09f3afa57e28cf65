// The components' declarations and the connections between them: validation (causality, types,
// units, inputs driven twice, algebraic loops) and the stepping plan that follows from them.
#ifndef STRIDE_COSIM_CONNECTION_GRAPH_HPP
#define STRIDE_COSIM_CONNECTION_GRAPH_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "stride/cosim/log.hpp"
#include "stride/cosim/model_description.hpp"

namespace stride::cosim {

/// A variable of a component of an execution.
struct variable_id {
  std::size_t component = 0;  ///< index returned by execution::add_component
  std::size_t variable = 0;   ///< index into the component's model_description().variables
  friend bool operator==(const variable_id&, const variable_id&) = default;
};

/// Extra information about a connection.
struct connection_options {
  /// the target reads the source value of the previous communication point (breaks loops)
  bool delayed = false;
  /// where the connection was declared ("walk.xml:12"), quoted in error messages
  std::string origin;
  /// the target receives factor × source + offset (Real only); 1 and 0: the value untouched
  double factor = 1.0;
  double offset = 0.0;

  bool transforms() const noexcept { return factor != 1.0 || offset != 0.0; }
};

/// A resolved connection.
struct connection {
  variable_id from;
  variable_id to;
  connection_options options;
};

/// Names and declarations of the components, by index.
struct component_declarations {
  std::vector<std::string> names;
  std::vector<const model_description*> descriptions;

  std::size_t size() const noexcept { return names.size(); }
  const variable_description& variable(variable_id id) const;
  /// "comp.var"
  std::string full_name(variable_id id) const;
};

/// Checks every connection: it starts at an output and ends at an input or a non-constant
/// parameter of the same exchange type, a linear transformation only between Reals, and no
/// input is driven twice; unit mismatches of untransformed connections are warnings. \throws
/// validation_error naming components, variables and connection origins.
void validate_connections(const component_declarations& components,
                          const std::vector<connection>& connections, const log_sink& log);

/// Finds direct-feedthrough loops over non-delayed connections. \throws validation_error that
/// spells the loop out and tells how to break it.
void check_algebraic_loops(const component_declarations& components,
                           const std::vector<connection>& connections);

/// Gauss-Seidel stepping order: upstream (non-delayed) before downstream; components on a
/// feedback cycle keep their declaration order, and among the rest the lowest declaration index
/// goes first.
std::vector<std::size_t> gauss_seidel_order(std::size_t component_count,
                                            const std::vector<connection>& connections);

/// How one macro step may be spread over threads: tasks of components stepped one after the
/// other, and which tasks must have finished before a task may start. Tasks without a path
/// between them share no value within the step and may run concurrently.
struct step_plan {
  std::vector<std::vector<std::size_t>> tasks;       ///< components, in stepping order
  std::vector<std::vector<std::size_t>> successors;  ///< per task: the tasks waiting for it
  std::vector<int> predecessor_count;                ///< per task
};

/// The plan for a stepping order: the strongly connected groups of the non-delayed connections
/// (each kept in `order`), chains of groups merged into one task. With `independent` (Jacobi:
/// every component reads the previous communication point) every component is its own task.
step_plan plan_steps(const std::vector<std::size_t>& order,
                     const std::vector<connection>& connections, bool independent);

/// Components stepped as one unit: each step group is a unit, every other component a unit of
/// its own. Units are numbered in the order of their smallest component index, so that among
/// units the declaration order is kept.
struct step_units {
  std::vector<std::size_t> unit_of;               ///< per component
  std::vector<std::vector<std::size_t>> members;  ///< per unit, ascending
};

/// The units of `groups` (disjoint sets of component indices) among `component_count`.
step_units make_units(std::size_t component_count,
                      const std::vector<std::vector<std::size_t>>& groups);

/// The connections between different units, with unit numbers in place of component indices.
std::vector<connection> connections_between(const step_units& units,
                                            const std::vector<connection>& connections);

/// Which of `groups` may step as one unit under Gauss-Seidel without changing any value: a group
/// may not lie on a same-step cycle (non-delayed connections) through components outside it,
/// since its members would then need values from outside between their own steps. Groups are
/// refused until the others are free of such cycles; the result says, per group, whether kept.
std::vector<bool> steppable_groups(std::size_t component_count,
                                   const std::vector<connection>& connections,
                                   const std::vector<std::vector<std::size_t>>& groups);

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_CONNECTION_GRAPH_HPP
