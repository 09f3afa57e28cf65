// The system description: what the system XML holds, as plain data. The XML parser fills it;
// C++ code can fill it directly and get the same system.
#ifndef STRIDE_COSIM_SYSTEM_STRUCTURE_HPP
#define STRIDE_COSIM_SYSTEM_STRUCTURE_HPP

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stride/cosim/algorithm.hpp"
#include "stride/cosim/model_exchange.hpp"
#include "stride/cosim/time.hpp"

namespace stride::cosim {

class temp_dir;

/// Where a declaration came from, for error messages ("walk.xml:12"); empty when built in code.
struct source_location {
  std::string file;
  int line = 0;
  /// "file:line", "file", or "" — the prefix of error messages.
  std::string str() const;
};

/// A value for a parameter (or the start value of an input).
struct parameter_setting {
  std::string variable;  ///< variable name inside the component
  std::string value;     ///< text, parsed according to the variable's type
  source_location where;
};

/// A component instance.
struct component_spec {
  /// Unique. May hold dots ("engine.pump": a component of a nested SSP system); a "comp.var"
  /// name then means the longest component name that prefixes it.
  std::string name;
  /// A path to an .fmu (relative to the system file's folder), or the bare name of a bundled
  /// FMU ("gait": no '/' and no ".fmu" suffix) looked up in $STRIDE_FMU_PATH and the build's
  /// FMU folder.
  std::string fmu;
  int step_multiple = 1;
  /// Where the component runs: empty = in this process; otherwise the name of a worker
  /// process (placement by the resolvers of build_options).
  std::string worker;
  std::vector<parameter_setting> parameters;
  source_location where;
  /// "co-simulation", "model-exchange", or "" (Co-Simulation when the FMU offers it).
  std::string kind{};
  /// The integrator of a Model Exchange component (solver, method, rtol, atol, max_step).
  std::optional<model_exchange_options> model_exchange = std::nullopt;
};

/// Where the component part of a "comp.var" name ends: at the dot after the longest prefix that
/// `is_component` accepts (component names may hold dots), else at the first dot; npos when
/// the name has no dot.
std::size_t component_end(std::string_view full_name,
                          const std::function<bool(std::string_view)>& is_component);

/// Whether an FMU reference is the bare name of a bundled FMU ("gait": not empty, no '/', no
/// ".fmu" suffix) rather than a path ("x/gait.fmu", "gait.fmu").
bool is_bundled_fmu_name(std::string_view fmu) noexcept;

/// A connection between "comp.var" names. Either side may be a group: "comp.var[*]" (every
/// index present) or "comp.var[1:12]" (an inclusive range); the two sides are paired in
/// ascending index order and must have the same size.
struct connection_spec {
  std::string from;
  std::string to;
  bool delayed = false;  ///< one-step delay: breaks an algebraic loop
  /// The target receives factor × source + offset (Real variables only; SSP linear
  /// transformations and unit conversions). 1 and 0 pass the value on untouched.
  double factor = 1.0;
  double offset = 0.0;
  source_location where;

  /// Whether the value is transformed on its way (factor != 1 or offset != 0).
  bool transforms() const noexcept { return factor != 1.0 || offset != 0.0; }
};

/// What to record.
struct record_spec {
  bool enabled = true;
  std::vector<std::string> signals;  ///< "comp.var" patterns with * and ?; empty = all outputs
  std::vector<source_location> signal_locations;  ///< parallel to `signals` (may be shorter)
  std::optional<duration> interval;               ///< nullopt = every base step
  std::string file = "results.csv";               ///< relative to the run's output folder
  source_location where;
};

/// Several agents: the whole system run `count` times at once, each copy a run of its own with
/// its own clock (docs/swarm.md). Copies share only what their components share through
/// `${shared_table}`, merged as `synchronous` says.
struct agents_spec {
  int count = 0;  ///< 0: no <agents> (one run)
  bool synchronous = true;
  /// Agent k runs on worker `workers[(k - 1) % size]` (its components without a worker of their
  /// own); empty: on threads of this process.
  std::vector<std::string> workers;
  source_location where;
};

/// Standby workers that take over the components of a lost worker (docs/failover.md).
struct failover_spec {
  std::vector<std::string> standby;   ///< in the order they are taken; empty: no failover
  std::optional<int> snapshot_every;  ///< steps between state images; nullopt: the default
  source_location where;
};

/// `count` copies of a group of components with their internal connections. Copy k of member
/// "gait" is the component "gait[k]" (k = 1..count); inside the group a member's name means the
/// member of the same copy, other names mean components outside the group. Outside the group,
/// "gait[*].x" (all copies, ascending) or "gait[2:3].x" connect to the copies, e.g. to the
/// elements of an array variable "monitor.x[*]". In a member's parameter values "${copy}" is
/// replaced by k and "${copy:a;b;c}" by the k-th item of the list (one item per copy).
struct replica_group {
  std::string name;
  int count = 1;
  std::vector<component_spec> components;
  std::vector<connection_spec> connections;
  source_location where;
};

/// What an importer of a foreign format found besides the system itself (`stride inspect` shows
/// it; docs/ssp.md).
struct import_notes {
  /// what set the base step and the algorithm, e.g. "libcosim's annotation
  /// (com.opensimulationplatform) at FILE:LINE"; "" when the system file itself or defaults did
  std::string stepping_from;
  /// annotations of other tools that Stride does not read: "TYPE at FILE:LINE"
  std::vector<std::string> ignored_annotations;
  /// the system structure descriptions (.ssd) at the root of an SSP archive or folder
  std::vector<std::string> descriptions;
};

/// A whole system.
struct system_structure {
  std::string name = "system";
  std::string description;
  /// folder against which relative FMU paths are resolved (the system file's folder)
  std::filesystem::path base_dir;
  source_location where;  ///< the system file
  time_point start{};
  std::optional<time_point> stop;
  std::optional<duration> base_step;  ///< nullopt = the smallest DefaultExperiment stepSize
  algorithm_kind algorithm = algorithm_kind::gauss_seidel;
  std::vector<component_spec> components;
  std::vector<connection_spec> connections;
  std::vector<replica_group> groups;  ///< expanded by expand_replicas()
  record_spec record;
  agents_spec agents;
  failover_spec failover;
  /// The folder an archive (.ssp) was extracted into, when the system came from one: its FMU
  /// paths point there, so it lives as long as any copy of the structure.
  std::shared_ptr<const temp_dir> extracted;
  import_notes notes;

  /// Convenience for C++ callers; each returns the added element.
  component_spec& add_component(std::string name, std::string fmu, int step_multiple = 1);
  connection_spec& connect(std::string from, std::string to, bool delayed = false);
  /// Sets (or replaces) "comp.var" = value; "gait.var" for a group member sets it in every
  /// copy. \throws validation_error for an unknown component, a single copy ("gait[2].var") or a
  /// name without a dot.
  void set(const std::string& full_name, std::string value, source_location where = {});
  component_spec* find_component(std::string_view name) noexcept;
};

/// The system with every replica group replaced by its copies (components "member[k]" after the
/// system's own components, in group order, copy by copy) and their internal connections.
/// \throws validation_error naming the group for a count below 1 or a member name that is
/// already a component.
system_structure expand_replicas(const system_structure& system);

/// The system with every component (replica group members included) that names no worker of its
/// own placed on `worker`: one agent or sweep point on one worker process.
system_structure on_worker(system_structure system, const std::string& worker);

/// Applies a command-line override "comp.var=value" via system_structure::set.
/// \throws validation_error if the text has no '=' or names no component.
void apply_override(system_structure& system, const std::string& assignment);

/// Reads a system XML file (Stride's own format only; load_system_file() in system_import.hpp
/// reads any format). \throws validation_error naming the file and line.
system_structure parse_system_file(const std::filesystem::path& file);
/// Reads system XML held in memory; `file` names it in messages and gives the base folder.
system_structure parse_system_text(std::string_view xml, const std::filesystem::path& file);
/// Writes a system as XML that parse_system_text reads back to the same structure. Bundled
/// FMU names stay names; relative FMU paths are made absolute when `absolute_fmu_paths`.
std::string to_xml(const system_structure& system, bool absolute_fmu_paths = true);

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_SYSTEM_STRUCTURE_HPP
