// stride::fmi_check on modelDescription.xml text: the hand-written valid description passes,
// and each single defect derived from it is reported with its rule id. The defects of each
// checker are listed in its own test file (<checker>_check_test.cpp); the test that runs them
// is here.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "defects.hpp"
#include "test_support.hpp"

namespace stride::fmi_check::test {

using enum finding::severity;

const std::vector<defect> k_model_description_defects = {
    {"not_well_formed", {{"</ModelStructure>", "</ModelStructur>"}}, "xml.well_formed"},
    {"wrong_root",
     {{"<fmiModelDescription", "<modelDescription"},
      {"</fmiModelDescription>", "</modelDescription>"}},
     "root.element"},
};

TEST_P(fmi_check_defect, is_reported_with_its_rule) {
  const defect& d = GetParam();
  const std::string xml = apply(d);
  ASSERT_NE(xml, valid_xml()) << "the edits changed nothing";
  const auto findings = check_model_description(xml);
  EXPECT_TRUE(has_rule(findings, d.rule, d.level))
      << "expected " << to_string(d.level) << " [" << d.rule << "], got:\n"
      << describe(findings);
  if (d.level == warning) {
    EXPECT_FALSE(has_errors(findings)) << describe(findings);
  }
}

INSTANTIATE_TEST_SUITE_P(model_description, fmi_check_defect,
                         testing::ValuesIn(k_model_description_defects), defect_name);

namespace {

TEST(fmi_check_model_description, valid_minimal_has_no_finding) {
  const auto findings = check_model_description(valid_xml());
  EXPECT_TRUE(findings.empty()) << describe(findings);
}

TEST(fmi_check_model_description, every_defect_rule_is_a_known_rule) {
  std::set<std::string_view> ids;
  for (const auto& r : all_rules()) {
    EXPECT_TRUE(ids.insert(r.id).second) << "duplicate rule id " << r.id;
    EXPECT_FALSE(r.summary.empty()) << r.id;
  }
  for (const auto* defects :
       {&k_model_description_defects, &k_root_defects, &k_type_definitions_defects,
        &k_variables_defects, &k_start_values_defects, &k_model_structure_defects,
        &k_model_exchange_defects}) {
    for (const defect& d : *defects) EXPECT_TRUE(ids.contains(d.rule)) << d.rule;
  }
}

TEST(fmi_check_model_description, every_rule_is_documented) {
  // `stride-fmu-check --list-rules` points to the rules pages: each id appears on one of them
  const std::filesystem::path docs = std::filesystem::path(STRIDE_SOURCE_DIR) / "docs";
  const std::string text = read_text(docs / "fmi-rules.md") + read_text(docs / "fmi3-rules.md");
  for (const auto& r : all_rules()) {
    EXPECT_NE(text.find(r.id), std::string::npos) << r.id << " is in neither rules page";
  }
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
  const auto findings = check_model_description(xml);
  EXPECT_TRUE(findings.empty()) << describe(findings);
}

TEST(fmi_check_model_description, messages_name_the_variable_and_line) {
  defect d{"param_without_start",
           {{"<Real start=\"2\" min=\"0\" max=\"10\"/>", "<Real min=\"0\" max=\"10\"/>"}},
           "variable.start_required"};
  const auto findings = check_model_description(apply(d));
  ASSERT_EQ(findings.size(), 1u) << describe(findings);
  EXPECT_NE(findings[0].message.find("\"gain\""), std::string::npos) << findings[0].message;
  EXPECT_NE(findings[0].message.find("line "), std::string::npos) << findings[0].message;
  EXPECT_EQ(format_finding("x.fmu", findings[0]),
            "x.fmu: error: [variable.start_required] " + findings[0].message);
}

}  // namespace

}  // namespace stride::fmi_check::test
