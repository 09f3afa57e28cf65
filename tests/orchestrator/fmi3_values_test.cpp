// Stride's value channels over the FMI 3.0 typed calls, with the test FMU's relations as the
// oracle: every kind, arrays whole and by element, hex Binary, and the range errors.
#include "fmi3_values.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "fmi3_fixture.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim {
namespace {

using test::batch;
using ::testing::HasSubstr;

const duration k_step = std::chrono::milliseconds(100);

class fmi3_values_test : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-fmi3-values-test-"};
  std::shared_ptr<fmu> f = fmu::load(test::k_fmi3_kinds, test::extract_into(scratch.path()));

  // One step with `in` as inputs, returning the outputs of `out`.
  value_block step_with(component& c, const batch& in, const variable_refs& out) {
    c.expose(in.refs, out);
    value_block result;
    result.resize_for(out);
    EXPECT_EQ(c.step(time_point{}, k_step, in.values, result), step_result::complete);
    return result;
  }

  std::string set_error(component& c, const batch& in) {
    try {
      c.set_values(in.refs, in.values);
    } catch (const component_error& e) {
      return e.what();
    }
    return "<no error>";
  }
};

TEST_F(fmi3_values_test, every_integer_kind_adds_one_per_step) {
  auto c = test::stepping_fmi3_kinds(f);
  batch in;
  variable_refs out;
  const std::vector<std::string> kinds = {"i8", "u8", "i16", "u16", "i32", "u32", "i64", "u64"};
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    in.integer(*c, kinds[i] + "_in", static_cast<int>(7 * i + 3));
    out.integers.push_back(test::ref(*c, kinds[i] + "_out"));
  }
  const auto result = step_with(*c, in, out);
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    EXPECT_EQ(result.integers[i], static_cast<int>(7 * i + 3) + 1) << kinds[i];
  }
}

TEST_F(fmi3_values_test, floats_booleans_strings_and_binary_follow_their_relations) {
  auto c = test::stepping_fmi3_kinds(f);
  batch in;
  in.real(*c, "f32_in", 0.25).real(*c, "f64_in", 4.5).boolean(*c, "b_in", true);
  in.string(*c, "s_in", "walk").string(*c, "bin_in", "0102ab");
  variable_refs out;
  for (const char* name : {"f32_out", "f64_out"}) out.reals.push_back(test::ref(*c, name));
  out.booleans.push_back(test::ref(*c, "b_out"));
  out.strings = {test::ref(*c, "s_out"), test::ref(*c, "bin_out")};
  const auto result = step_with(*c, in, out);
  EXPECT_EQ(result.reals[0], 1.25);           // f32: in + 1, exact in binary
  EXPECT_EQ(result.reals[1], 2.0 * 4.5 + 1);  // gain * in + steps (one step)
  EXPECT_FALSE(result.booleans[0]);
  EXPECT_EQ(result.strings[0], "walk!");
  EXPECT_EQ(result.strings[1], "ab0201");  // the bytes reversed, as hex text
}

TEST_F(fmi3_values_test, start_values_reach_the_outputs_untouched) {
  auto c = test::stepping_fmi3_kinds(f);
  variable_refs out;
  out.strings = {test::ref(*c, "bin_out"), test::ref(*c, "s_out")};
  out.reals = {test::ref(*c, "series_out[4]")};
  value_block v;
  c->get_values(out, v);
  EXPECT_EQ(v.strings[0], "feca");  // start "cafe" reversed
  EXPECT_EQ(v.strings[1], "stride!");
  EXPECT_EQ(v.reals[0], 1 + 2 + 3 + 4);
}

TEST_F(fmi3_values_test, arrays_are_read_and_written_whole_or_by_element) {
  auto c = test::stepping_fmi3_kinds(f);
  // one element of each numeric array: the others keep their start values 10, 20, 30
  batch in;
  for (const char* k : {"f32", "f64"}) in.real(*c, std::string(k) + "_ain[2]", 5);
  for (const char* k : {"i8", "u8", "i16", "u16", "i32", "u32", "i64", "u64"}) {
    in.integer(*c, std::string(k) + "_ain[2]", 5);
  }
  variable_refs out;
  for (const char* k : {"f32", "f64"}) {
    for (int i = 1; i <= 3; ++i) {
      out.reals.push_back(test::ref(*c, std::string(k) + "_aout[" + std::to_string(i) + "]"));
    }
  }
  for (const char* k : {"i8", "u8", "i16", "u16", "i32", "u32", "i64", "u64"}) {
    for (int i = 1; i <= 3; ++i) {
      out.integers.push_back(test::ref(*c, std::string(k) + "_aout[" + std::to_string(i) + "]"));
    }
  }
  const auto result = step_with(*c, in, out);
  const std::vector<double> expected = {10 + 1, 5 + 2, 30 + 3};
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(result.reals[3 * k + i], expected[i]);
  }
  for (std::size_t k = 0; k < 8; ++k) {
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(result.integers[3 * k + i], expected[i]);
  }
  // the whole array, in a different order than declared
  batch all;
  all.real(*c, "series_in[4]", 40).real(*c, "series_in[1]", 10);
  all.real(*c, "series_in[3]", 30).real(*c, "series_in[2]", 20);
  variable_refs sums;
  for (int i = 1; i <= 4; ++i) {
    sums.reals.push_back(test::ref(*c, "series_out[" + std::to_string(i) + "]"));
  }
  const auto s = step_with(*c, all, sums);
  EXPECT_EQ(s.reals, (std::vector<double>{10, 30, 60, 100}));
}

TEST_F(fmi3_values_test, integers_outside_the_fmi3_kind_are_refused_naming_the_port) {
  auto c = test::stepping_fmi3_kinds(f);
  EXPECT_THAT(set_error(*c, batch().integer(*c, "i8_in", 200)),
              HasSubstr("component 'k': value 200 of k.i8_in does not fit FMI 3 Int8"));
  EXPECT_THAT(set_error(*c, batch().integer(*c, "u8_ain[3]", -1)),
              HasSubstr("value -1 of k.u8_ain[3] does not fit FMI 3 UInt8"));
  EXPECT_THAT(set_error(*c, batch().integer(*c, "u64_in", -5)),
              HasSubstr("value -5 of k.u64_in does not fit FMI 3 UInt64"));
  EXPECT_THAT(set_error(*c, batch().integer(*c, "i16_in", 40000)), HasSubstr("FMI 3 Int16"));
  EXPECT_THAT(set_error(*c, batch().real(*c, "f32_in", 1e39)),
              HasSubstr("value 1e+39 of k.f32_in does not fit FMI 3 Float32"));
  // the limits themselves fit
  EXPECT_EQ(set_error(*c, batch().integer(*c, "i8_in", -128).integer(*c, "u16_in", 65535)),
            "<no error>");
}

TEST_F(fmi3_values_test, a_refused_batch_changes_no_element) {
  auto c = test::stepping_fmi3_kinds(f);
  // element 1 fits, element 3 does not: the array keeps 10 20 30
  EXPECT_THAT(set_error(*c, batch().integer(*c, "u8_ain[1]", 1).integer(*c, "u8_ain[3]", 300)),
              HasSubstr("value 300 of k.u8_ain[3] does not fit FMI 3 UInt8"));
  variable_refs out;
  out.integers = {test::ref(*c, "u8_aout[1]")};
  EXPECT_EQ(step_with(*c, batch().integer(*c, "u8_ain[2]", 0), out).integers[0], 10 + 1);
}

TEST_F(fmi3_values_test, fmi3_integers_beyond_32_bits_are_refused_when_read) {
  auto c = test::stepping_fmi3_kinds(f);
  variable_refs big;
  big.integers = {test::ref(*c, "big")};
  value_block v;
  try {
    c->get_values(big, v);
    FAIL() << "read " << v.integers.at(0);
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("value 5000000000 of k.big does not fit Stride's 32-bit "
                                    "integers"));
  }
  // u32_out = in + 1 leaves the int range exactly at the top
  variable_refs u32;
  u32.integers = {test::ref(*c, "u32_out")};
  EXPECT_EQ(step_with(*c, batch().integer(*c, "u32_in", 2147483646), u32).integers[0], 2147483647);
  EXPECT_THROW(step_with(*c, batch().integer(*c, "u32_in", 2147483647), u32), component_error);
}

TEST_F(fmi3_values_test, a_non_finite_float_is_not_passed_on) {
  auto c = test::stepping_fmi3_kinds(f);
  variable_refs out;
  out.reals = {test::ref(*c, "f64_out")};
  try {
    step_with(*c, batch().real(*c, "f64_in", INFINITY), out);
    FAIL() << "no error";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("fmi3GetFloat64 gave k.f64_out = inf, not a finite number"));
  }
}

TEST_F(fmi3_values_test, binary_must_be_hex_text) {
  auto c = test::stepping_fmi3_kinds(f);
  EXPECT_THAT(set_error(*c, batch().string(*c, "bin_in", "xyz")),
              HasSubstr("\"xyz\" for the Binary variable k.bin_in is not hex text"));
  EXPECT_THAT(set_error(*c, batch().string(*c, "bin_in", "abc")), HasSubstr("not hex text"));
  EXPECT_EQ(set_error(*c, batch().string(*c, "bin_in", "")), "<no error>");  // zero bytes
}

TEST_F(fmi3_values_test, a_reference_of_the_wrong_channel_is_refused) {
  auto c = test::stepping_fmi3_kinds(f);
  batch wrong;
  wrong.refs.reals = {test::ref(*c, "i8_in")};
  wrong.values.reals = {1.0};
  EXPECT_THAT(set_error(*c, wrong),
              HasSubstr("value reference " + std::to_string(test::ref(*c, "i8_in")) +
                        " is not a port of type Real"));
  batch beyond;
  beyond.refs.integers = {100000};
  beyond.values.integers = {1};
  EXPECT_THAT(set_error(*c, beyond),
              HasSubstr("value reference 100000 is not a port of type Integer"));
}

TEST_F(fmi3_values_test, an_fmu_refusal_names_the_fmi3_function) {
  auto c = test::stepping_fmi3_kinds(f);
  // gain is a fixed parameter: the FMU refuses it in step mode
  EXPECT_THAT(set_error(*c, batch().real(*c, "gain", 3)),
              HasSubstr("component 'k': fmi3SetFloat64 returned fmi3Error"));
}

}  // namespace
}  // namespace stride::cosim
