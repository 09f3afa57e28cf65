// The checker of start values and ranges (fmi/check/src/start_values_check.cpp).
#include <gtest/gtest.h>

#include "defects.hpp"

namespace stride::fmi_check::test {

const std::vector<defect> k_start_values_defects = {
    // start required or forbidden
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
    // values and ranges
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
};

INSTANTIATE_TEST_SUITE_P(start_values, fmi_check_defect, testing::ValuesIn(k_start_values_defects),
                         defect_name);

}  // namespace stride::fmi_check::test
