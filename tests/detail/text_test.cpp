// How pgm reads the numbers users type (docs/limits.md, "Numbers"): parse_double and the
// reasons number_hint gives for what it refuses.

#include "pgm/detail/text.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace pgm::detail {
namespace {

using ::testing::HasSubstr;

TEST(numbers_test, decimal_numbers_are_read_as_written) {
  EXPECT_EQ(parse_double("0.5"), 0.5);
  EXPECT_EQ(parse_double("+0.5"), 0.5);
  EXPECT_EQ(parse_double("5e-1"), 0.5);
  EXPECT_EQ(parse_double(".5"), 0.5);
  EXPECT_EQ(parse_double("-0"), 0.0);              // -0 is 0 ...
  EXPECT_TRUE(std::signbit(*parse_double("-0")));  // ... though its sign survives parsing
  EXPECT_EQ(parse_double("1e-400"), 0.0);          // underflow is a number
  for (const auto* text : {"0.5", "-0", "1e-400", "17"}) EXPECT_EQ(number_hint(text), "") << text;
}

TEST(numbers_test, what_is_not_a_number_is_never_read_as_another) {
  for (const auto* text : {"0x1p-3", "0x10", "1,5", "1,000", "1 000", "1_000", "1'000", "", "-", "e5", "1e"}) {
    const auto value = parse_double(text);
    EXPECT_FALSE(value) << text << " read as " << *value;
  }
  EXPECT_TRUE(std::isinf(*parse_double("1e400")));  // callers refuse it with number_hint's reason
  EXPECT_TRUE(std::isnan(*parse_double("nan")));
}

TEST(numbers_test, the_reason_names_what_was_probably_meant) {
  EXPECT_EQ(number_hint("nan"), "NaN is not accepted");
  EXPECT_EQ(number_hint("-NaN"), "NaN is not accepted");
  EXPECT_EQ(number_hint("inf"), "infinities are not accepted");
  EXPECT_EQ(number_hint("-Infinity"), "infinities are not accepted");
  EXPECT_THAT(number_hint("1e400"), HasSubstr("out of the range of a double"));
  EXPECT_THAT(number_hint("-1e400"), HasSubstr("out of the range of a double"));
  EXPECT_THAT(number_hint("0x1p-3"), HasSubstr("hexadecimal is not accepted"));
  EXPECT_THAT(number_hint("-0X10"), HasSubstr("hexadecimal is not accepted"));
  EXPECT_EQ(number_hint("1,5"), "a comma is no decimal mark: write 1.5");
  EXPECT_EQ(number_hint("-0,25"), "a comma is no decimal mark: write -0.25");
  EXPECT_EQ(number_hint("1,000"), "neither thousands separators nor a decimal comma are accepted: write 1000 or 1.000");
  EXPECT_EQ(number_hint("1,000,000"), "thousands separators are not accepted: write 1000000");
  EXPECT_EQ(number_hint("abc"), "");
  EXPECT_EQ(number_hint("a,b"), "");
}

TEST(numbers_test, quoted_number_puts_the_reason_in_parentheses) {
  EXPECT_EQ(quoted_number("abc"), "'abc'");
  EXPECT_EQ(quoted_number("1,5"), "'1,5' (a comma is no decimal mark: write 1.5)");
}

}  // namespace
}  // namespace pgm::detail
