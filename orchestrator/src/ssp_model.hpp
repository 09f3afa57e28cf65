// The SSP importer's view of an SSD (docs/ssp.md): the system tree as read, before it is
// flattened into a system_structure. Shared by the reader (ssp_import.cpp), the parameter
// files (ssp_parameters.cpp) and the flattening of connections and bindings (ssp_flatten.cpp).
#ifndef STRIDE_COSIM_SRC_SSP_MODEL_HPP
#define STRIDE_COSIM_SRC_SSP_MODEL_HPP

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "import_xml.hpp"
#include "stride/cosim/model_description.hpp"
#include "stride/cosim/system_structure.hpp"

namespace stride::cosim::detail::ssp {

/// target = factor × source + offset
struct linear_map {
  double factor = 1.0;
  double offset = 0.0;
};

/// `first`, then `then`.
linear_map compose(const linear_map& first, const linear_map& then);

/// An ssc:Unit: SI exponents (kg m s A K mol cd rad) and value_SI = factor × value + offset.
struct unit {
  std::array<int, 8> exponents{};
  double factor = 1.0;
  double offset = 0.0;
};
using unit_table = std::map<std::string, unit, std::less<>>;

/// Reads the ssc:Unit children of a Units element into `units`.
void read_units(const xml_file& file, const tinyxml2::XMLElement& e, unit_table& units);

/// The conversion of values in unit `from_name` (`from`) into unit `to_name` (`to`).
/// \throws validation_error with `where` when their SI base units differ.
linear_map unit_conversion(const std::string& from_name, const unit& from,
                           const std::string& to_name, const unit& to, const std::string& where);

/// An ssc:LinearTransformation, BooleanMappingTransformation or IntegerMappingTransformation.
struct transformation {
  enum class kind { linear, boolean_map, integer_map } what = kind::linear;
  linear_map linear;
  std::map<std::string, std::string> table;  ///< source → target values (mapping kinds)
};

/// Reads a transformation element (ssc namespace); `allowed_maps` false refuses the mapping
/// kinds (connections carry linear transformations only).
transformation read_transformation(const xml_file& file, const tinyxml2::XMLElement& e,
                                   bool allowed_maps);

/// Walks the children of an element that holds at most one transformation (rank 0) before the
/// `others`; `visit` (may be empty) gets the others. Returns the transformation, if any.
std::optional<transformation> read_transformed(
    const xml_file& file, const tinyxml2::XMLElement& e, bool allowed_maps,
    const std::vector<child_rule>& others,
    const std::function<void(const tinyxml2::XMLElement&, std::string_view)>& visit);

/// A connector of a component or system.
struct connector {
  std::string name;
  std::string kind;  ///< input, output, parameter or calculatedParameter
  std::optional<variable_type> type;
  std::string unit;  ///< declared (ssc:Real unit); "" when not
  source_location where;
};

/// One value of a parameter set, its name as the binding resolves it (prefix and mapping done).
struct parameter_value {
  std::string name;
  std::string value;  ///< text, parsed later by the variable's type
  variable_type type = variable_type::real;
  std::string unit;           ///< of a Real value; "" when none
  bool convert_units = true;  ///< false: the mapping suppresses unit conversion
  /// a mapping's linear transformation, applied after any unit conversion (SSP 1.0)
  std::optional<linear_map> transform;
  const unit_table* units = nullptr;  ///< where `unit` is defined (the parameter set's file)
  std::string origin;                 ///< "file:line: <ssv:Parameter name=...>: " for messages
  source_location where;
};

/// A component or a (sub)system of the SSD.
struct element {
  std::string name;  ///< as in the SSD
  std::string path;  ///< the dotted Stride name ("" for the top system)
  bool system = false;
  std::string fmu;        ///< component: the component_spec's fmu text
  std::string worker;     ///< component: Stride's component annotation (placement); "" in process
  int step_multiple = 1;  ///< component: Stride's component annotation
  /// component: "model-exchange" or "co-simulation" from its implementation; "" for any
  std::string kind;
  /// component: its integrator (Stride's component annotation); system: the integrator of its
  /// components (OMSimulator's solver annotation)
  std::optional<model_exchange_options> model_exchange;
  /// component: values from Stride's component annotation (placeholders the run substitutes)
  std::vector<parameter_setting> stride_values;
  const model_description* description = nullptr;  ///< component: its FMU's
  std::vector<connector> connectors;
  /// ParameterBindings in document order, each as the values it supplies
  std::vector<std::vector<parameter_value>> bindings;
  std::vector<element> children;  ///< system: its elements
  struct connection {
    std::string start_element, start_connector, end_element, end_connector;
    bool suppress_unit_conversion = false;
    bool delayed = false;  ///< Stride's connection annotation: a one-step delay
    std::optional<linear_map> transform;
    source_location where;
    std::string origin;  ///< "file:line: <ssd:Connection>: "
  };
  std::vector<connection> connections;  ///< system: its connections
  source_location where;
  std::string origin;

  const connector* find_connector(std::string_view connector_name) const;
  const element* find_child(std::string_view child_name) const;
};

/// Step and algorithm as another tool's annotation gives them (docs/ssp.md, "Other tools'
/// annotations").
struct tool_stepping {
  duration step{};
  algorithm_kind algorithm = algorithm_kind::jacobi;
  std::string source;  ///< "libcosim's annotation (com.opensimulationplatform) at FILE:LINE"
  source_location where;
};

/// libcosim's annotation (type com.opensimulationplatform) of the ssd:DefaultExperiment:
/// osp:Algorithm/osp:FixedStepAlgorithm baseStepSize. nullopt when it names no algorithm.
std::optional<tool_stepping> read_osp_stepping(const xml_file& file,
                                               const tinyxml2::XMLElement& annotation);
/// What OMSimulator's annotation (type org.openmodelica) of an ssd:System says:
/// [oms:Annotations/]oms:SimulationInformation holding oms:FixedStepMaster stepSize (a
/// co-simulation master), or oms:VariableStepSolver / oms:FixedStepSolver (the integrator of
/// the system's Model Exchange FMUs). Both empty when it says neither.
struct oms_simulation {
  std::optional<tool_stepping> master;
  std::optional<model_exchange_options> solver;
};
oms_simulation read_oms_simulation(const xml_file& file, const tinyxml2::XMLElement& annotation);

/// Everything read from one SSD (and the files it refers to).
struct ssd_content {
  element top;
  unit_table units;
  std::optional<time_point> start;
  std::optional<time_point> stop;
  std::optional<duration> step;
  std::optional<algorithm_kind> algorithm;
  std::optional<record_spec> record;  ///< Stride's system annotation; nullopt: the default
  agents_spec agents;                 ///< Stride's system annotation; count 0: one run
  failover_spec failover;             ///< Stride's system annotation; no standby: none
  std::string description;
  std::optional<source_location> stride_annotation;  ///< where Stride's system annotation is
  std::vector<tool_stepping> tool_steppings;         ///< other tools' step and algorithm
  std::vector<std::string> ignored_annotations;      ///< "TYPE at FILE:LINE", in document order
};

/// Sets the base step and algorithm of `s` from `content`: Stride's annotation alone when it is
/// there, else the other tools' annotations (which must agree). \throws validation_error
void take_stepping(const ssd_content& content, system_structure& s);

/// Stride's <Record> (in its system annotation): <record> of the system XML, read exactly.
record_spec read_record_annotation(const xml_file& file, const tinyxml2::XMLElement& e);
/// Stride's <Agents> (in its system annotation): <agents> of the system XML.
agents_spec read_agents_annotation(const xml_file& file, const tinyxml2::XMLElement& e);
/// Stride's <Failover> (in its system annotation): <failover> of the system XML.
failover_spec read_failover_annotation(const xml_file& file, const tinyxml2::XMLElement& e);

/// Stride's component annotation (its stride:Component `s`) into the component `c`: worker,
/// step multiple, integrator and stride:Value values.
void read_component_annotation(const xml_file& file, const tinyxml2::XMLElement& s, element& c);

/// Reads the ParameterBinding children of a ParameterBindings element into `into` (one entry
/// per binding). `base` resolves relative sources; `units` are the SSD's (Real values may name
/// them). Keeps the parameter files' unit tables alive in `keep`.
void read_bindings(const xml_file& file, const tinyxml2::XMLElement& e,
                   std::vector<std::vector<parameter_value>>& into,
                   std::vector<std::unique_ptr<unit_table>>& keep);

/// The components, connections and parameters of `content` as a flat system: components named
/// by their dotted paths, connections resolved through system connectors (their linear
/// transformations and unit conversions folded into factor and offset), bindings applied with
/// the SSP's precedence. Names that match nothing are reported to `log` and ignored (SSP).
void flatten(const ssd_content& content, system_structure& system, const log_sink& log);

}  // namespace stride::cosim::detail::ssp

#endif  // STRIDE_COSIM_SRC_SSP_MODEL_HPP
