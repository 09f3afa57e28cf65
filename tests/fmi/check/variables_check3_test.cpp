// The FMI 3.0 checker of ModelVariables and of the rules that combine variables
// (fmi/check/src/variables_check3.cpp).
#include <gtest/gtest.h>

#include "defects.hpp"

namespace stride::fmi_check::test {

const std::vector<defect> k_variables3_defects = {
    // the variable elements, names and value references
    {"no_model_variables",
     {{"re:<ModelVariables>[\\s\\S]*</ModelVariables>", ""}},
     "fmi3.variables.empty"},
    {"empty_model_variables",
     {{"re:<ModelVariables>[\\s\\S]*</ModelVariables>", "<ModelVariables/>"}},
     "fmi3.variables.empty"},
    {"fmi2_scalar_variable",
     {{"<Int8 name=\"trim\" valueReference=\"13\" causality=\"parameter\" variability=\"fixed\" "
       "start=\"-128\" min=\"-128\" max=\"127\"/>",
       "<ScalarVariable name=\"trim\" valueReference=\"13\" causality=\"parameter\" "
       "variability=\"fixed\"><Integer start=\"1\"/></ScalarVariable>"}},
     "fmi3.variable.type"},
    {"variable_without_name", {{"name=\"der_x\" ", ""}}, "fmi3.variable.name"},
    {"duplicate_name", {{"name=\"der_x\"", "name=\"x\""}}, "fmi3.variable.name_unique"},
    {"negative_value_reference",
     {{"valueReference=\"13\"", "valueReference=\"-1\""}},
     "fmi3.variable.value_reference"},
    {"no_value_reference", {{"valueReference=\"13\" ", ""}}, "fmi3.variable.value_reference"},
    {"duplicate_value_reference",
     {{"valueReference=\"13\"", "valueReference=\"12\""}},
     "fmi3.variable.value_reference_unique"},
    {"unknown_variable_attribute",
     {{"name=\"u\" valueReference=\"2\"", "name=\"u\" valueReference=\"2\" causalty=\"input\""}},
     "schema.attribute"},
    {"unit_on_integer",
     {{"initial=\"exact\" start=\"0\" min=\"0\"",
       "initial=\"exact\" start=\"0\" min=\"0\" unit=\"m\""}},
     "schema.attribute"},
    // causality, variability, initial
    {"bad_causality",
     {{"name=\"x\" valueReference=\"14\"",
       "name=\"x\" valueReference=\"14\" causality=\"internal\""}},
     "fmi3.variable.causality"},
    {"bad_variability",
     {{"variability=\"tunable\" declaredType", "variability=\"sometimes\" declaredType"}},
     "fmi3.variable.variability"},
    {"bad_initial",
     {{"initial=\"exact\" start=\"0\" min=\"0\"", "initial=\"given\" start=\"0\" min=\"0\""}},
     "fmi3.variable.initial"},
    {"parameter_continuous",
     {{"causality=\"parameter\" variability=\"fixed\" start=\"2\"",
       "causality=\"parameter\" variability=\"continuous\" start=\"2\""}},
     "fmi3.variable.causality_variability"},
    {"structural_parameter_discrete",
     {{"causality=\"structuralParameter\" variability=\"fixed\"",
       "causality=\"structuralParameter\" variability=\"discrete\""}},
     "fmi3.variable.causality_variability"},
    {"input_fixed",
     {{"name=\"u\" valueReference=\"2\" causality=\"input\"",
       "name=\"u\" valueReference=\"2\" causality=\"input\" variability=\"fixed\""}},
     "fmi3.variable.causality_variability"},
    {"output_tunable",
     {{"name=\"q\" valueReference=\"7\" causality=\"output\"",
       "name=\"q\" valueReference=\"7\" causality=\"output\" variability=\"tunable\""}},
     "fmi3.variable.causality_variability"},
    {"parameter_initial_calculated",
     {{"name=\"trim\" valueReference=\"13\" causality=\"parameter\"",
       "name=\"trim\" valueReference=\"13\" causality=\"parameter\" initial=\"calculated\""}},
     "fmi3.variable.initial"},
    {"independent_with_initial",
     {{"causality=\"independent\"", "causality=\"independent\" initial=\"exact\""}},
     "fmi3.variable.initial"},
    {"calculated_parameter_exact",
     {{"causality=\"calculatedParameter\"", "causality=\"calculatedParameter\" initial=\"exact\""}},
     "fmi3.variable.initial"},
    {"integer_continuous",
     {{"causality=\"output\" variability=\"discrete\"",
       "causality=\"output\" variability=\"continuous\""}},
     "fmi3.variable.continuous_non_float"},
    // the independent variable and derivatives
    {"no_independent",
     {{"causality=\"independent\" variability=\"continuous\"", "variability=\"continuous\""}},
     "fmi3.variable.independent"},
    {"two_independent",
     {{"<Float32 name=\"x\" valueReference=\"14\" initial=\"exact\" start=\"1\"/>",
       "<Float32 name=\"x\" valueReference=\"14\" initial=\"exact\" start=\"1\"/>\n"
       "    <Float64 name=\"angle\" valueReference=\"99\" causality=\"independent\"/>"}},
     "fmi3.variable.independent"},
    {"integer_independent",
     {{"<Float64 name=\"time\" valueReference=\"0\" causality=\"independent\" "
       "variability=\"continuous\" unit=\"s\"/>",
       "<Int64 name=\"time\" valueReference=\"0\" causality=\"independent\"/>"}},
     "fmi3.variable.independent"},
    {"derivative_of_nothing",
     {{"derivative=\"14\"", "derivative=\"99\""}},
     "fmi3.variable.derivative"},
    {"derivative_of_integer",
     {{"derivative=\"14\"", "derivative=\"4\""}},
     "fmi3.variable.derivative"},
};

INSTANTIATE_TEST_SUITE_P(variables3, fmi3_check_defect, testing::ValuesIn(k_variables3_defects),
                         defect_name);

}  // namespace stride::fmi_check::test
