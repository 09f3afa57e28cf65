// The shared text helpers: INI and CSV field handling, number parsing and printing, name
// patterns, markup escaping.
#include "stride/common/text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace stride::text {
namespace {

TEST(common_text, case_insensitive_comparison_is_ascii_only) {
  EXPECT_TRUE(iequals("Walking Config", "walking config"));
  EXPECT_FALSE(iequals("period", "periods"));
  EXPECT_FALSE(iequals("a", "b"));
  EXPECT_EQ(lower("X_Offset 7"), "x_offset 7");
  EXPECT_EQ(lower("\xC3\x89"), "\xC3\x89");  // bytes outside ASCII are left alone
}

TEST(common_text, trim_removes_every_kind_of_blank_at_both_ends_only) {
  EXPECT_EQ(trim(" \t\r\n\f\vx y\t\r\n"), "x y");
  EXPECT_EQ(trim("   "), "");
  EXPECT_EQ(trim(""), "");
}

TEST(common_text, split_keeps_empty_fields) {
  const std::vector<std::string_view> expected{"a", "", "b", ""};
  EXPECT_EQ(split("a,,b,", ','), expected);
  EXPECT_EQ(split("", ','), std::vector<std::string_view>{""});
  EXPECT_EQ(split("a:b", ','), std::vector<std::string_view>{"a:b"});
}

TEST(common_text, csv_fields_honour_quotes) {
  const std::vector<std::string> expected{"a,b", "say \"hi\"", "", "c"};
  EXPECT_EQ(csv_fields("\"a,b\",\"say \"\"hi\"\"\",,c\r"), expected);
  // a carriage return inside quotes is data
  EXPECT_EQ(csv_fields("\"x\ry\""), std::vector<std::string>{"x\ry"});
  EXPECT_EQ(csv_fields(""), std::vector<std::string>{""});
}

TEST(common_text, parse_double_takes_a_whole_decimal_number) {
  EXPECT_EQ(parse_double(" 2.5e3 "), 2500.0);
  EXPECT_EQ(parse_double("+0.125"), 0.125);
  EXPECT_EQ(parse_double("-7"), -7.0);
  EXPECT_FALSE(parse_double("1.5x"));
  EXPECT_FALSE(parse_double("1,5"));
  EXPECT_FALSE(parse_double(""));
  EXPECT_FALSE(parse_double("+"));
  EXPECT_FALSE(parse_double("+-1"));
  EXPECT_FALSE(parse_double("0x10"));
}

// NaN and infinity parse; every reader that takes a physical value refuses them itself (with
// the file and line), so this helper must not hide them as "not a number" either.
TEST(common_text, parse_double_returns_non_finite_values_for_the_caller_to_refuse) {
  const auto nan = parse_double("nan");
  ASSERT_TRUE(nan);
  EXPECT_TRUE(std::isnan(*nan));
  EXPECT_EQ(parse_double("-inf"), -std::numeric_limits<double>::infinity());
}

TEST(common_text, parse_integer_refuses_fractions_and_overflow) {
  EXPECT_EQ(parse_integer(" +42 "), 42);
  EXPECT_EQ(parse_integer("-3"), -3);
  EXPECT_FALSE(parse_integer("4.0"));
  EXPECT_FALSE(parse_integer("1e3"));
  EXPECT_FALSE(parse_integer("99999999999999999999"));
  EXPECT_FALSE(parse_integer("+-3"));
  EXPECT_FALSE(parse_integer("++3"));
  EXPECT_FALSE(parse_integer(""));
}

TEST(common_text, format_double_reads_back_bit_for_bit) {
  for (const double v : {0.1, 1.0 / 3.0, -2.5e-300, 6.02214076e23, 1e16 + 2.0,
                         std::numeric_limits<double>::denorm_min()}) {
    const std::string s = format_double(v);
    const auto back = parse_double(s);
    ASSERT_TRUE(back) << s;
    EXPECT_EQ(*back, v) << s;
  }
  EXPECT_EQ(format_double(0.1), "0.1");  // shortest, not 17 digits
  EXPECT_EQ(format_double(32.0), "32");
}

TEST(common_text, glob_match_star_and_question_mark) {
  EXPECT_TRUE(glob_match("robot.*", "robot.base_x"));
  EXPECT_TRUE(glob_match("*", ""));
  EXPECT_TRUE(glob_match("a*b*c", "abbbc"));
  EXPECT_TRUE(glob_match("a*b*c", "axbyc"));
  EXPECT_FALSE(glob_match("a*b*c", "axbyd"));
  EXPECT_TRUE(glob_match("joint[??]", "joint[12]"));
  EXPECT_FALSE(glob_match("joint[??]", "joint[1]"));
  EXPECT_FALSE(glob_match("", "x"));
  EXPECT_TRUE(glob_match("x**", "x"));
}

TEST(common_text, xml_escape_replaces_markup_characters) {
  EXPECT_EQ(xml_escape("a<b & \"c\">d"), "a&lt;b &amp; &quot;c&quot;&gt;d");
  EXPECT_EQ(xml_escape("it's plain"), "it's plain");  // output attributes use double quotes
  EXPECT_EQ(xml_escape(""), "");
  EXPECT_EQ(xml_escape("&amp;"), "&amp;amp;");  // escaping is not idempotent, by design
}

}  // namespace
}  // namespace stride::text
