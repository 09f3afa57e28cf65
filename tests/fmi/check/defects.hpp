// Single defects of modelDescription.xml: edits applied to the valid data/valid_minimal.xml and
// the rule that must report them. Each *_check_test.cpp lists the defects of its checker and
// instantiates fmi_check_defect with them; model_description_check_test.cpp defines the test.
#ifndef STRIDE_TESTS_FMI_CHECK_DEFECTS_HPP
#define STRIDE_TESTS_FMI_CHECK_DEFECTS_HPP

#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "stride/fmi_check/fmu_check.hpp"

namespace stride::fmi_check::test {

/// One defect: edits applied to the valid description, and the rule that must report it.
/// An edit whose `from` starts with "re:" is an ECMAScript regex; otherwise it is literal text
/// that must occur exactly once.
struct defect {
  std::string name;
  std::vector<std::pair<std::string, std::string>> edits;
  std::string rule;
  finding::severity level = finding::severity::error;
};

void PrintTo(const defect& d, std::ostream* os);

/// The text of data/valid_minimal.xml.
const std::string& valid_xml();
/// The text of data/valid_minimal3.xml, the FMI 3.0 counterpart.
const std::string& valid3_xml();
/// The text of data/valid_me.xml, a Model Exchange description.
const std::string& valid_me_xml();
/// `base` (valid_xml() by default) with the edits of `d` applied; an edit that does not apply
/// fails the test.
std::string apply(const defect& d, const std::string& base = valid_xml());
/// The findings one per line, as stride-fmu-check prints them.
std::string describe(const std::vector<finding>& findings);
bool has_rule(const std::vector<finding>& findings, std::string_view rule, finding::severity level);

class fmi_check_defect : public testing::TestWithParam<defect> {};
/// The same for defects of valid3_xml().
class fmi3_check_defect : public testing::TestWithParam<defect> {};

/// Test name suffix: the defect's name.
std::string defect_name(const testing::TestParamInfo<defect>& info);

// the defects of each checker, for the test that every rule id is known
extern const std::vector<defect> k_model_description_defects;
extern const std::vector<defect> k_root_defects;
extern const std::vector<defect> k_type_definitions_defects;
extern const std::vector<defect> k_variables_defects;
extern const std::vector<defect> k_start_values_defects;
extern const std::vector<defect> k_model_structure_defects;
extern const std::vector<defect> k_model_exchange_defects;
// and of the FMI 3.0 checkers
extern const std::vector<defect> k_root3_defects;
extern const std::vector<defect> k_variables3_defects;
extern const std::vector<defect> k_start_values3_defects;
extern const std::vector<defect> k_model_structure3_defects;

}  // namespace stride::fmi_check::test

#endif  // STRIDE_TESTS_FMI_CHECK_DEFECTS_HPP
