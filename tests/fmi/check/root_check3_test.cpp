// The FMI 3.0 checker of the fmiModelDescription attributes, the interface type elements,
// UnitDefinitions and TypeDefinitions (fmi/check/src/root_check3.cpp), and of the elements it
// shares with 2.0 (child order, LogCategories, DefaultExperiment).
#include <gtest/gtest.h>

#include "defects.hpp"

namespace stride::fmi_check::test {

using enum finding::severity;

const std::vector<defect> k_root3_defects = {
    // fmiModelDescription attributes
    {"version_3_1", {{"fmiVersion=\"3.0\"", "fmiVersion=\"3.1\""}}, "fmi3.root.fmi_version"},
    {"no_model_name", {{"modelName=\"check_minimal3\"", ""}}, "fmi3.root.model_name"},
    {"no_instantiation_token",
     {{"instantiationToken=\"{5b1d0c7e-2a7f-4c55-9b57-3c1f1a2e3000}\"", ""}},
     "fmi3.root.instantiation_token"},
    {"guid_instead_of_token", {{"instantiationToken=", "guid="}}, "fmi3.root.instantiation_token"},
    {"empty_instantiation_token",
     {{"instantiationToken=\"{5b1d0c7e-2a7f-4c55-9b57-3c1f1a2e3000}\"", "instantiationToken=\"\""}},
     "fmi3.root.instantiation_token"},
    {"bad_naming_convention",
     {{"variableNamingConvention=\"structured\"", "variableNamingConvention=\"tree\""}},
     "fmi3.root.naming_convention"},
    {"date_time_with_space",
     {{"2026-11-22T10:00:00Z", "2026-11-22 10:00:00"}},
     "root.generation_date"},
    {"fmi2_event_indicators",
     {{"variableNamingConvention=", "numberOfEventIndicators=\"0\" variableNamingConvention="}},
     "schema.attribute"},
    // element order, shared checkers
    {"default_experiment_after_variables",
     {{"<DefaultExperiment startTime=\"0\" stopTime=\"2\" stepSize=\"0.01\"/>", ""},
      {"</ModelVariables>", "</ModelVariables>\n  <DefaultExperiment stepSize=\"0.01\"/>"}},
     "structure.child_order"},
    {"log_category_twice",
     {{"<Category name=\"logAll\"/>", "<Category name=\"logStatusError\"/>"}},
     "log_categories.unique"},
    {"step_size_zero", {{"stepSize=\"0.01\"", "stepSize=\"0\""}}, "default_experiment.step_size"},
    // interface types
    {"no_co_simulation_nor_model_exchange",
     {{"<CoSimulation", "<ScheduledExecution"}},
     "fmi3.interface.missing"},
    {"model_exchange_without_identifier",
     {{"<CoSimulation", "<ModelExchange/>\n  <CoSimulation"}},
     "fmi3.interface.model_identifier"},
    {"scheduled_execution_too",
     {{"<UnitDefinitions>",
       "<ScheduledExecution modelIdentifier=\"check_minimal3\"/>\n  <UnitDefinitions>"}},
     "fmi3.interface.not_usable",
     warning},
    {"missing_model_identifier",
     {{"modelIdentifier=\"check_minimal3\"", ""}},
     "fmi3.interface.model_identifier"},
    {"model_identifier_not_c",
     {{"modelIdentifier=\"check_minimal3\"", "modelIdentifier=\"check-minimal3\""}},
     "fmi3.interface.model_identifier"},
    {"flag_not_boolean",
     {{"hasEventMode=\"false\"", "hasEventMode=\"no\""}},
     "fmi3.interface.flag"},
    {"order_negative",
     {{"maxOutputDerivativeOrder=\"0\"", "maxOutputDerivativeOrder=\"-1\""}},
     "fmi3.interface.flag"},
    {"fixed_internal_step_negative",
     {{"hasEventMode=\"false\"", "hasEventMode=\"false\" fixedInternalStepSize=\"-0.1\""}},
     "fmi3.interface.flag"},
    {"serialize_without_get_set",
     {{"canGetAndSetFMUState=\"true\"", "canGetAndSetFMUState=\"false\""}},
     "fmi3.interface.flag"},
    {"fmi2_flag",
     {{"hasEventMode=", "canInterpolateInputs=\"true\" hasEventMode="}},
     "schema.attribute"},
    // UnitDefinitions, TypeDefinitions
    {"unit_twice", {{"<Unit name=\"s\">", "<Unit name=\"m\">"}}, "fmi3.unit.name"},
    {"unit_without_name", {{"<Unit name=\"s\">", "<Unit>"}}, "fmi3.unit.name"},
    {"display_unit_without_name",
     {{"<DisplayUnit name=\"mm\" factor", "<DisplayUnit factor"}},
     "fmi3.unit.name"},
    {"type_definition_twice",
     {{"<EnumerationType name=\"mode_type\">", "<EnumerationType name=\"length\">"}},
     "fmi3.type_definitions.name"},
    {"fmi2_simple_type",
     {{"<Float64Type name=\"length\"", "<SimpleType name=\"length\""}},
     "structure.child_order"},
};

INSTANTIATE_TEST_SUITE_P(root3, fmi3_check_defect, testing::ValuesIn(k_root3_defects), defect_name);

}  // namespace stride::fmi_check::test
