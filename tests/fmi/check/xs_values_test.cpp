// The XML Schema value parsers behind every checker (fmi/check/src/xs_values.cpp): what
// fmi2ModelDescription.xsd accepts for xs:boolean, xs:unsignedInt, xs:int, xs:double and
// xs:dateTime, and nothing more.
#include "xs_values.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string_view>
#include <vector>

namespace stride::fmi_check::detail {
namespace {

TEST(fmi_check_xs_values, whitespace_is_xml_whitespace) {
  EXPECT_EQ(trim(" \t\r\nx y\n"), "x y");
  const std::vector<std::string_view> parts{"1", "2", "3"};
  EXPECT_EQ(split_ws("  1\t2\n\n3 "), parts);
  EXPECT_TRUE(split_ws(" \t ").empty());
}

TEST(fmi_check_xs_values, boolean) {
  EXPECT_EQ(parse_xs_boolean(" true "), true);
  EXPECT_EQ(parse_xs_boolean("0"), false);
  EXPECT_FALSE(parse_xs_boolean("True"));
  EXPECT_FALSE(parse_xs_boolean("yes"));
  EXPECT_FALSE(parse_xs_boolean(""));
}

TEST(fmi_check_xs_values, unsigned_int_range_and_signs) {
  EXPECT_EQ(parse_xs_unsigned_int("+4294967295"), 4294967295u);
  EXPECT_EQ(parse_xs_unsigned_int("007"), 7u);
  EXPECT_FALSE(parse_xs_unsigned_int("4294967296"));
  EXPECT_FALSE(parse_xs_unsigned_int("-0"));
  EXPECT_FALSE(parse_xs_unsigned_int("+"));
  EXPECT_FALSE(parse_xs_unsigned_int("1 2"));
}

TEST(fmi_check_xs_values, int_covers_exactly_32_bits) {
  EXPECT_EQ(parse_xs_int("-2147483648"), std::numeric_limits<std::int32_t>::min());
  EXPECT_EQ(parse_xs_int("+2147483647"), std::numeric_limits<std::int32_t>::max());
  EXPECT_FALSE(parse_xs_int("2147483648"));
  EXPECT_FALSE(parse_xs_int("-2147483649"));
  EXPECT_FALSE(parse_xs_int("+-1"));
  EXPECT_FALSE(parse_xs_int("1.0"));
}

TEST(fmi_check_xs_values, long_covers_exactly_64_bits) {
  EXPECT_EQ(parse_xs_long("-9223372036854775808"), std::numeric_limits<std::int64_t>::min());
  EXPECT_EQ(parse_xs_long("+9223372036854775807"), std::numeric_limits<std::int64_t>::max());
  EXPECT_EQ(parse_xs_long(" -42 "), -42);
  EXPECT_FALSE(parse_xs_long("9223372036854775808"));
  EXPECT_FALSE(parse_xs_long("-9223372036854775809"));
  EXPECT_FALSE(parse_xs_long("1e3"));
  EXPECT_FALSE(parse_xs_long("-"));
}

TEST(fmi_check_xs_values, unsigned_long_covers_exactly_64_bits) {
  EXPECT_EQ(parse_xs_unsigned_long("18446744073709551615"),
            std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(parse_xs_unsigned_long("+0"), 0u);
  EXPECT_FALSE(parse_xs_unsigned_long("18446744073709551616"));
  EXPECT_FALSE(parse_xs_unsigned_long("-1"));
  EXPECT_FALSE(parse_xs_unsigned_long(""));
}

TEST(fmi_check_xs_values, hex_binary_is_pairs_of_hex_digits) {
  EXPECT_TRUE(is_xs_hex_binary("666f6F"));
  EXPECT_TRUE(is_xs_hex_binary(""));
  EXPECT_FALSE(is_xs_hex_binary("666"));
  EXPECT_FALSE(is_xs_hex_binary("0x66"));
  EXPECT_FALSE(is_xs_hex_binary("66 6f"));
}

TEST(fmi_check_xs_values, double_lexical_forms) {
  EXPECT_EQ(parse_xs_double("1.5E3"), 1500.0);
  EXPECT_EQ(parse_xs_double("+.5"), 0.5);
  EXPECT_EQ(parse_xs_double("5."), 5.0);
  EXPECT_EQ(parse_xs_double("-INF"), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(parse_xs_double("+INF"), std::numeric_limits<double>::infinity());
  const auto nan = parse_xs_double("NaN");
  ASSERT_TRUE(nan);
  EXPECT_TRUE(std::isnan(*nan));
  // spellings from_chars would take but the schema does not
  EXPECT_FALSE(parse_xs_double("nan"));
  EXPECT_FALSE(parse_xs_double("inf"));
  EXPECT_FALSE(parse_xs_double("+-1"));
  EXPECT_FALSE(parse_xs_double("0x1p3"));
  EXPECT_FALSE(parse_xs_double("1e"));
  EXPECT_FALSE(parse_xs_double("1,5"));
  EXPECT_FALSE(parse_xs_double(""));
}

TEST(fmi_check_xs_values, date_time_fields_are_range_checked) {
  EXPECT_TRUE(is_xs_date_time("2026-12-03T04:00:00Z"));
  EXPECT_TRUE(is_xs_date_time("2024-02-29T23:59:59.125+14:00"));
  EXPECT_TRUE(is_xs_date_time("2026-12-03T24:00:00"));
  EXPECT_FALSE(is_xs_date_time("2026-02-29T00:00:00"));  // not a leap year
  EXPECT_FALSE(is_xs_date_time("2026-12-03T24:00:01"));
  EXPECT_FALSE(is_xs_date_time("2026-13-01T00:00:00"));
  EXPECT_FALSE(is_xs_date_time("0000-01-01T00:00:00"));
  EXPECT_FALSE(is_xs_date_time("2026-12-03T04:00:00+14:30"));
  EXPECT_FALSE(is_xs_date_time("2026-12-03 04:00:00"));
  // years of any length: no overflow, and leap years still follow the calendar
  EXPECT_TRUE(is_xs_date_time("123456789012345678901236-02-29T00:00:00"));
  EXPECT_FALSE(is_xs_date_time("123456789012345678901900-02-29T00:00:00"));
  EXPECT_TRUE(is_xs_date_time("-0044-03-15T12:00:00"));
}

TEST(fmi_check_xs_values, c_identifier_and_quote) {
  EXPECT_TRUE(is_c_identifier("_robot2"));
  EXPECT_FALSE(is_c_identifier("2robot"));
  EXPECT_FALSE(is_c_identifier("robot-fmu"));
  EXPECT_FALSE(is_c_identifier(""));
  EXPECT_EQ(quote("gait"), "\"gait\"");
}

}  // namespace
}  // namespace stride::fmi_check::detail
