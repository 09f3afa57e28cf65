// What a component declares about itself: variables, output dependencies, capabilities.
//
// Mirrors the FMI 2.0 modelDescription.xml; `parse_model_description` is the orchestrator's own
// reader of that file (it does not share code with the FMU SDK, so it also reads foreign FMUs).
#ifndef STRIDE_COSIM_MODEL_DESCRIPTION_HPP
#define STRIDE_COSIM_MODEL_DESCRIPTION_HPP

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stride/fmi2/vocabulary.hpp"

namespace stride::cosim {

/// FMI value reference: the handle of a variable inside one component.
using value_reference = std::uint32_t;

// The FMI attribute vocabulary (stride/fmi2/vocabulary.hpp), under the names libstride uses.
/// Variable base types. Enumeration values are exchanged as integers.
using variable_type = fmi2::value_type;
using fmi2::causality;
using fmi2::initial_kind;  // `none` when the attribute is absent
using fmi2::variability;
/// FMI names of the enumerators ("real" → "Real", "calculated_parameter" → "calculatedParameter").
using fmi2::to_string;

/// Integer and enumeration variables use the same value channel.
constexpr variable_type exchange_type(variable_type t) noexcept {
  return t == variable_type::enumeration ? variable_type::integer : t;
}

/// One scalar variable.
struct variable_description {
  std::string name;
  value_reference reference = 0;
  variable_type type = variable_type::real;
  stride::cosim::causality causality = causality::local;
  stride::cosim::variability variability = variability::continuous;
  initial_kind initial = initial_kind::none;
  std::optional<std::string> start;  ///< the start attribute as written ("2", "true", "stride")
  std::optional<std::string> min;
  std::optional<std::string> max;
  std::string unit;           ///< own unit, or the unit of its declared type; "" if none
  std::string declared_type;  ///< "" if none
  std::string description;
  int line = 0;  ///< line in modelDescription.xml (0 when built in code)
  /// Real/@derivative: index into `variables` of the state this variable is the derivative of.
  std::optional<std::size_t> derivative_of = std::nullopt;
};

/// An output and the variables it depends on (ModelStructure/Outputs).
struct output_dependency {
  std::size_t output = 0;  ///< index into `model_description::variables`
  /// indices into `variables`; std::nullopt when the attribute is absent ("depends on all").
  std::optional<std::vector<std::size_t>> dependencies;
};

/// CoSimulation capability flags.
struct cosim_capabilities {
  std::string model_identifier;
  bool needs_execution_tool = false;
  bool can_handle_variable_communication_step_size = false;
  bool can_interpolate_inputs = false;
  int max_output_derivative_order = 0;
  bool can_run_asynchronuously = false;
  bool can_be_instantiated_only_once_per_process = false;
  bool can_not_use_memory_management_functions = false;
  bool can_get_and_set_fmu_state = false;
  bool can_serialize_fmu_state = false;
  bool provides_directional_derivative = false;
};

/// ModelExchange capability flags.
struct model_exchange_capabilities {
  std::string model_identifier;
  bool needs_execution_tool = false;
  bool completed_integrator_step_not_needed = false;
  bool can_be_instantiated_only_once_per_process = false;
  bool can_not_use_memory_management_functions = false;
  bool can_get_and_set_fmu_state = false;
  bool can_serialize_fmu_state = false;
  bool provides_directional_derivative = false;
};

/// DefaultExperiment; absent attributes stay empty.
struct default_experiment {
  std::optional<double> start_time;
  std::optional<double> stop_time;
  std::optional<double> tolerance;
  std::optional<double> step_size;
};

/// Everything a component declares.
struct model_description {
  std::string fmi_version = "2.0";
  std::string model_name;
  std::string guid;
  std::string description;
  std::string author;
  std::string version;
  std::string generation_tool;
  std::string generation_date_and_time;
  std::optional<cosim_capabilities> co_simulation;  ///< nullopt if the FMU is ModelExchange only
  bool has_model_exchange = false;
  stride::cosim::default_experiment default_experiment;
  std::vector<variable_description> variables;
  std::vector<output_dependency> outputs;
  std::optional<model_exchange_capabilities> model_exchange =
      std::nullopt;  ///< nullopt without <ModelExchange>
  std::size_t number_of_event_indicators = 0;
  /// ModelStructure/Derivatives: indices into `variables` of the state derivatives, in the
  /// order of the continuous-state vector.
  std::vector<std::size_t> derivatives{};

  /// The variable called `name`, or nullptr.
  const variable_description* find(std::string_view name) const noexcept;
  /// Index of the variable called `name` in `variables`, or nullopt.
  std::optional<std::size_t> index_of(std::string_view name) const noexcept;
  /// Whether output `output_index` depends directly on input `input_index` (an absent
  /// dependency list means it depends on every input; an output not listed in ModelStructure
  /// is treated the same way).
  bool has_feedthrough(std::size_t output_index, std::size_t input_index) const noexcept;
};

/// Reads modelDescription.xml. Checks fmiVersion 2.0, a non-empty GUID, unique variable names,
/// well-formed value references, known enumerator names and ModelStructure indices. An FMI 3.0
/// model description (fmiVersion 3.x) is read by the FMI 3.0 reader instead and returned as its
/// scalar ports (one per array element; docs/fmu-interop.md).
/// \throws fmu_import_error naming the file and line.
model_description parse_model_description(const std::filesystem::path& file);
/// Reads a modelDescription.xml held in memory; `origin` names it in error messages.
model_description parse_model_description_text(std::string_view xml, const std::string& origin);
/// Reads the modelDescription.xml of the FMU archive `fmu`, inflating that entry only (no
/// binary is unpacked or loaded); errors name `fmu/modelDescription.xml`.
/// \throws fmu_import_error also for an archive without it at its root.
model_description read_archive_description(const std::filesystem::path& fmu);

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_MODEL_DESCRIPTION_HPP
