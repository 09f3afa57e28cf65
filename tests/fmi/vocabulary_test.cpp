// stride::fmi2 vocabulary: every enumerator has its FMI spelling, and parsing inverts it.
#include <gtest/gtest.h>

#include <set>
#include <string_view>

#include "stride/fmi2/fmi2_api.h"
#include "stride/fmi2/vocabulary.hpp"

namespace stride::test {
namespace {

using namespace stride::fmi2;

TEST(fmi2_vocabulary, spellings_are_the_fmi_ones) {
  EXPECT_EQ(to_string(value_type::real), "Real");
  EXPECT_EQ(to_string(value_type::enumeration), "Enumeration");
  EXPECT_EQ(to_string(causality::calculated_parameter), "calculatedParameter");
  EXPECT_EQ(to_string(causality::independent), "independent");
  EXPECT_EQ(to_string(variability::tunable), "tunable");
  EXPECT_EQ(to_string(initial_kind::approx), "approx");
  EXPECT_EQ(to_string(initial_kind::none), "");
  EXPECT_EQ(to_string(status::ok), "fmi2OK");
  EXPECT_EQ(to_string(status::pending), "fmi2Pending");
  EXPECT_EQ(to_string(static_cast<status>(42)), "unknown status");
}

template <class Enum, std::size_t N, class Parse>
void expect_round_trip(const Enum (&all)[N], Parse parse) {
  std::set<std::string_view> seen;
  for (Enum e : all) {
    const std::string_view text = to_string(e);
    EXPECT_TRUE(seen.insert(text).second) << "spelled twice: " << text;
    EXPECT_EQ(text.data()[text.size()], '\0') << text;
    if (text.empty()) continue;  // initial_kind::none
    const auto parsed = parse(text);
    ASSERT_TRUE(parsed.has_value()) << text;
    EXPECT_EQ(*parsed, e) << text;
  }
}

TEST(fmi2_vocabulary, parsing_inverts_to_string) {
  expect_round_trip(all_value_types, parse_value_type);
  expect_round_trip(all_causalities, parse_causality);
  expect_round_trip(all_variabilities, parse_variability);
  expect_round_trip(all_initial_kinds, parse_initial_kind);
}

TEST(fmi2_vocabulary, parsing_rejects_other_spellings) {
  EXPECT_FALSE(parse_value_type("real"));
  EXPECT_FALSE(parse_value_type("Real "));
  EXPECT_FALSE(parse_causality("calculated_parameter"));
  EXPECT_FALSE(parse_causality(""));
  EXPECT_FALSE(parse_variability("Continuous"));
  EXPECT_FALSE(parse_initial_kind(""));  // an empty attribute is not "absent"
  EXPECT_FALSE(parse_initial_kind("given"));
}

TEST(fmi2_vocabulary, status_values_are_the_c_api_ones) {
  EXPECT_EQ(static_cast<int>(status::ok), fmi2OK);
  EXPECT_EQ(static_cast<int>(status::warning), fmi2Warning);
  EXPECT_EQ(static_cast<int>(status::discard), fmi2Discard);
  EXPECT_EQ(static_cast<int>(status::error), fmi2Error);
  EXPECT_EQ(static_cast<int>(status::fatal), fmi2Fatal);
  EXPECT_EQ(static_cast<int>(status::pending), fmi2Pending);
}

}  // namespace
}  // namespace stride::test
