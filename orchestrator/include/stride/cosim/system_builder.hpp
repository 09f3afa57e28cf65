// Turns a system_structure into a frozen, ready-to-run execution.
#ifndef STRIDE_COSIM_SYSTEM_BUILDER_HPP
#define STRIDE_COSIM_SYSTEM_BUILDER_HPP

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stride/cosim/execution.hpp"
#include "stride/cosim/fmu.hpp"
#include "stride/cosim/log.hpp"
#include "stride/cosim/placement.hpp"
#include "stride/cosim/system_structure.hpp"

namespace stride::cosim {

/// The data folder of an installed Stride, `<prefix>/share/stride` for a program running as
/// `<prefix>/bin/<program>`; empty when the running program is not installed that way.
std::filesystem::path installed_data_dir();

/// The folders searched for bundled FMUs: each entry of $STRIDE_FMU_PATH (':'-separated), then
/// the installed FMU folder (installed_data_dir()/fmus) when there is one, else the build's FMU
/// folder (STRIDE_FMU_OUTPUT_DIR): an installed program never picks FMUs from a build tree.
std::vector<std::filesystem::path> default_fmu_search_path();

/// Resolves `component.fmu` to an existing file. \throws validation_error naming the system
/// file and line, and every place searched.
std::filesystem::path resolve_fmu(const component_spec& component, const system_structure& system,
                                  const std::vector<std::filesystem::path>& search_path);

struct build_options {
  std::vector<std::filesystem::path> fmu_search_path = default_fmu_search_path();
  /// Tried in order for every component; then in-process FMU import for the components
  /// without a `worker`. A component that no resolver takes is an error.
  std::vector<std::shared_ptr<placement_resolver>> placements;
  fmu_import_options import;
  log_sink log;  ///< component and validation messages; empty = stderr
  bool fmu_debug_logging = false;
  /// Threads for stepping independent components concurrently (results do not depend on it).
  int threads = 1;
};

/// Per-component facts for reports and manifests.
struct component_info {
  std::string name;
  std::filesystem::path fmu;  ///< resolved file; empty for factory-made components
  std::string guid;
  std::string model_name;
  std::string generation_tool;
  int step_multiple = 1;
  std::string worker;  ///< where it runs; empty = this process
};

/// A built system.
struct built_system {
  std::unique_ptr<stride::cosim::execution> execution;
  std::vector<component_info> components;
  /// the components that step together on their worker (indices into `components`)
  std::vector<std::vector<std::size_t>> groups;
  duration base_step{};
  time_point start{};
  time_point stop{};
};

/// The base step `system` runs at: its own, else the smallest positive DefaultExperiment
/// stepSize of `models` (its components' FMUs); nullopt when there is neither.
std::optional<duration> base_step_of(const system_structure& system,
                                     const std::vector<const model_description*>& models);

/// Expands replica groups, creates the components where their specs place them, applies
/// parameters, expands and checks connections, freezes the execution.
/// The stop time must be set (`system.stop`) and (stop - start) must be a whole number of base
/// steps. \throws validation_error / fmu_import_error / component_error naming file and line.
built_system build_system(const system_structure& system, const build_options& options = {});

/// The components that step together on their worker: the sets (two or more, indices
/// ascending) of components with the same `workers[i]` (empty: this process, never grouped)
/// connected to each other, except those that may not step as one unit
/// (steppable_groups(), Gauss-Seidel only) and those joined by a connection with a factor or
/// offset (a group's links carry values as they are). Valid before and after freeze().
std::vector<std::vector<std::size_t>> worker_groups(const execution& ex,
                                                    const std::vector<std::string>& workers,
                                                    algorithm_kind kind);

/// The indices into `names` (component names) of the components a connection side names:
/// "comp", or the copies "comp[*]" / "comp[2:3]" of a replica group, in ascending copy index.
/// \throws validation_error (`context` prefixed) when none or not all of them exist.
std::vector<std::size_t> expand_component_group(const std::vector<std::string>& names,
                                                const std::string& comp,
                                                const std::string& context);

/// Expands the variable part of a connection side ("var", "var[*]", "var[2:5]") into variable
/// indices of `md`, in ascending index order. \throws validation_error.
std::vector<std::size_t> expand_variable_group(const model_description& md,
                                               std::string_view variable_pattern,
                                               const std::string& context);

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_SYSTEM_BUILDER_HPP
