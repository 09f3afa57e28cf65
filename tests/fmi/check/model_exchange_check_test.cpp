// The Model Exchange rules (fmi/check/src/model_exchange_check.cpp, docs/fmi-rules.md §2.5):
// each defect of data/valid_me.xml is reported with its rule and with no other rule, the valid
// description has no finding, and an FMU with both interface elements needs both binaries.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <string_view>

#include "defects.hpp"

// apply() is called qualified: with a std::string argument, ADL would also find std::apply

namespace stride::fmi_check::test {

const std::vector<defect> k_model_exchange_defects = {
    // the interface elements
    {"no_interface_element", {{"re:<ModelExchange[^>]*/>", ""}}, "cosim.missing"},
    {"me_without_model_identifier", {{"modelIdentifier=\"check_me\"", ""}}, "me.model_identifier"},
    {"me_model_identifier_not_c",
     {{"modelIdentifier=\"check_me\"", "modelIdentifier=\"check-me\""}},
     "me.model_identifier"},
    {"me_flag_not_boolean",
     {{"completedIntegratorStepNotNeeded=\"true\"", "completedIntegratorStepNotNeeded=\"yes\""}},
     "me.flag"},
    {"me_with_co_simulation_flag",
     {{"canGetAndSetFMUstate=\"false\"",
       "canGetAndSetFMUstate=\"false\" canHandleVariableCommunicationStepSize=\"true\""}},
     "schema.attribute"},
    // the states <Derivatives> defines
    {"derivative_discrete",
     {{"<ScalarVariable name=\"der(x)\" valueReference=\"1\">",
       "<ScalarVariable name=\"der(x)\" valueReference=\"1\" variability=\"discrete\">"}},
     "me.derivative_continuous"},
    {"state_discrete",
     {{"causality=\"output\" initial=\"exact\">",
       "causality=\"output\" variability=\"discrete\" initial=\"exact\">"}},
     "me.state"},
    {"state_parameter",
     {{"<ScalarVariable name=\"v\" valueReference=\"2\" initial=\"exact\">",
       "<ScalarVariable name=\"v\" valueReference=\"2\" causality=\"parameter\" "
       "variability=\"tunable\">"}},
     "me.state"},
    {"two_derivatives_of_one_state",
     {{"<Real derivative=\"3\"/>", "<Real derivative=\"1\"/>"}},
     "me.state_unique"},
    {"derivative_listed_twice",
     {{"<Unknown index=\"2\" dependencies=\"3\"/>",
       "<Unknown index=\"2\" dependencies=\"3\"/>\n      <Unknown index=\"2\"/>"}},
     "me.state_unique"},
    {"derivative_not_in_derivatives",
     {{"      <Unknown index=\"4\" dependencies=\"1 6\"/>\n", ""},
      {"      <Unknown index=\"4\"/>\n", ""}},
     "me.derivative_unlisted"},
    {"no_derivatives_element",
     {{"re:<Derivatives>[\\s\\S]*</Derivatives>", ""},
      {"re:<InitialUnknowns>[\\s\\S]*</InitialUnknowns>", ""},
      {" reinit=\"true\"", ""}},  // x is no state any more
     "me.derivative_unlisted"},
    {"reinit_on_a_derivative",
     {{"<Real derivative=\"1\"/>", "<Real derivative=\"1\" reinit=\"false\"/>"}},
     "me.reinit"},
    {"reinit_on_a_parameter",
     {{"<Real start=\"1\"/>", "<Real start=\"1\" reinit=\"true\"/>"}},
     "me.reinit"},
};

namespace {

using enum finding::severity;

std::set<std::string> rules_of(const std::vector<finding>& findings) {
  std::set<std::string> rules;
  for (const finding& f : findings) rules.insert(f.rule);
  return rules;
}

class fmi_me_check_defect : public testing::TestWithParam<defect> {};

TEST_P(fmi_me_check_defect, is_reported_with_its_rule_only) {
  const defect& d = GetParam();
  const std::string xml = test::apply(d, valid_me_xml());
  ASSERT_NE(xml, valid_me_xml()) << "the edits changed nothing";
  const auto findings = check_model_description(xml);
  EXPECT_TRUE(has_rule(findings, d.rule, d.level)) << "expected [" << d.rule << "], got:\n"
                                                   << describe(findings);
  EXPECT_EQ(rules_of(findings), std::set<std::string>{d.rule}) << describe(findings);
}

INSTANTIATE_TEST_SUITE_P(model_exchange, fmi_me_check_defect,
                         testing::ValuesIn(k_model_exchange_defects), defect_name);

const std::string k_co_simulation_element = "\n  <CoSimulation modelIdentifier=\"check_cs\"/>";

/// valid_me_xml() with a <CoSimulation> element after <ModelExchange>.
std::string with_co_simulation(const std::string& element = k_co_simulation_element) {
  return test::apply(
      {"add_co_simulation",
       {{"canGetAndSetFMUstate=\"false\"/>", "canGetAndSetFMUstate=\"false\"/>" + element}},
       ""},
      valid_me_xml());
}

TEST(fmi_check_model_exchange, every_model_exchange_rule_has_a_defect) {
  std::set<std::string_view> tested;
  for (const defect& d : k_model_exchange_defects) tested.insert(d.rule);
  for (const auto& r : all_rules()) {
    if (r.id.starts_with("me.")) {
      EXPECT_TRUE(tested.contains(r.id)) << r.id << " has no defect test";
    }
  }
}

TEST(fmi_check_model_exchange, valid_description_has_no_finding) {
  const auto findings = check_model_description(valid_me_xml());
  EXPECT_TRUE(findings.empty()) << describe(findings);
}

TEST(fmi_check_model_exchange, valid_with_its_binary_has_no_finding) {
  const archive_listing archive = {"modelDescription.xml", "binaries/linux64/check_me.so"};
  const auto findings = check_model_description(valid_me_xml(), &archive);
  EXPECT_TRUE(findings.empty()) << describe(findings);
}

TEST(fmi_check_model_exchange, binary_named_after_model_exchange_identifier) {
  const archive_listing archive = {"modelDescription.xml", "binaries/linux64/other.so"};
  const auto findings = check_model_description(valid_me_xml(), &archive);
  ASSERT_EQ(rules_of(findings), std::set<std::string>{"archive.binary"}) << describe(findings);
  EXPECT_NE(findings[0].message.find("binaries/linux64/check_me.so (named after "
                                     "ModelExchange@modelIdentifier)"),
            std::string::npos)
      << findings[0].message;
}

TEST(fmi_check_model_exchange, both_interfaces_with_one_identifier_share_a_binary) {
  const std::string xml = with_co_simulation("\n  <CoSimulation modelIdentifier=\"check_me\"/>");
  const archive_listing archive = {"modelDescription.xml", "binaries/linux64/check_me.so"};
  const auto findings = check_model_description(xml, &archive);
  EXPECT_TRUE(findings.empty()) << describe(findings);
  const archive_listing empty;
  const auto without = check_model_description(xml, &empty);
  ASSERT_EQ(without.size(), 1u) << describe(without);
  EXPECT_NE(without[0].message.find("CoSimulation@modelIdentifier and "
                                    "ModelExchange@modelIdentifier"),
            std::string::npos)
      << without[0].message;
}

TEST(fmi_check_model_exchange, both_interfaces_with_two_identifiers_need_two_binaries) {
  const std::string xml = with_co_simulation();
  const archive_listing both = {"modelDescription.xml", "binaries/linux64/check_me.so",
                                "binaries/linux64/check_cs.so"};
  const auto ok = check_model_description(xml, &both);
  EXPECT_TRUE(ok.empty()) << describe(ok);
  for (const std::string kept : {"check_me", "check_cs"}) {
    const archive_listing one = {"modelDescription.xml", "binaries/linux64/" + kept + ".so"};
    const auto findings = check_model_description(xml, &one);
    ASSERT_EQ(rules_of(findings), std::set<std::string>{"archive.binary"}) << describe(findings);
    EXPECT_EQ(findings.size(), 1u) << describe(findings);
    const std::string lost = kept == "check_me" ? "check_cs" : "check_me";
    EXPECT_NE(findings[0].message.find("binaries/linux64/" + lost + ".so"), std::string::npos)
        << findings[0].message;
  }
}

TEST(fmi_check_model_exchange, co_simulation_only_rules_stay_as_they_were) {
  // reinit and a derivative missing from <Derivatives> are Model Exchange matters: a
  // Co-Simulation-only FMU ignores <Derivatives>, so the same text passes without
  // <ModelExchange>
  const defect d{"co_simulation_instead",
                 {{"re:<ModelExchange[^>]*/>", k_co_simulation_element},
                  {"re:<Derivatives>[\\s\\S]*</Derivatives>", ""},
                  {"re:<InitialUnknowns>[\\s\\S]*</InitialUnknowns>", ""}},
                 ""};
  const auto cs = check_model_description(test::apply(d, valid_me_xml()));
  EXPECT_TRUE(cs.empty()) << describe(cs);
  const defect me{"model_exchange_too",
                  {{"re:<Derivatives>[\\s\\S]*</Derivatives>", ""},
                   {"re:<InitialUnknowns>[\\s\\S]*</InitialUnknowns>", ""}},
                  ""};
  const auto both = check_model_description(test::apply(me, with_co_simulation()));
  EXPECT_TRUE(has_rule(both, "me.derivative_unlisted", error)) << describe(both);
  EXPECT_TRUE(has_rule(both, "me.reinit", error)) << describe(both);
}

}  // namespace

}  // namespace stride::fmi_check::test
