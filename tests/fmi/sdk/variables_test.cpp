// Get/set dispatch through the variable table: types, causality rules, ranges, feedthrough.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "fmi_harness.hpp"

namespace stride::test {
namespace {

TEST(variables, start_values_after_initialization) {
  fmi_harness h;
  h.to_step_complete();
  EXPECT_EQ(h.get_real("gain"), 2.0);
  EXPECT_EQ(h.get_real("y"), 0.0);
  EXPECT_EQ(h.get_integer("counter"), 0);
  const fmi2ValueReference echo = fmi_harness::vr("echo");
  fmi2String text = nullptr;
  ASSERT_EQ(fmi2GetString(h.c(), &echo, 1, &text), fmi2OK);
  EXPECT_STREQ(text, "stride");
}

TEST(variables, feedthrough_output_follows_input_without_a_step) {
  fmi_harness h;
  h.to_step_complete();
  ASSERT_EQ(h.set_real("u", 3.0), fmi2OK);
  EXPECT_EQ(h.get_real("y"), 6.0);
  ASSERT_EQ(h.set_real("gain", -1.0), fmi2OK);  // tunable
  EXPECT_EQ(h.get_real("y"), -3.0);
}

TEST(variables, step_updates_state_outputs) {
  fmi_harness h;
  h.to_step_complete();
  const fmi2ValueReference in[] = {fmi_harness::vr("vec_in[1]"), fmi_harness::vr("vec_in[2]"),
                                   fmi_harness::vr("vec_in[3]")};
  const double values[] = {1.0, -2.0, 0.5};
  ASSERT_EQ(fmi2SetReal(h.c(), in, 3, values), fmi2OK);
  ASSERT_EQ(h.set_real("u", 2.0), fmi2OK);
  ASSERT_EQ(fmi2DoStep(h.c(), 0.0, 0.25, fmi2True), fmi2OK);
  EXPECT_EQ(h.get_real("vec_out[2]"), -4.0);
  EXPECT_EQ(h.get_real("integral"), 0.5);
  EXPECT_EQ(h.get_integer("counter"), 1);
}

TEST(variables, fixed_parameter_only_before_initialization_ends) {
  fmi_harness h;
  EXPECT_EQ(h.set_real("offset", 1.0), fmi2OK);
  h.to_initialization_mode();
  EXPECT_EQ(h.set_real("offset", 2.0), fmi2OK);
  ASSERT_EQ(fmi2ExitInitializationMode(h.c()), fmi2OK);
  EXPECT_EQ(h.set_real("offset", 3.0), fmi2Error);
  EXPECT_TRUE(h.logged("'offset' (parameter, fixed) cannot be set in state stepComplete"));
  EXPECT_EQ(h.get_real("offset"), 2.0);
}

TEST(variables, outputs_cannot_be_set) {
  fmi_harness h;
  EXPECT_EQ(h.set_real("y", 1.0), fmi2Error);
  EXPECT_TRUE(h.logged("'y' (output, continuous) cannot be set"));
}

TEST(variables, range_and_finiteness_checked) {
  fmi_harness h;
  EXPECT_EQ(h.set_real("offset", 1000.5), fmi2Error);
  EXPECT_TRUE(h.logged("'offset': value 1000.5 is outside [-1000, 1000]"));
  EXPECT_EQ(h.set_real("u", std::numeric_limits<double>::quiet_NaN()), fmi2Error);
  EXPECT_TRUE(h.logged("'u': value is not a finite number"));
  EXPECT_EQ(h.set_integer("stop_after_steps", -1), fmi2Error);
  EXPECT_EQ(h.set_integer("stop_after_steps", 0), fmi2OK);
}

// An infinity is refused as "not a finite number" by every kind of Real variable (input, array
// element, tunable and fixed parameter) and leaves the value as it was; so is a NaN among finite
// values of one call, which stops the call at that value.
TEST(variables, infinities_are_refused_by_every_real_set) {
  const double inf = std::numeric_limits<double>::infinity();
  fmi_harness h;
  for (const char* name : {"u", "vec_in[2]", "gain", "offset"}) {
    for (const double x : {inf, -inf}) {
      h.clear_log();
      EXPECT_EQ(h.set_real(name, x), fmi2Error) << name << " = " << x;
      EXPECT_TRUE(h.logged(std::string("'") + name + "': value is not a finite number")) << name;
    }
  }
  const fmi2ValueReference refs[] = {fmi_harness::vr("vec_in[1]"), fmi_harness::vr("vec_in[2]")};
  const double values[] = {4.0, std::numeric_limits<double>::quiet_NaN()};
  EXPECT_EQ(fmi2SetReal(h.c(), refs, 2, values), fmi2Error);
  h.to_step_complete();
  EXPECT_EQ(h.get_real("gain"), 2.0);
  EXPECT_EQ(h.get_real("offset"), 0.0);
  EXPECT_EQ(h.get_real("y"), 0.0);  // u unchanged
  ASSERT_EQ(fmi2DoStep(h.c(), 0.0, 0.01, fmi2True), fmi2OK);
  EXPECT_EQ(h.get_real("vec_out[1]"), 8.0);  // the value before the refused one was taken
  EXPECT_EQ(h.get_real("vec_out[2]"), 0.0);
  // in step mode too
  EXPECT_EQ(h.set_real("u", -inf), fmi2Error);
  EXPECT_EQ(h.get_real("y"), 0.0);
}

TEST(variables, unknown_reference_or_wrong_type) {
  fmi_harness h;
  h.to_step_complete();
  const fmi2ValueReference bad = 9999;
  double v;
  EXPECT_EQ(fmi2GetReal(h.c(), &bad, 1, &v), fmi2Error);
  EXPECT_TRUE(h.logged("no Real variable has value reference 9999"));
  const fmi2ValueReference counter = fmi_harness::vr("counter");
  EXPECT_EQ(fmi2GetReal(h.c(), &counter, 1, &v), fmi2Error);
  EXPECT_EQ(fmi2GetReal(h.c(), nullptr, 1, &v), fmi2Error);
  EXPECT_EQ(fmi2GetReal(h.c(), nullptr, 0, nullptr), fmi2OK);
}

TEST(variables, strings_have_a_checked_capacity) {
  fmi_harness h;
  const fmi2ValueReference label = fmi_harness::vr("label");
  const std::string long_text(64, 'x');
  const fmi2String too_long = long_text.c_str();
  EXPECT_EQ(fmi2SetString(h.c(), &label, 1, &too_long), fmi2Error);
  EXPECT_TRUE(h.logged("exceeds the capacity of 63"));
  const fmi2String fits = "walker";
  ASSERT_EQ(fmi2SetString(h.c(), &label, 1, &fits), fmi2OK);
  const fmi2ValueReference suffix = fmi_harness::vr("suffix");
  const fmi2String bang = "!";
  ASSERT_EQ(fmi2SetString(h.c(), &suffix, 1, &bang), fmi2OK);
  h.to_step_complete();
  const fmi2ValueReference echo = fmi_harness::vr("echo");
  fmi2String text = nullptr;
  ASSERT_EQ(fmi2GetString(h.c(), &echo, 1, &text), fmi2OK);
  EXPECT_STREQ(text, "walker!");
  const fmi2String null_text = nullptr;
  EXPECT_EQ(fmi2SetString(h.c(), &suffix, 1, &null_text), fmi2Error);
}

TEST(variables, booleans_and_integers) {
  fmi_harness h;
  h.to_step_complete();
  const fmi2ValueReference enable = fmi_harness::vr("enable"), active = fmi_harness::vr("active");
  const fmi2Boolean off = fmi2False;
  ASSERT_EQ(fmi2SetBoolean(h.c(), &enable, 1, &off), fmi2OK);
  fmi2Boolean value = fmi2True;
  ASSERT_EQ(fmi2GetBoolean(h.c(), &active, 1, &value), fmi2OK);
  EXPECT_EQ(value, fmi2False);
  ASSERT_EQ(h.set_integer("n", 4), fmi2OK);
  ASSERT_EQ(fmi2DoStep(h.c(), 0.0, 0.01, fmi2True), fmi2OK);
  EXPECT_EQ(h.get_integer("counter"), 5);
}

TEST(variables, log_messages_with_percent_signs_are_not_formats) {
  fmi_harness h;
  const fmi2String category[] = {"cat%s%d%n"};
  EXPECT_EQ(fmi2SetDebugLogging(h.c(), fmi2True, 1, category), fmi2Error);
  EXPECT_TRUE(h.logged("unknown log category 'cat%s%d%n'"));
}

}  // namespace
}  // namespace stride::test
