// fmi3Get*/fmi3Set* of glue3_values.cpp on the linked-in stride_test component: arrays travel
// whole, nValues must match, the independent variable reads the time, bad values are refused.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>

#include "fmi3_harness.hpp"
#include "stride/sdk/fmu.hpp"

namespace stride::test {
namespace {

TEST(glue3_values, an_array_is_set_and_read_whole) {
  fmi3_harness h;
  h.to_step_mode();
  const fmi3ValueReference in = fmi3_harness::vr("vec_in"), out = fmi3_harness::vr("vec_out");
  const double values[3] = {1.0, -2.0, 0.5};
  ASSERT_EQ(fmi3SetFloat64(h.instance(), &in, 1, values, 3), fmi3OK);
  ASSERT_EQ(h.step(0, 0.1), fmi3OK);
  double got[3] = {};
  ASSERT_EQ(fmi3GetFloat64(h.instance(), &out, 1, got, 3), fmi3OK);
  EXPECT_DOUBLE_EQ(got[0], 2.0);  // vec_out = 2 * vec_in
  EXPECT_DOUBLE_EQ(got[1], -4.0);
  EXPECT_DOUBLE_EQ(got[2], 1.0);
}

TEST(glue3_values, scalars_and_arrays_mix_in_one_call) {
  fmi3_harness h;
  h.to_step_mode();
  const fmi3ValueReference vrs[] = {fmi3_harness::vr("u"), fmi3_harness::vr("vec_in"),
                                    fmi3_harness::vr("gain")};
  const double values[] = {4.0, 1.0, 2.0, 3.0, 0.5};
  ASSERT_EQ(fmi3SetFloat64(h.instance(), vrs, 3, values, 5), fmi3OK);
  double got[5] = {};
  ASSERT_EQ(fmi3GetFloat64(h.instance(), vrs, 3, got, 5), fmi3OK);
  for (int k = 0; k < 5; ++k) EXPECT_DOUBLE_EQ(got[k], values[k]) << k;
  EXPECT_DOUBLE_EQ(h.get_float64("y"), 0.5 * 4.0);  // the new gain times the new u
}

TEST(glue3_values, wrong_value_counts_change_nothing) {
  fmi3_harness h;
  h.to_step_mode();
  const fmi3ValueReference in = fmi3_harness::vr("vec_in");
  const double values[3] = {7, 8, 9};
  EXPECT_EQ(fmi3SetFloat64(h.instance(), &in, 1, values, 2), fmi3Error);
  EXPECT_TRUE(h.logged("nValues is 2, the value references name 3 values"));
  EXPECT_EQ(fmi3SetFloat64(h.instance(), &in, 1, values, 4), fmi3Error);
  double got[4] = {-1, -1, -1, -1};
  EXPECT_EQ(fmi3GetFloat64(h.instance(), &in, 1, got, 4), fmi3Error);
  ASSERT_EQ(fmi3GetFloat64(h.instance(), &in, 1, got, 3), fmi3OK);
  EXPECT_EQ(got[0], 0.0);  // still the start values
  EXPECT_EQ(got[2], 0.0);
}

TEST(glue3_values, an_element_reference_other_than_the_first_is_no_variable) {
  fmi3_harness h;
  h.to_initialization_mode();
  const sdk::variable* second = sdk::detail::registered_fmu().table.find("vec_in[2]");
  ASSERT_NE(second, nullptr);
  const fmi3ValueReference vr = second->value_reference;
  double x = 0;
  EXPECT_EQ(fmi3GetFloat64(h.instance(), &vr, 1, &x, 1), fmi3Error);
  EXPECT_TRUE(h.logged("no Float64 variable has value reference " + std::to_string(vr)));
}

TEST(glue3_values, time_is_read_but_not_written) {
  fmi3_harness h;
  h.to_step_mode();
  ASSERT_EQ(h.step(0, 0.125), fmi3OK);
  ASSERT_EQ(h.step(0.125, 0.125), fmi3OK);
  EXPECT_DOUBLE_EQ(h.get_float64("time"), 0.25);
  EXPECT_EQ(h.set_float64("time", 1.0), fmi3Error);
  EXPECT_TRUE(h.logged("'time' cannot be set"));
}

TEST(glue3_values, types_are_checked_per_value_reference) {
  fmi3_harness h;
  h.to_initialization_mode();
  const fmi3ValueReference u = fmi3_harness::vr("u");
  fmi3Int32 i = 0;
  EXPECT_EQ(fmi3GetInt32(h.instance(), &u, 1, &i, 1), fmi3Error);
  EXPECT_TRUE(h.logged("no Int32 variable has value reference"));
  fmi3UInt8 b = 0;
  EXPECT_EQ(fmi3GetUInt8(h.instance(), &u, 1, &b, 1), fmi3Error);
  EXPECT_TRUE(h.logged("no UInt8 variable"));
}

TEST(glue3_values, non_finite_and_out_of_range_values_are_refused_by_name) {
  fmi3_harness h;
  h.to_step_mode();
  EXPECT_EQ(h.set_float64("u", std::numeric_limits<double>::quiet_NaN()), fmi3Error);
  EXPECT_TRUE(h.logged("'u'"));
  EXPECT_EQ(h.set_float64("gain", 2e6), fmi3Error);  // range(-1e6, 1e6)
  EXPECT_TRUE(h.logged("'gain'"));
  EXPECT_EQ(h.get_float64("u"), 0.0);
}

TEST(glue3_values, integers_booleans_and_strings) {
  fmi3_harness h;
  h.to_initialization_mode();
  const fmi3ValueReference n = fmi3_harness::vr("n"), counter = fmi3_harness::vr("counter");
  const fmi3Int32 four = 4;
  ASSERT_EQ(fmi3SetInt32(h.instance(), &n, 1, &four, 1), fmi3OK);
  const fmi3ValueReference enable = fmi3_harness::vr("enable"), active = fmi3_harness::vr("active");
  const fmi3Boolean off = fmi3False;
  ASSERT_EQ(fmi3SetBoolean(h.instance(), &enable, 1, &off, 1), fmi3OK);
  const fmi3ValueReference suffix = fmi3_harness::vr("suffix"), echo = fmi3_harness::vr("echo");
  const fmi3String text = "-3";
  ASSERT_EQ(fmi3SetString(h.instance(), &suffix, 1, &text, 1), fmi3OK);
  ASSERT_EQ(fmi3ExitInitializationMode(h.instance()), fmi3OK);
  ASSERT_EQ(h.step(0, 0.1), fmi3OK);
  fmi3Int32 c = -1;
  ASSERT_EQ(fmi3GetInt32(h.instance(), &counter, 1, &c, 1), fmi3OK);
  EXPECT_EQ(c, 5);  // 0 + 1 + n
  fmi3Boolean a = fmi3True;
  ASSERT_EQ(fmi3GetBoolean(h.instance(), &active, 1, &a, 1), fmi3OK);
  EXPECT_FALSE(a);
  fmi3String e = nullptr;
  ASSERT_EQ(fmi3GetString(h.instance(), &echo, 1, &e, 1), fmi3OK);
  EXPECT_STREQ(e, "stride-3");  // label's start value + suffix
  const fmi3String null_text = nullptr;
  EXPECT_EQ(fmi3SetString(h.instance(), &suffix, 1, &null_text, 1), fmi3Error);
  EXPECT_TRUE(h.logged("'suffix': null string"));
}

TEST(glue3_values, null_arrays_are_refused) {
  fmi3_harness h;
  double x;
  EXPECT_EQ(fmi3GetFloat64(h.instance(), nullptr, 1, &x, 1), fmi3Error);
  const fmi3ValueReference u = fmi3_harness::vr("u");
  EXPECT_EQ(fmi3SetFloat64(h.instance(), &u, 1, nullptr, 1), fmi3Error);
  EXPECT_TRUE(h.logged("null array argument"));
}

}  // namespace
}  // namespace stride::test
