#include <algorithm>
#include <array>
#include <stdexcept>

#include "reporter.hpp"
#include "stride/fmi_check/fmu_check.hpp"

namespace stride::fmi_check {

namespace {

constexpr std::array k_rules{
    // docs/fmi-rules.md §2.1 archive
    rule_description{"archive.open",
                     "the file is a readable ZIP archive; every entry decompresses, CRC ok"},
    rule_description{"archive.extension", "the file name ends in .fmu (warning)"},
    rule_description{"archive.format",
                     "no ZIP64, split or spanned archive; version needed to extract <= 2.0"},
    rule_description{"archive.compression", "every entry is stored (0) or deflated (8)"},
    rule_description{"archive.encryption", "no entry is encrypted"},
    rule_description{"archive.link", "no entry is a symbolic link"},
    rule_description{"archive.backslash", "entry names use forward slashes only"},
    rule_description{"archive.path", "no absolute entry names, no '..' components"},
    rule_description{"archive.duplicate_entry", "no entry name occurs twice"},
    rule_description{"archive.name_ascii", "entry names are ASCII (warning)"},
    rule_description{"archive.model_description", "modelDescription.xml is at the archive root"},
    rule_description{"archive.binary",
                     "binaries/linux64/<modelIdentifier>.so is present, for each interface "
                     "element's modelIdentifier"},
    rule_description{"archive.platform_dir",
                     "no FMI 3 platform tuple (x86_64-linux, ...) for a platform FMI 2 names"},
    // docs/fmi-rules.md §2.2 modelDescription.xml
    rule_description{"xml.well_formed", "modelDescription.xml is well-formed XML"},
    rule_description{"schema.attribute", "no attribute the FMI 2.0 schema does not define"},
    rule_description{"root.element", "the root element is fmiModelDescription"},
    rule_description{"root.fmi_version", "fmiVersion is \"2.0\""},
    rule_description{"root.model_name", "modelName is given"},
    rule_description{"root.guid", "guid is given and not empty"},
    rule_description{"root.generation_date", "generationDateAndTime is an xs:dateTime"},
    rule_description{"root.attribute_value",
                     "variableNamingConvention is flat|structured, numberOfEventIndicators "
                     "unsigned"},
    rule_description{"structure.child_order",
                     "child elements are known, unique and in the order of the XSD sequence"},
    rule_description{"structure.model_structure", "the ModelStructure element is present"},
    rule_description{"cosim.missing", "a CoSimulation or a ModelExchange element is present"},
    rule_description{"cosim.model_identifier", "CoSimulation@modelIdentifier is a C identifier"},
    rule_description{"cosim.flag",
                     "capability flags are xs:boolean, maxOutputDerivativeOrder "
                     "unsigned"},
    rule_description{"me.model_identifier", "ModelExchange@modelIdentifier is a C identifier"},
    rule_description{"me.flag", "ModelExchange capability flags are xs:boolean"},
    rule_description{"type_definitions.name", "SimpleType names are given and unique"},
    rule_description{"log_categories.name", "every Category has a name"},
    rule_description{"log_categories.unique", "Category names are unique"},
    rule_description{"default_experiment.value", "DefaultExperiment attributes are numbers"},
    rule_description{"default_experiment.interval", "startTime < stopTime"},
    rule_description{"default_experiment.step_size", "stepSize > 0"},
    rule_description{"default_experiment.tolerance", "tolerance > 0"},
    rule_description{"variables.empty", "ModelVariables is present with at least one variable"},
    rule_description{"variable.name", "every ScalarVariable has a non-empty name"},
    rule_description{"variable.name_unique", "variable names are unique"},
    rule_description{"variable.value_reference", "valueReference is an xs:unsignedInt"},
    rule_description{"variable.type",
                     "exactly one type child Real|Integer|Boolean|String|Enumeration; "
                     "Enumeration has declaredType"},
    rule_description{"variable.declared_type",
                     "declaredType names a SimpleType of the same base type"},
    rule_description{"variable.causality", "causality is a legal value"},
    rule_description{"variable.variability", "variability is a legal value"},
    rule_description{"variable.causality_variability",
                     "the causality x variability combination is allowed by the spec table"},
    rule_description{"variable.initial",
                     "initial is a legal value and allowed for the causality x variability"},
    rule_description{"variable.start_required",
                     "start is given for initial exact|approx, inputs and constants"},
    rule_description{"variable.start_forbidden",
                     "no start for initial calculated or causality independent"},
    rule_description{"variable.value", "start/min/max/nominal parse as the variable's type"},
    rule_description{"variable.continuous_non_real", "only Real variables are continuous"},
    rule_description{"variable.range", "min <= max and min <= start <= max"},
    rule_description{"variable.independent", "at most one independent variable, and it is a Real"},
    rule_description{"variable.derivative",
                     "Real@derivative is the 1-based index of a Real variable"},
    rule_description{"variable.alias_start",
                     "of the non-constant variables sharing valueReference and type, at most "
                     "one has start"},
    rule_description{"variable.array_index",
                     "array elements name[i] of a group start at 1 and are contiguous "
                     "(warning)"},
    rule_description{"outputs.index", "Outputs/Unknown@index is a 1-based index in range"},
    rule_description{"outputs.missing", "every output variable is listed in Outputs"},
    rule_description{"outputs.not_output", "Outputs lists only output variables"},
    rule_description{"outputs.order", "Outputs follows ModelVariables order, no duplicates"},
    rule_description{"derivatives.index",
                     "Derivatives/Unknown@index is in range and names a Real with derivative"},
    rule_description{"dependencies.index", "dependencies are 1-based indices in range"},
    rule_description{"dependencies.order", "dependencies are sorted ascending without duplicates"},
    rule_description{"dependencies.kind", "dependenciesKind has one legal kind per dependency"},
    rule_description{"initial_unknowns.index",
                     "InitialUnknowns/Unknown@index is a 1-based index in range"},
    rule_description{"initial_unknowns.missing",
                     "InitialUnknowns lists every output with initial approx|calculated, every "
                     "calculatedParameter (and states/derivatives)"},
    rule_description{"initial_unknowns.extra", "InitialUnknowns lists nothing else"},
    rule_description{"initial_unknowns.order",
                     "InitialUnknowns is sorted by index without duplicates"},
    rule_description{"initial_unknowns.kind",
                     "InitialUnknowns dependenciesKind is dependent|constant only"},
    // docs/fmi-rules.md §2.5 Model Exchange (only with a ModelExchange element)
    rule_description{"me.derivative_continuous", "every variable in Derivatives is continuous"},
    rule_description{"me.state",
                     "the state a listed derivative names is continuous and no (calculated) "
                     "parameter"},
    rule_description{"me.state_unique", "each state has one derivative in Derivatives"},
    rule_description{"me.derivative_unlisted",
                     "Derivatives lists every derivative attribute not tied to an input"},
    rule_description{"me.reinit", "only continuous states have reinit"},
    // docs/fmi3-rules.md §8 FMI 3.0: archive and binary
    rule_description{"fmi3.archive.platform_dir",
                     "no FMI 2.0 platform folder (linux64, win64, ...) in an FMI 3.0 FMU"},
    rule_description{"fmi3.archive.binary",
                     "binaries/x86_64-linux/<modelIdentifier>.so is present"},
    rule_description{"fmi3.exports.elf",
                     "the binary is a readable x86-64 ELF shared object with a .dynsym"},
    rule_description{"fmi3.exports.functions",
                     "the binary exports every fmi3* function of the C API, as functions"},
    // docs/fmi3-rules.md §8 FMI 3.0: modelDescription.xml
    rule_description{"fmi3.root.fmi_version", "fmiVersion is \"3.0\" (or 3.0.x)"},
    rule_description{"fmi3.root.model_name", "modelName is given"},
    rule_description{"fmi3.root.instantiation_token", "instantiationToken is given and not empty"},
    rule_description{"fmi3.root.naming_convention", "variableNamingConvention is flat|structured"},
    rule_description{"fmi3.interface.missing",
                     "a CoSimulation or ModelExchange element is present"},
    rule_description{"fmi3.interface.not_usable",
                     "ScheduledExecution is not usable by Stride (warning)"},
    rule_description{"fmi3.interface.model_identifier",
                     "every interface element has a modelIdentifier that is a C identifier"},
    rule_description{"fmi3.interface.flag",
                     "interface flags are xs:boolean or unsigned; fixedInternalStepSize > 0; "
                     "canSerializeFMUState needs canGetAndSetFMUState"},
    rule_description{"fmi3.unit.name", "Unit and DisplayUnit names are given and unique"},
    rule_description{"fmi3.type_definitions.name", "type definition names are given and unique"},
    rule_description{"fmi3.variables.empty",
                     "ModelVariables is present with at least one variable"},
    rule_description{"fmi3.variable.type",
                     "each variable element is "
                     "Float32|Float64|Int8..UInt64|Boolean|String|Binary|Enumeration|Clock"},
    rule_description{"fmi3.variable.name", "every variable has a non-empty name"},
    rule_description{"fmi3.variable.name_unique", "variable names are unique"},
    rule_description{"fmi3.variable.value_reference", "valueReference is an xs:unsignedInt"},
    rule_description{"fmi3.variable.value_reference_unique",
                     "value references are unique (no aliases by valueReference)"},
    rule_description{"fmi3.variable.causality",
                     "causality is a legal value (structuralParameter included)"},
    rule_description{"fmi3.variable.variability", "variability is a legal value"},
    rule_description{"fmi3.variable.causality_variability",
                     "the causality x variability combination is allowed by the spec table"},
    rule_description{"fmi3.variable.initial",
                     "initial is a legal value and allowed for the causality x variability"},
    rule_description{"fmi3.variable.continuous_non_float",
                     "only Float32 and Float64 variables are continuous"},
    rule_description{"fmi3.variable.independent",
                     "exactly one independent variable, a Float32 or Float64"},
    rule_description{"fmi3.variable.derivative",
                     "derivative is the valueReference of a float variable"},
    rule_description{
        "fmi3.variable.declared_type",
        "declaredType names a type definition of the variable's type; Enumeration has one"},
    rule_description{"fmi3.variable.unit",
                     "unit is declared in UnitDefinitions, displayUnit is one of its DisplayUnits"},
    rule_description{"fmi3.variable.start_required",
                     "start is given for initial exact|approx, inputs and constants"},
    rule_description{"fmi3.variable.start_forbidden",
                     "no start for initial calculated or causality independent"},
    rule_description{"fmi3.variable.value",
                     "start/min/max/nominal parse as the variable's type and fit its range"},
    rule_description{"fmi3.variable.range", "min <= max and min <= every start value <= max"},
    rule_description{"fmi3.variable.start_syntax",
                     "String and Binary starts are <Start value> children, Binary ones hex; no "
                     "<Start> elsewhere"},
    rule_description{"fmi3.dimension.attribute",
                     "a Dimension has exactly one of start and valueReference; no Clock arrays"},
    rule_description{"fmi3.dimension.start", "Dimension@start is a positive integer"},
    rule_description{"fmi3.dimension.reference",
                     "Dimension@valueReference names a UInt64 structuralParameter or constant"},
    rule_description{"fmi3.variable.start_count",
                     "the number of start values is the product of the dimensions"},
    rule_description{"fmi3.unknown.value_reference",
                     "each ModelStructure entry names a variable by valueReference"},
    rule_description{"fmi3.outputs.missing", "every output variable has an Output entry"},
    rule_description{"fmi3.outputs.not_output", "Output entries name only output variables"},
    rule_description{"fmi3.outputs.order",
                     "Output entries follow ModelVariables order, no duplicates"},
    rule_description{"fmi3.derivatives.value_reference",
                     "ContinuousStateDerivative entries name variables with derivative"},
    rule_description{"fmi3.dependencies.value_reference",
                     "dependencies are value references of variables"},
    rule_description{"fmi3.dependencies.known",
                     "dependencies are inputs, continuous states or the independent variable "
                     "(InitialUnknown: also initial exact)"},
    rule_description{"fmi3.dependencies.kind",
                     "dependenciesKind has one legal kind per dependency"},
    rule_description{"fmi3.initial_unknowns.missing",
                     "InitialUnknown lists every output with initial approx|calculated, every "
                     "calculatedParameter, and states/derivatives with approx|calculated"},
    rule_description{"fmi3.initial_unknowns.extra", "InitialUnknown lists nothing else"},
    rule_description{"fmi3.initial_unknowns.order", "InitialUnknown lists no variable twice"},
    rule_description{"fmi3.initial_unknowns.kind",
                     "InitialUnknown dependenciesKind is dependent|constant only"},
};

}  // namespace

std::span<const rule_description> all_rules() {
  return k_rules;
}

std::string_view to_string(finding::severity level) {
  return level == finding::severity::error ? "error" : "warning";
}

std::string format_finding(std::string_view file, const finding& f) {
  std::string line(file);
  line += ": ";
  line += to_string(f.level);
  line += ": [";
  line += f.rule;
  line += "] ";
  line += f.message;
  return line;
}

bool has_errors(std::span<const finding> findings) {
  return std::any_of(findings.begin(), findings.end(),
                     [](const finding& f) { return f.level == finding::severity::error; });
}

namespace detail {

void reporter::error(std::string_view rule, std::string message) {
  add(finding::severity::error, rule, std::move(message));
}

void reporter::warning(std::string_view rule, std::string message) {
  add(finding::severity::warning, rule, std::move(message));
}

void reporter::append(std::vector<finding> more) {
  for (auto& f : more) findings_.push_back(std::move(f));
}

void reporter::add(finding::severity level, std::string_view rule, std::string message) {
  const auto rules = all_rules();
  if (std::none_of(rules.begin(), rules.end(),
                   [&](const rule_description& r) { return r.id == rule; })) {
    throw std::logic_error("stride::fmi_check: rule id \"" + std::string(rule) +
                           "\" is not in all_rules()");
  }
  findings_.push_back(finding{level, std::string(rule), std::move(message)});
}

}  // namespace detail

}  // namespace stride::fmi_check
