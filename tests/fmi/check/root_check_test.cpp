// The checker of the fmiModelDescription attributes, the element order, CoSimulation,
// LogCategories and DefaultExperiment (fmi/check/src/root_check.cpp).
#include <gtest/gtest.h>

#include "defects.hpp"

namespace stride::fmi_check::test {

const std::vector<defect> k_root_defects = {
    // fmiModelDescription attributes
    {"bad_fmi_version", {{"fmiVersion=\"2.0\"", "fmiVersion=\"2.1\""}}, "root.fmi_version"},
    // "3.0" is checked by the FMI 3.0 rules, which want an instantiationToken, not a guid
    {"fmi3_version",
     {{"fmiVersion=\"2.0\"", "fmiVersion=\"3.0\""}},
     "fmi3.root.instantiation_token"},
    {"no_fmi_version", {{"fmiVersion=\"2.0\"", ""}}, "root.fmi_version"},
    {"no_model_name", {{"modelName=\"check_minimal\"", ""}}, "root.model_name"},
    {"no_guid", {{"guid=\"{8c4e810f-3df3-4a00-8276-176fa3c9f000}\"", ""}}, "root.guid"},
    {"empty_guid",
     {{"guid=\"{8c4e810f-3df3-4a00-8276-176fa3c9f000}\"", "guid=\" \""}},
     "root.guid"},
    {"date_time_with_space",
     {{"2026-11-22T10:00:00Z", "2026-11-22 10:00:00"}},
     "root.generation_date"},
    {"date_time_bad_day",
     {{"2026-11-22T10:00:00Z", "2026-02-30T10:00:00Z"}},
     "root.generation_date"},
    {"bad_naming_convention",
     {{"variableNamingConvention=\"structured\"", "variableNamingConvention=\"tree\""}},
     "root.attribute_value"},
    {"bad_event_indicators",
     {{"numberOfEventIndicators=\"0\"", "numberOfEventIndicators=\"x\""}},
     "root.attribute_value"},
    {"unknown_root_attribute", {{"modelName=", "modelname=\"x\" modelName="}}, "schema.attribute"},
    // element order
    {"default_experiment_after_variables",
     {{"<DefaultExperiment startTime=\"0\" stopTime=\"2\" stepSize=\"0.01\"/>", ""},
      {"</ModelVariables>", "</ModelVariables>\n  <DefaultExperiment stepSize=\"0.01\"/>"}},
     "structure.child_order"},
    {"unknown_element",
     {{"</LogCategories>", "</LogCategories>\n  <Extras/>"}},
     "structure.child_order"},
    {"duplicate_element",
     {{"</LogCategories>", "</LogCategories>\n  <LogCategories/>"}},
     "structure.child_order"},
    // CoSimulation
    // a description with neither interface element; <ModelExchange> alone is tested in
    // model_exchange_check_test.cpp
    {"no_co_simulation", {{"re:<CoSimulation[^>]*/>", ""}}, "cosim.missing"},
    {"missing_model_identifier",
     {{"modelIdentifier=\"check_minimal\"", ""}},
     "cosim.model_identifier"},
    {"model_identifier_not_c",
     {{"modelIdentifier=\"check_minimal\"", "modelIdentifier=\"check-minimal\""}},
     "cosim.model_identifier"},
    {"flag_not_boolean",
     {{"canHandleVariableCommunicationStepSize=\"true\"",
       "canHandleVariableCommunicationStepSize=\"yes\""}},
     "cosim.flag"},
    {"max_output_derivative_order_negative",
     {{"maxOutputDerivativeOrder=\"0\"", "maxOutputDerivativeOrder=\"-1\""}},
     "cosim.flag"},
    {"fmi3_flag_spelling",
     {{"canGetAndSetFMUstate=\"false\"", "canGetAndSetFMUState=\"false\""}},
     "schema.attribute"},
    // LogCategories
    {"log_category_twice",
     {{"<Category name=\"logAll\"/>", "<Category name=\"logStatusError\"/>"}},
     "log_categories.unique"},
    {"log_category_without_name",
     {{"<Category name=\"logAll\"/>", "<Category/>"}},
     "log_categories.name"},
    // DefaultExperiment
    {"step_size_zero", {{"stepSize=\"0.01\"", "stepSize=\"0\""}}, "default_experiment.step_size"},
    {"stop_before_start", {{"stopTime=\"2\"", "stopTime=\"0\""}}, "default_experiment.interval"},
    {"stop_time_not_a_number",
     {{"stopTime=\"2\"", "stopTime=\"two\""}},
     "default_experiment.value"},
    {"negative_tolerance",
     {{"stepSize=\"0.01\"", "stepSize=\"0.01\" tolerance=\"-1e-6\""}},
     "default_experiment.tolerance"},
};

INSTANTIATE_TEST_SUITE_P(root, fmi_check_defect, testing::ValuesIn(k_root_defects), defect_name);

}  // namespace stride::fmi_check::test
