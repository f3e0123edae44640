// How pgm reads the numbers users type (docs/limits.md, "Numbers"): parse_double and the
// reasons number_hint gives for what it refuses.

#include "pgm/core/text.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace pgm::text::text_tests {
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

// What a message quotes from a bad file reaches the terminal escaped (issue 28).
TEST(printable_test, control_bytes_and_broken_utf8_are_escaped_and_the_rest_kept) {
  EXPECT_EQ(printable("plain ASCII, × and ≥ and ü"), "plain ASCII, × and ≥ and ü");
  EXPECT_EQ(printable("a\tb\nc\rd"), "a\\tb\\nc\\rd");
  EXPECT_EQ(printable("\x1b[31mred\x1b[0m"), "\\x1b[31mred\\x1b[0m");
  EXPECT_EQ(printable(std::string("nul\0here", 8)), "nul\\x00here");
  EXPECT_EQ(printable("del\x7f"), "del\\x7f");
  EXPECT_EQ(printable("c1 \xc2\x9b"), "c1 \\xc2\\x9b");         // CSI as a C1 control
  EXPECT_EQ(printable("latin1 caf\xe9!"), "latin1 caf\\xe9!");  // not UTF-8
  EXPECT_EQ(printable("cut \xe2\x82"), "cut \\xe2\\x82");       // a sequence cut short
  EXPECT_EQ(printable("overlong \xc0\xaf"), "overlong \\xc0\\xaf");
  EXPECT_EQ(printable("surrogate \xed\xa0\x80"), "surrogate \\xed\\xa0\\x80");
  EXPECT_EQ(printable("bidi \xe2\x80\xae"
                      "evil"),
            "bidi \\xe2\\x80\\xaeevil");  // U+202E
  EXPECT_EQ(printable("emoji \xf0\x9f\x99\x82"), "emoji \xf0\x9f\x99\x82");
}

TEST(closest_name_test, a_name_within_two_edits_is_suggested) {
  const std::vector<std::string> keys{"repetitions", "subsets", "epsilon", "bins", "map"};
  EXPECT_EQ(closest_name("repetitons", keys), "repetitions");
  EXPECT_EQ(closest_name("subests", keys), "subsets");  // a swap is one edit
  EXPECT_EQ(closest_name("bin", keys), "bins");
  EXPECT_EQ(closest_name("mpa", keys), "map");
  EXPECT_EQ(closest_name("colour", keys), std::nullopt);
  EXPECT_EQ(closest_name("x", keys), std::nullopt);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3U);
  EXPECT_EQ(edit_distance("", "abc"), 3U);
}

}  // namespace
}  // namespace pgm::text::text_tests
