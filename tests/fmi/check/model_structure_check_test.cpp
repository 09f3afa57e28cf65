// The checker of ModelStructure (fmi/check/src/model_structure_check.cpp).
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "defects.hpp"

namespace stride::fmi_check::test {

const std::vector<defect> k_model_structure_defects = {
    {"no_model_structure",
     {{"re:<ModelStructure>[\\s\\S]*</ModelStructure>", ""}},
     "structure.model_structure"},
    // Outputs
    {"output_missing_from_outputs",
     {{"      <Unknown index=\"8\"/>\n    </Outputs>", "    </Outputs>"}},
     "outputs.missing"},
    {"no_outputs_element", {{"re:<Outputs>[\\s\\S]*</Outputs>", ""}}, "outputs.missing"},
    {"non_output_in_outputs",
     {{"<Outputs>", "<Outputs>\n      <Unknown index=\"1\"/>"}},
     "outputs.not_output"},
    {"zero_based_output_index",
     {{"<Unknown index=\"3\" dependencies=\"1 2\" dependenciesKind=\"constant dependent\"/>",
       "<Unknown index=\"0\" dependencies=\"1 2\" dependenciesKind=\"constant dependent\"/>"}},
     "outputs.index"},
    {"output_index_out_of_range",
     {{"<Unknown index=\"3\" dependencies=\"1 2\" dependenciesKind=\"constant dependent\"/>",
       "<Unknown index=\"30\" dependencies=\"1 2\" dependenciesKind=\"constant dependent\"/>"}},
     "outputs.index"},
    {"outputs_out_of_order",
     {{"<Unknown index=\"7\"/>\n      <Unknown index=\"8\"/>\n    </Outputs>",
       "<Unknown index=\"8\"/>\n      <Unknown index=\"7\"/>\n    </Outputs>"}},
     "outputs.order"},
    // dependencies
    {"dependencies_unsorted",
     {{"dependencies=\"1 2\" dependenciesKind=\"constant dependent\"",
       "dependencies=\"2 1\" dependenciesKind=\"constant dependent\""}},
     "dependencies.order"},
    {"dependencies_duplicate",
     {{"dependencies=\"1 2\" dependenciesKind=\"constant dependent\"",
       "dependencies=\"1 1\" dependenciesKind=\"constant dependent\""}},
     "dependencies.order"},
    {"dependency_out_of_range",
     {{"dependencies=\"1 2\" dependenciesKind=\"constant dependent\"",
       "dependencies=\"1 99\" dependenciesKind=\"constant dependent\""}},
     "dependencies.index"},
    {"dependencies_kind_length",
     {{"dependenciesKind=\"constant dependent\"", "dependenciesKind=\"constant\""}},
     "dependencies.kind"},
    {"dependencies_kind_illegal",
     {{"dependenciesKind=\"constant dependent\"", "dependenciesKind=\"constant sometimes\""}},
     "dependencies.kind"},
    // Derivatives
    {"derivatives_lists_a_state",
     {{"</Outputs>", "</Outputs>\n    <Derivatives><Unknown index=\"3\"/></Derivatives>"}},
     "derivatives.index"},
    // InitialUnknowns
    {"initial_unknowns_incomplete",
     {{"      <Unknown index=\"6\" dependencies=\"1\"/>\n", ""}},
     "initial_unknowns.missing"},
    {"no_initial_unknowns",
     {{"re:<InitialUnknowns>[\\s\\S]*</InitialUnknowns>", ""}},
     "initial_unknowns.missing"},
    {"initial_unknowns_unsorted",
     {{"<Unknown index=\"7\"/>\n      <Unknown index=\"8\"/>\n    </InitialUnknowns>",
       "<Unknown index=\"8\"/>\n      <Unknown index=\"7\"/>\n    </InitialUnknowns>"}},
     "initial_unknowns.order"},
    {"initial_unknowns_duplicate",
     {{"<Unknown index=\"8\"/>\n    </InitialUnknowns>",
       "<Unknown index=\"8\"/>\n      <Unknown index=\"8\"/>\n    </InitialUnknowns>"}},
     "initial_unknowns.order"},
    {"initial_unknowns_extra",
     {{"<Unknown index=\"6\" dependencies=\"1\"/>",
       "<Unknown index=\"5\"/>\n      <Unknown index=\"6\" dependencies=\"1\"/>"}},
     "initial_unknowns.extra"},
    {"initial_unknowns_zero_based",
     {{"<Unknown index=\"6\" dependencies=\"1\"/>", "<Unknown index=\"0\" dependencies=\"1\"/>"}},
     "initial_unknowns.index"},
    {"initial_unknowns_kind",
     {{"dependenciesKind=\"dependent dependent\"", "dependenciesKind=\"dependent fixed\""}},
     "initial_unknowns.kind"},
};

INSTANTIATE_TEST_SUITE_P(model_structure, fmi_check_defect,
                         testing::ValuesIn(k_model_structure_defects), defect_name);

namespace {

using enum finding::severity;

TEST(fmi_check_model_structure, states_and_derivatives_join_initial_unknowns) {
  // x (1) is a state with derivative der_x (2); both default to calculated/approx as outputs
  // and locals, so with <Derivatives> given both must be initial unknowns.
  const std::string base = R"xml(<fmiModelDescription fmiVersion="2.0" modelName="m" guid="g">
  <CoSimulation modelIdentifier="m"/>
  <ModelVariables>
    <ScalarVariable name="x" valueReference="0" causality="output" initial="approx">
      <Real start="1"/>
    </ScalarVariable>
    <ScalarVariable name="der(x)" valueReference="1">
      <Real derivative="1"/>
    </ScalarVariable>
  </ModelVariables>
  <ModelStructure>
    <Outputs><Unknown index="1"/></Outputs>
    <Derivatives><Unknown index="2"/></Derivatives>
    INITIAL
  </ModelStructure>
</fmiModelDescription>)xml";
  auto with = [&](const std::string& initial) {
    return std::regex_replace(base, std::regex("INITIAL"), initial);
  };
  const auto ok = check_model_description(
      with(R"(<InitialUnknowns><Unknown index="1"/><Unknown index="2"/></InitialUnknowns>)"));
  EXPECT_TRUE(ok.empty()) << describe(ok);
  const auto missing =
      check_model_description(with(R"(<InitialUnknowns><Unknown index="1"/></InitialUnknowns>)"));
  EXPECT_TRUE(has_rule(missing, "initial_unknowns.missing", error)) << describe(missing);
}

}  // namespace

}  // namespace stride::fmi_check::test
