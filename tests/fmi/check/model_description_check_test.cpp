// stride::fmi_check on modelDescription.xml text: the hand-written valid description passes,
// and each single defect derived from it is reported with its rule id.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "stride/fmi_check/fmu_check.hpp"
#include "test_support.hpp"

namespace {

namespace check = stride::fmi_check;

const std::string& valid_xml() {
  static const std::string text =
      check::test::read_text(std::filesystem::path(STRIDE_TEST_DATA_DIR) / "valid_minimal.xml");
  return text;
}

std::string describe(const std::vector<check::finding>& findings) {
  std::string out;
  for (const auto& f : findings) out += check::format_finding("md", f) + "\n";
  return out.empty() ? "(no findings)\n" : out;
}

bool has_rule(const std::vector<check::finding>& findings, std::string_view rule,
              check::finding::severity level) {
  return std::any_of(findings.begin(), findings.end(),
                     [&](const check::finding& f) { return f.rule == rule && f.level == level; });
}

/// One defect: edits applied to the valid description, and the rule that must report it.
/// An edit whose `from` starts with "re:" is an ECMAScript regex; otherwise it is literal text
/// that must occur exactly once.
struct defect {
  std::string name;
  std::vector<std::pair<std::string, std::string>> edits;
  std::string rule;
  check::finding::severity level = check::finding::severity::error;
};

void PrintTo(const defect& d, std::ostream* os) {
  *os << d.name;
}

std::string apply(const defect& d) {
  std::string xml = valid_xml();
  for (const auto& [from, to] : d.edits) {
    if (from.starts_with("re:")) {
      const std::regex re(from.substr(3));
      if (!std::regex_search(xml, re)) {
        ADD_FAILURE() << d.name << ": regex matches nothing: " << from;
      }
      xml = std::regex_replace(xml, re, to);
      continue;
    }
    const auto at = xml.find(from);
    if (at == std::string::npos || xml.find(from, at + 1) != std::string::npos) {
      ADD_FAILURE() << d.name << ": edit text must occur exactly once: " << from;
      continue;
    }
    xml.replace(at, from.size(), to);
  }
  return xml;
}

using enum check::finding::severity;

const std::vector<defect> k_defects = {
    // well-formedness and root
    {"not_well_formed", {{"</ModelStructure>", "</ModelStructur>"}}, "xml.well_formed"},
    {"wrong_root",
     {{"<fmiModelDescription", "<modelDescription"},
      {"</fmiModelDescription>", "</modelDescription>"}},
     "root.element"},
    {"bad_fmi_version", {{"fmiVersion=\"2.0\"", "fmiVersion=\"2.1\""}}, "root.fmi_version"},
    {"fmi3_version", {{"fmiVersion=\"2.0\"", "fmiVersion=\"3.0\""}}, "root.fmi_version"},
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
    {"no_model_structure",
     {{"re:<ModelStructure>[\\s\\S]*</ModelStructure>", ""}},
     "structure.model_structure"},
    // CoSimulation
    {"no_co_simulation", {{"<CoSimulation", "<ModelExchange"}}, "cosim.missing"},
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
    // TypeDefinitions, LogCategories, DefaultExperiment
    {"simple_type_without_name",
     {{"<SimpleType name=\"mode_type\">", "<SimpleType>"}},
     "type_definitions.name"},
    {"log_category_twice",
     {{"<Category name=\"logAll\"/>", "<Category name=\"logStatusError\"/>"}},
     "log_categories.unique"},
    {"log_category_without_name",
     {{"<Category name=\"logAll\"/>", "<Category/>"}},
     "log_categories.name"},
    {"step_size_zero", {{"stepSize=\"0.01\"", "stepSize=\"0\""}}, "default_experiment.step_size"},
    {"stop_before_start", {{"stopTime=\"2\"", "stopTime=\"0\""}}, "default_experiment.interval"},
    {"stop_time_not_a_number",
     {{"stopTime=\"2\"", "stopTime=\"two\""}},
     "default_experiment.value"},
    {"negative_tolerance",
     {{"stepSize=\"0.01\"", "stepSize=\"0.01\" tolerance=\"-1e-6\""}},
     "default_experiment.tolerance"},
    // ModelVariables
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
    {"enumeration_without_declared_type",
     {{"<Enumeration declaredType=\"mode_type\" start=\"1\"/>", "<Enumeration start=\"1\"/>"}},
     "variable.type"},
    {"undefined_declared_type",
     {{"declaredType=\"mode_type\"", "declaredType=\"no_such_type\""}},
     "variable.declared_type"},
    {"unknown_variable_attribute",
     {{"name=\"u\" valueReference=\"1\"", "name=\"u\" valueReference=\"1\" causalty=\"input\""}},
     "schema.attribute"},
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
    {"param_without_start",
     {{"<Real start=\"2\" min=\"0\" max=\"10\"/>", "<Real min=\"0\" max=\"10\"/>"}},
     "variable.start_required"},
    {"input_without_start", {{"<Real start=\"0\"/>", "<Real/>"}}, "variable.start_required"},
    {"output_exact_without_start",
     {{"<Integer start=\"0\" min=\"0\"/>", "<Integer min=\"0\"/>"}},
     "variable.start_required"},
    {"constant_without_start",
     {{"<String start=\"1.0\"/>", "<String/>"}},
     "variable.start_required"},
    {"calculated_with_start",
     {{"<Real unit=\"m\"/>", "<Real unit=\"m\" start=\"1\"/>"}},
     "variable.start_forbidden"},
    {"independent_with_start",
     {{"causality=\"independent\">\n      <Real/>",
       "causality=\"independent\">\n      <Real start=\"0\"/>"}},
     "variable.start_forbidden"},
    {"integer_continuous",
     {{"causality=\"output\" variability=\"discrete\"", "causality=\"output\""}},
     "variable.continuous_non_real"},
    {"boolean_continuous",
     {{"causality=\"input\" variability=\"discrete\"",
       "causality=\"input\" variability=\"continuous\""}},
     "variable.continuous_non_real"},
    {"start_above_max",
     {{"<Real start=\"2\" min=\"0\" max=\"10\"/>", "<Real start=\"20\" min=\"0\" max=\"10\"/>"}},
     "variable.range"},
    {"min_above_max",
     {{"<Real start=\"2\" min=\"0\" max=\"10\"/>", "<Real start=\"2\" min=\"11\" max=\"10\"/>"}},
     "variable.range"},
    {"integer_start_below_min",
     {{"<Integer start=\"0\" min=\"0\"/>",
       "<Integer start=\"-1\" "
       "min=\"0\"/>"}},
     "variable.range"},
    {"boolean_start_not_boolean",
     {{"<Boolean start=\"true\"/>", "<Boolean start=\"yes\"/>"}},
     "variable.value"},
    {"real_start_not_a_number",
     {{"<Real start=\"2\" min=\"0\" max=\"10\"/>", "<Real start=\"2,5\" min=\"0\" max=\"10\"/>"}},
     "variable.value"},
    {"nominal_zero",
     {{"<Real unit=\"m\"/>", "<Real unit=\"m\" nominal=\"0\"/>"}},
     "variable.value"},
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
    // ModelStructure
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
    {"derivatives_lists_a_state",
     {{"</Outputs>", "</Outputs>\n    <Derivatives><Unknown index=\"3\"/></Derivatives>"}},
     "derivatives.index"},
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

class fmi_check_defect : public testing::TestWithParam<defect> {};

TEST_P(fmi_check_defect, is_reported_with_its_rule) {
  const defect& d = GetParam();
  const std::string xml = apply(d);
  ASSERT_NE(xml, valid_xml()) << "the edits changed nothing";
  const auto findings = check::check_model_description(xml);
  EXPECT_TRUE(has_rule(findings, d.rule, d.level))
      << "expected " << check::to_string(d.level) << " [" << d.rule << "], got:\n"
      << describe(findings);
  if (d.level == warning) {
    EXPECT_FALSE(check::has_errors(findings)) << describe(findings);
  }
}

INSTANTIATE_TEST_SUITE_P(all, fmi_check_defect, testing::ValuesIn(k_defects),
                         [](const testing::TestParamInfo<defect>& info) {
                           return info.param.name;
                         });

TEST(fmi_check_model_description, valid_minimal_has_no_finding) {
  const auto findings = check::check_model_description(valid_xml());
  EXPECT_TRUE(findings.empty()) << describe(findings);
}

TEST(fmi_check_model_description, every_defect_rule_is_a_known_rule) {
  std::set<std::string_view> ids;
  for (const auto& r : check::all_rules()) {
    EXPECT_TRUE(ids.insert(r.id).second) << "duplicate rule id " << r.id;
    EXPECT_FALSE(r.summary.empty()) << r.id;
  }
  for (const defect& d : k_defects) EXPECT_TRUE(ids.contains(d.rule)) << d.rule;
}

TEST(fmi_check_model_description, valid_without_optional_elements_passes) {
  // the smallest description a CS FMU can have: one parameter, nothing optional
  const std::string xml = R"xml(<fmiModelDescription fmiVersion="2.0" modelName="m" guid="g">
  <CoSimulation modelIdentifier="m"/>
  <ModelVariables>
    <ScalarVariable name="p" valueReference="0" causality="parameter" variability="fixed">
      <Real start="1"/>
    </ScalarVariable>
  </ModelVariables>
  <ModelStructure/>
</fmiModelDescription>)xml";
  const auto findings = check::check_model_description(xml);
  EXPECT_TRUE(findings.empty()) << describe(findings);
}

TEST(fmi_check_model_description, states_and_derivatives_join_initial_unknowns) {
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
  const auto ok = check::check_model_description(
      with(R"(<InitialUnknowns><Unknown index="1"/><Unknown index="2"/></InitialUnknowns>)"));
  EXPECT_TRUE(ok.empty()) << describe(ok);
  const auto missing = check::check_model_description(
      with(R"(<InitialUnknowns><Unknown index="1"/></InitialUnknowns>)"));
  EXPECT_TRUE(has_rule(missing, "initial_unknowns.missing", error)) << describe(missing);
}

TEST(fmi_check_model_description, messages_name_the_variable_and_line) {
  defect d{"param_without_start",
           {{"<Real start=\"2\" min=\"0\" max=\"10\"/>", "<Real min=\"0\" max=\"10\"/>"}},
           "variable.start_required"};
  const auto findings = check::check_model_description(apply(d));
  ASSERT_EQ(findings.size(), 1u) << describe(findings);
  EXPECT_NE(findings[0].message.find("\"gain\""), std::string::npos) << findings[0].message;
  EXPECT_NE(findings[0].message.find("line "), std::string::npos) << findings[0].message;
  EXPECT_EQ(check::format_finding("x.fmu", findings[0]),
            "x.fmu: error: [variable.start_required] " + findings[0].message);
}

}  // namespace
