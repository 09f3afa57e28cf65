// The FMI 3.0 view of a variable table: indexed members grouped into arrays, time appended.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "fmi3_variables.hpp"
#include "stride/sdk/variable_table.hpp"

namespace stride::test {
namespace {

struct data {
  double a = 1;
  double v[4] = {1, 2, 3, 4};
  int k = 0;
  double time = 0;
};

sdk::variable_table table_of(bool with_time) {
  sdk::table_builder<data> t;
  t.add("a", &data::a).input();
  t.add("v", &data::v).output();
  t.add("k", &data::k).parameter();
  if (with_time) t.add("time", &data::time).output();
  return t.finish();
}

TEST(fmi3_variables, an_indexed_member_is_one_array) {
  const sdk::variable_table table = table_of(false);
  const sdk::fmi3_variables vars(table);
  ASSERT_EQ(vars.all().size(), 4u);  // a, v, k, time
  const sdk::fmi3_variable& v = vars.all()[1];
  EXPECT_EQ(v.name, "v");
  EXPECT_TRUE(v.is_array);
  EXPECT_EQ(v.count, 4u);
  EXPECT_EQ(v.value_reference, table.find("v[1]")->value_reference);
  EXPECT_EQ(&v.element(3), table.find("v[4]"));
  EXPECT_FALSE(vars.all()[0].is_array);
}

TEST(fmi3_variables, only_first_elements_and_time_are_value_references) {
  const sdk::variable_table table = table_of(false);
  const sdk::fmi3_variables vars(table);
  EXPECT_EQ(vars.find(table.find("v[1]")->value_reference)->name, "v");
  EXPECT_EQ(vars.find(table.find("v[2]")->value_reference), nullptr);
  EXPECT_TRUE(vars.find(vars.time().value_reference)->is_time());
  std::uint32_t highest = 0;
  for (const sdk::variable& e : table.variables()) highest = std::max(highest, e.value_reference);
  EXPECT_EQ(vars.time().value_reference, highest + 1);
  EXPECT_EQ(vars.find(highest + 2), nullptr);
}

TEST(fmi3_variables, every_element_has_its_owner) {
  const sdk::variable_table table = table_of(false);
  const sdk::fmi3_variables vars(table);
  EXPECT_EQ(vars.owner(*table.find("v[3]")).name, "v");
  EXPECT_EQ(vars.owner(*table.find("k")).name, "k");
}

TEST(fmi3_variables, a_table_variable_called_time_is_refused) {
  const sdk::variable_table table = table_of(true);
  EXPECT_THROW(sdk::fmi3_variables{table}, std::logic_error);
}

}  // namespace
}  // namespace stride::test
