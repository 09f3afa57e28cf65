// The checker of TypeDefinitions and of the type element of each variable
// (fmi/check/src/type_definitions_check.cpp).
#include <gtest/gtest.h>

#include "defects.hpp"

namespace stride::fmi_check::test {

const std::vector<defect> k_type_definitions_defects = {
    {"simple_type_without_name",
     {{"<SimpleType name=\"mode_type\">", "<SimpleType>"}},
     "type_definitions.name"},
    {"enumeration_without_declared_type",
     {{"<Enumeration declaredType=\"mode_type\" start=\"1\"/>", "<Enumeration start=\"1\"/>"}},
     "variable.type"},
    {"undefined_declared_type",
     {{"declaredType=\"mode_type\"", "declaredType=\"no_such_type\""}},
     "variable.declared_type"},
};

INSTANTIATE_TEST_SUITE_P(type_definitions, fmi_check_defect,
                         testing::ValuesIn(k_type_definitions_defects), defect_name);

}  // namespace stride::fmi_check::test
