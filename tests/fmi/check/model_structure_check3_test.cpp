// The FMI 3.0 checker of ModelStructure (fmi/check/src/model_structure_check3.cpp).
#include <gtest/gtest.h>

#include "defects.hpp"

namespace stride::fmi_check::test {

const std::vector<defect> k_model_structure3_defects = {
    {"no_model_structure",
     {{"re:<ModelStructure>[\\s\\S]*</ModelStructure>", ""}},
     "structure.model_structure"},
    {"fmi2_outputs_element",
     {{"<Output valueReference=\"7\"/>", "<Outputs><Unknown index=\"8\"/></Outputs>"}},
     "structure.child_order"},
    {"derivative_after_initial_unknowns",
     {{"<ContinuousStateDerivative valueReference=\"15\" dependencies=\"14\"/>", ""},
      {"<InitialUnknown valueReference=\"15\"/>",
       "<InitialUnknown valueReference=\"15\"/>\n"
       "    <ContinuousStateDerivative valueReference=\"15\" dependencies=\"14\"/>"}},
     "structure.child_order"},
    {"unknown_value_reference",
     {{"<Output valueReference=\"7\"/>", "<Output valueReference=\"99\"/>"}},
     "fmi3.unknown.value_reference"},
    {"fmi2_index_attribute",
     {{"<Output valueReference=\"7\"/>", "<Output index=\"8\"/>"}},
     "fmi3.unknown.value_reference"},
    // Output
    {"output_missing", {{"<Output valueReference=\"7\"/>", ""}}, "fmi3.outputs.missing"},
    {"output_not_an_output",
     {{"<Output valueReference=\"7\"/>",
       "<Output valueReference=\"7\"/>\n    <Output valueReference=\"13\"/>"}},
     "fmi3.outputs.not_output"},
    {"outputs_out_of_order",
     {{"<Output valueReference=\"4\" dependencies=\"\"/>", ""},
      {"<Output valueReference=\"7\"/>",
       "<Output valueReference=\"7\"/>\n    <Output valueReference=\"4\" dependencies=\"\"/>"}},
     "fmi3.outputs.order"},
    {"output_twice",
     {{"<Output valueReference=\"7\"/>",
       "<Output valueReference=\"7\"/>\n    <Output valueReference=\"7\"/>"}},
     "fmi3.outputs.order"},
    // dependencies
    {"dependency_on_nothing",
     {{"dependencies=\"2 14\"", "dependencies=\"2 99\""}},
     "fmi3.dependencies.value_reference"},
    {"dependency_on_an_output",
     {{"dependencies=\"2 14\"", "dependencies=\"2 4\""}},
     "fmi3.dependencies.known"},
    {"output_dependency_on_a_parameter",
     {{"dependencies=\"2 14\"", "dependencies=\"1 14\""}},
     "fmi3.dependencies.known"},
    {"initial_dependency_on_a_calculated_parameter",
     {{"<InitialUnknown valueReference=\"3\" dependencies=\"1 2\"",
       "<InitialUnknown valueReference=\"3\" dependencies=\"5 2\""}},
     "fmi3.dependencies.known"},
    {"too_few_kinds",
     {{"dependenciesKind=\"constant dependent\"", "dependenciesKind=\"constant\""}},
     "fmi3.dependencies.kind"},
    {"illegal_kind",
     {{"dependenciesKind=\"constant dependent\"", "dependenciesKind=\"constant sometimes\""}},
     "fmi3.dependencies.kind"},
    {"kinds_without_dependencies",
     {{"<Output valueReference=\"4\" dependencies=\"\"/>",
       "<Output valueReference=\"4\" dependenciesKind=\"dependent\"/>"}},
     "fmi3.dependencies.kind"},
    // ContinuousStateDerivative
    {"state_listed_as_derivative",
     {{"<ContinuousStateDerivative valueReference=\"15\"",
       "<ContinuousStateDerivative valueReference=\"14\""}},
     "fmi3.derivatives.value_reference"},
    // InitialUnknown
    {"initial_unknown_missing",
     {{"<InitialUnknown valueReference=\"5\" dependencies=\"1\"/>", ""}},
     "fmi3.initial_unknowns.missing"},
    {"derivative_initial_unknown_missing",
     {{"<InitialUnknown valueReference=\"15\"/>", ""}},
     "fmi3.initial_unknowns.missing"},
    {"initial_unknown_extra",
     {{"<InitialUnknown valueReference=\"15\"/>",
       "<InitialUnknown valueReference=\"15\"/>\n    <InitialUnknown valueReference=\"1\"/>"}},
     "fmi3.initial_unknowns.extra"},
    {"initial_unknown_twice",
     {{"<InitialUnknown valueReference=\"15\"/>",
       "<InitialUnknown valueReference=\"15\"/>\n    <InitialUnknown valueReference=\"15\"/>"}},
     "fmi3.initial_unknowns.order"},
    {"initial_unknown_kind_tunable",
     {{"dependenciesKind=\"dependent dependent\"", "dependenciesKind=\"dependent tunable\""}},
     "fmi3.initial_unknowns.kind"},
};

INSTANTIATE_TEST_SUITE_P(model_structure3, fmi3_check_defect,
                         testing::ValuesIn(k_model_structure3_defects), defect_name);

}  // namespace stride::fmi_check::test
