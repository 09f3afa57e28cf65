// Integer simulation time: parsing and formatting.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "stride/cosim/time.hpp"

namespace stride::cosim {
namespace {

using ::testing::HasSubstr;

TEST(cosim_time, parse_duration_is_exact) {
  EXPECT_EQ(parse_duration("0.008").count(), 8'000'000);
  EXPECT_EQ(parse_duration("60").count(), 60'000'000'000);
  EXPECT_EQ(parse_duration("1e-3").count(), 1'000'000);
  EXPECT_EQ(parse_duration("2.5E+1").count(), 25'000'000'000);
  EXPECT_EQ(parse_duration("-0.5").count(), -500'000'000);
  EXPECT_EQ(parse_duration("0.000000001").count(), 1);
  EXPECT_EQ(parse_duration("0").count(), 0);
  EXPECT_EQ(parse_duration(".25").count(), 250'000'000);
  EXPECT_THROW(parse_duration("0.0000000001"), std::invalid_argument);
  EXPECT_THROW(parse_duration("abc"), std::invalid_argument);
  EXPECT_THROW(parse_duration("1s"), std::invalid_argument);
  EXPECT_THROW(parse_duration(""), std::invalid_argument);
  EXPECT_THROW(parse_duration("1e30"), std::out_of_range);
}

TEST(cosim_time, format_seconds_round_trips) {
  for (const char* s : {"0", "0.008", "60", "-1.5", "99999.9", "0.000000001"}) {
    EXPECT_EQ(format_seconds(parse_duration(s)), s);
  }
  EXPECT_EQ(duration_from_seconds(0.008).count(), 8'000'000);
}

}  // namespace
}  // namespace stride::cosim
