// The checker of ModelVariables and of the rules that combine variables
// (fmi/check/src/variables_check.cpp).
#include <gtest/gtest.h>

#include "defects.hpp"

namespace stride::fmi_check::test {

using enum finding::severity;

const std::vector<defect> k_variables_defects = {
    // ScalarVariable attributes and type child
    {"no_model_variables",
     {{"re:<ModelVariables>[\\s\\S]*</ModelVariables>", ""}},
     "variables.empty"},
    {"empty_model_variables",
     {{"re:<ModelVariables>[\\s\\S]*</ModelVariables>", "<ModelVariables/>"}},
     "variables.empty"},
    {"variable_without_name", {{"name=\"y_alias\" ", ""}}, "variable.name"},
    {"duplicate_name", {{"name=\"y_alias\"", "name=\"y\""}}, "variable.name_unique"},
    {"negative_value_reference",
     {{"valueReference=\"7\"", "valueReference=\"-1\""}},
     "variable.value_reference"},
    {"no_value_reference", {{"valueReference=\"7\"", ""}}, "variable.value_reference"},
    {"two_type_elements",
     {{"<Real unit=\"m\"/>", "<Real unit=\"m\"/><Integer/>"}},
     "variable.type"},
    {"no_type_element",
     {{"causality=\"local\">\n      <Real/>", "causality=\"local\">"}},
     "variable.type"},
    {"unknown_variable_attribute",
     {{"name=\"u\" valueReference=\"1\"", "name=\"u\" valueReference=\"1\" causalty=\"input\""}},
     "schema.attribute"},
    // causality, variability, initial
    {"bad_causality",
     {{"causality=\"local\" variability=\"constant\"",
       "causality=\"internal\" variability=\"constant\""}},
     "variable.causality"},
    {"bad_variability",
     {{"variability=\"tunable\"", "variability=\"sometimes\""}},
     "variable.variability"},
    {"bad_initial",
     {{"variability=\"discrete\"\n                    initial=\"exact\"",
       "variability=\"discrete\"\n                    initial=\"given\""}},
     "variable.initial"},
    {"param_continuous",
     {{"causality=\"parameter\" variability=\"fixed\"",
       "causality=\"parameter\" variability=\"continuous\""}},
     "variable.causality_variability"},
    {"input_fixed",
     {{"name=\"u\" valueReference=\"1\" causality=\"input\"",
       "name=\"u\" valueReference=\"1\" causality=\"input\" variability=\"fixed\""}},
     "variable.causality_variability"},
    {"independent_discrete",
     {{"causality=\"independent\"", "causality=\"independent\" variability=\"discrete\""}},
     "variable.causality_variability"},
    {"param_initial_calculated",
     {{"causality=\"parameter\" variability=\"fixed\"",
       "causality=\"parameter\" variability=\"fixed\" initial=\"calculated\""}},
     "variable.initial"},
    {"input_with_initial",
     {{"name=\"u\" valueReference=\"1\" causality=\"input\"",
       "name=\"u\" valueReference=\"1\" causality=\"input\" initial=\"exact\""}},
     "variable.initial"},
    {"calculated_parameter_exact",
     {{"causality=\"calculatedParameter\"\n                    variability=\"fixed\"",
       "causality=\"calculatedParameter\"\n                    variability=\"fixed\" "
       "initial=\"exact\""}},
     "variable.initial"},
    {"integer_continuous",
     {{"causality=\"output\" variability=\"discrete\"", "causality=\"output\""}},
     "variable.continuous_non_real"},
    {"boolean_continuous",
     {{"causality=\"input\" variability=\"discrete\"",
       "causality=\"input\" variability=\"continuous\""}},
     "variable.continuous_non_real"},
    // combinations of variables
    {"two_independent",
     {{"name=\"y_alias\" valueReference=\"2\" causality=\"local\"",
       "name=\"y_alias\" valueReference=\"2\" causality=\"independent\""}},
     "variable.independent"},
    {"integer_independent",
     {{"causality=\"independent\">\n      <Real/>",
       "causality=\"independent\">\n      <Integer/>"}},
     "variable.independent"},
    {"derivative_out_of_range",
     {{"causality=\"local\">\n      <Real/>",
       "causality=\"local\">\n      <Real derivative=\"99\"/>"}},
     "variable.derivative"},
    {"duplicate_vr_two_starts",
     {{"</ModelVariables>",
       "  <ScalarVariable name=\"gain_alias\" valueReference=\"0\" causality=\"parameter\" "
       "variability=\"fixed\"><Real start=\"3\"/></ScalarVariable>\n  </ModelVariables>"}},
     "variable.alias_start"},
    {"array_gap", {{"name=\"q[2]\"", "name=\"q[3]\""}}, "variable.array_index", warning},
    {"array_zero_based",
     {{"name=\"q[1]\"", "name=\"q[0]\""}, {"name=\"q[2]\"", "name=\"q[1]\""}},
     "variable.array_index",
     warning},
};

INSTANTIATE_TEST_SUITE_P(variables, fmi_check_defect, testing::ValuesIn(k_variables_defects),
                         defect_name);

}  // namespace stride::fmi_check::test
