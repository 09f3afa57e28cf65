// Values of any FMI type and their text form.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "stride/cosim/scalar_value.hpp"

namespace stride::cosim {
namespace {

using ::testing::HasSubstr;

TEST(cosim_scalar, parse_and_format) {
  EXPECT_EQ(std::get<double>(parse_scalar(variable_type::real, "1.5")), 1.5);
  EXPECT_EQ(std::get<int>(parse_scalar(variable_type::integer, "-3")), -3);
  EXPECT_EQ(std::get<bool>(parse_scalar(variable_type::boolean, "true")), true);
  EXPECT_EQ(std::get<bool>(parse_scalar(variable_type::boolean, "0")), false);
  EXPECT_EQ(std::get<std::string>(parse_scalar(variable_type::string, "a b")), "a b");
  EXPECT_THROW(parse_scalar(variable_type::real, "abc"), std::invalid_argument);
  EXPECT_THROW(parse_scalar(variable_type::integer, "1.5"), std::invalid_argument);
  EXPECT_THROW(parse_scalar(variable_type::boolean, "yes"), std::invalid_argument);
  EXPECT_EQ(format_scalar(0.1), "0.1");
}

// the lexical forms of xs:double and xs:int, which modelDescription.xml start values use too
TEST(cosim_scalar, numbers_may_carry_blanks_and_a_plus_sign_but_one_sign_only) {
  EXPECT_EQ(std::get<double>(parse_scalar(variable_type::real, " +1.5e1 ")), 15.0);
  EXPECT_EQ(std::get<int>(parse_scalar(variable_type::integer, "+7")), 7);
  EXPECT_EQ(std::get<bool>(parse_scalar(variable_type::boolean, " false\n")), false);
  EXPECT_THROW(parse_scalar(variable_type::real, "+-1"), std::invalid_argument);
  EXPECT_THROW(parse_scalar(variable_type::integer, "--1"), std::invalid_argument);
  EXPECT_THROW(parse_scalar(variable_type::real, ""), std::invalid_argument);
  EXPECT_THROW(parse_scalar(variable_type::integer, "2147483648"), std::invalid_argument);
  EXPECT_EQ(std::get<int>(parse_scalar(variable_type::integer, "-2147483648")),
            std::numeric_limits<int>::min());
  // a string keeps its blanks
  EXPECT_EQ(std::get<std::string>(parse_scalar(variable_type::string, " a ")), " a ");
}

// a Real given as text must be a finite number: infinities, NaN and overflow are refused
TEST(cosim_scalar, non_finite_reals_are_refused) {
  for (const char* text : {"inf", "-inf", "infinity", "nan", "-nan", "1e400", "-1e400"}) {
    EXPECT_THROW(parse_scalar(variable_type::real, text), std::invalid_argument) << text;
  }
  EXPECT_EQ(std::get<double>(parse_scalar(variable_type::real, "1.7976931348623157e308")),
            std::numeric_limits<double>::max());
}

}  // namespace
}  // namespace stride::cosim
