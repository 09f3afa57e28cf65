// stride::fmi_check on FMI 3.0 modelDescription.xml text (fmi/check/src/model_description_check3
// .cpp): the hand-written valid description passes, each single defect derived from it is
// reported with its rule id, and the fmiVersion decides which rule set runs. The defects of
// each 3.0 checker are listed in its own test file; the test that runs them is here.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "defects.hpp"

namespace stride::fmi_check::test {

using enum finding::severity;

TEST_P(fmi3_check_defect, is_reported_with_its_rule) {
  const defect& d = GetParam();
  const std::string xml = apply(d, valid3_xml());
  ASSERT_NE(xml, valid3_xml()) << "the edits changed nothing";
  const auto findings = check_model_description(xml);
  EXPECT_TRUE(has_rule(findings, d.rule, d.level))
      << "expected " << to_string(d.level) << " [" << d.rule << "], got:\n"
      << describe(findings);
  if (d.level == warning) {
    EXPECT_FALSE(has_errors(findings)) << describe(findings);
  }
}

namespace {

TEST(fmi_check_model_description3, valid_minimal3_has_no_finding) {
  const auto findings = check_model_description(valid3_xml());
  EXPECT_TRUE(findings.empty()) << describe(findings);
}

TEST(fmi_check_model_description3, every_description_rule_has_a_defect) {
  // the archive and export rules are tested on archives (archive_check3_test.cpp)
  std::set<std::string_view> tested;
  for (const auto* defects : {&k_root3_defects, &k_variables3_defects, &k_start_values3_defects,
                              &k_model_structure3_defects}) {
    for (const defect& d : *defects) tested.insert(d.rule);
  }
  for (const auto& r : all_rules()) {
    if (!r.id.starts_with("fmi3.") || r.id.starts_with("fmi3.archive.") ||
        r.id.starts_with("fmi3.exports.")) {
      continue;
    }
    EXPECT_TRUE(tested.contains(r.id)) << r.id << " has no defect test";
  }
  std::set<std::string_view> ids;
  for (const auto& r : all_rules()) ids.insert(r.id);
  for (std::string_view rule : tested) EXPECT_TRUE(ids.contains(rule)) << rule;
}

TEST(fmi_check_model_description3, the_version_chooses_the_rule_set) {
  // a 2.0 description is held to the 2.0 rules only, a 3.0 one to the 3.0 rules
  auto any_fmi3_rule = [](const std::vector<finding>& findings) {
    return std::any_of(findings.begin(), findings.end(),
                       [](const finding& f) { return f.rule.starts_with("fmi3."); });
  };
  const defect as_fmi3{"as_fmi3", {{"fmiVersion=\"2.0\"", "fmiVersion=\"3.0\""}}, ""};
  auto findings = check_model_description(apply(as_fmi3));
  EXPECT_TRUE(has_rule(findings, "fmi3.root.instantiation_token", error)) << describe(findings);
  EXPECT_TRUE(has_rule(findings, "fmi3.variable.type", error)) << describe(findings);
  EXPECT_FALSE(has_rule(findings, "root.fmi_version", error)) << describe(findings);

  const defect fmi2_defect{"no_start", {{"<Real start=\"0\"/>", "<Real/>"}}, ""};
  findings = check_model_description(apply(fmi2_defect));
  EXPECT_TRUE(has_rule(findings, "variable.start_required", error)) << describe(findings);
  EXPECT_FALSE(any_fmi3_rule(findings)) << describe(findings);
}

TEST(fmi_check_model_description3, an_fmi2_spelling_is_named) {
  const defect d{"fmi2_spelling",
                 {{"canGetAndSetFMUState=\"true\"", "canGetAndSetFMUstate=\"true\""}},
                 "schema.attribute"};
  const auto findings = check_model_description(apply(d, valid3_xml()));
  const auto it = std::find_if(findings.begin(), findings.end(),
                               [](const finding& f) { return f.rule == "schema.attribute"; });
  ASSERT_NE(it, findings.end()) << describe(findings);
  EXPECT_NE(it->message.find("FMI 3.0 writes canGetAndSetFMUState"), std::string::npos)
      << it->message;
}

TEST(fmi_check_model_description3, messages_name_the_variable_and_line) {
  const defect d{"param_without_start", {{"fixed\" start=\"2\" min", "fixed\" min"}}, ""};
  const auto findings = check_model_description(apply(d, valid3_xml()));
  ASSERT_EQ(findings.size(), 1u) << describe(findings);
  EXPECT_EQ(findings[0].rule, "fmi3.variable.start_required");
  EXPECT_NE(findings[0].message.find("\"gain\""), std::string::npos) << findings[0].message;
  EXPECT_NE(findings[0].message.find("line 37"), std::string::npos) << findings[0].message;
}

}  // namespace

}  // namespace stride::fmi_check::test
