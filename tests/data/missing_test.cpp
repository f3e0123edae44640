// Missing values (issue 18): the tokens, the three policies in read_csv and count_csv, the
// reserved code in a data set, counting over the rows present, and discretization.

#include "pgm/data/missing.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "data/csv_engine.hpp"
#include "pgm/data/bin_columns.hpp"
#include "pgm/data/discretizer.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/csv_counts.hpp"
#include "pgm/learn/independence_test.hpp"

namespace pgm::missing_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

csv_options with_policy(missing_policy policy, column_kind kind = column_kind::discrete) {
  csv_options options;
  options.default_kind = kind;
  options.missing.policy = policy;
  return options;
}

// a, b, c over six rows; row 2 lacks b (NA), row 4 lacks c (empty), row 5 lacks a (?).
constexpr std::string_view small = "a,b,c\nx,0,1\nx,NA,0\ny,1,1\ny,0,\n?,1,0\nx,1,1\n";

family_counts count_text(std::string_view text, const family_count_request& request) {
  csv_reader input(text, "m.csv");
  return count_csv(input, request);
}

family_count_request family_request(missing_policy policy, std::vector<family_names> families) {
  family_count_request request;
  request.columns = {"a", "b", "c"};
  request.families = std::move(families);
  request.missing.policy = policy;
  return request;
}

TEST(missing_test, the_tokens_match_exactly) {
  const detail::missing_matcher is_missing(missing_values{}.tokens);
  for (const char* text : {"NA", "", "?"}) EXPECT_TRUE(is_missing(text)) << text;
  for (const char* text : {"N", "NAN", "na", "??", "0", "Nope"}) EXPECT_FALSE(is_missing(text)) << text;
  const detail::missing_matcher dash({"-"});
  EXPECT_TRUE(dash("-"));
  EXPECT_FALSE(dash("NA"));
  EXPECT_FALSE(dash.empty_is_missing());
  for (const auto policy : missing_policies) EXPECT_EQ(parse_missing_policy(to_string(policy)), policy);
  EXPECT_THAT([] { static_cast<void>(parse_missing_policy("pairwise")); },
              ThrowsMessage<unknown_name>(
                  HasSubstr("unknown missing-value policy 'pairwise' (known: error, drop, available)")));
}

TEST(missing_test, by_default_the_first_missing_value_is_an_error_naming_its_place) {
  EXPECT_THAT([] { static_cast<void>(parse_csv(small, "m.csv")); },
              ThrowsMessage<parse_error>(HasSubstr("m.csv:3:3: column 'b': 'NA' is a missing value")));
  EXPECT_THAT([] { static_cast<void>(parse_csv("a,b\n1,2\n3,\n", "m.csv")); },
              ThrowsMessage<parse_error>(HasSubstr("m.csv:3:3: column 'b': the value is empty, a missing value")));
  EXPECT_THAT([] { static_cast<void>(parse_csv("a,b\n1,2\n?,3\n", "m.csv")); },
              ThrowsMessage<parse_error>(HasSubstr("m.csv:3:1: column 'a': '?' is a missing value")));
  EXPECT_THAT([] { static_cast<void>(parse_csv("a,b\n1,2\n?,3\n", "m.csv")); },
              ThrowsMessage<parse_error>(HasSubstr("choose the missing-value policy drop or available")));
  // The streaming counter says the same.
  EXPECT_THAT(
      [] {
        static_cast<void>(count_text(small, family_request(missing_policy::error, {{"a", {"b"}}})));
      },
      ThrowsMessage<parse_error>(HasSubstr("m.csv:3:3: column 'b': 'NA' is a missing value")));
  // A column not read is not checked.
  csv_options only_a;
  only_a.columns = {"a", "c"};
  EXPECT_THAT([&] { static_cast<void>(parse_csv(small, "m.csv", only_a)); },
              ThrowsMessage<parse_error>(HasSubstr("m.csv:5:5: column 'c': the value is empty")));
}

// Issue 28: a model that declares a state spelled like a missing token (pathfinder's "NA") has
// it read as that state in the variable's column, by every reader and policy; elsewhere it is
// still missing.
TEST(missing_test, a_state_the_model_spells_like_a_missing_token_is_that_state) {
  const std::string text = "a,b\nNA,x\nx,NA\nNA,y\n";
  const variable a("a", {"NA", "x"});
  for (const auto policy : {missing_policy::drop, missing_policy::available}) {
    auto options = with_policy(policy);
    options.variables.emplace("a", a);
    const auto [data, dropped] = parse_csv_data(text, "m.csv", options);
    EXPECT_EQ(dropped, policy == missing_policy::drop ? 1U : 0U);
    EXPECT_EQ(data.discrete("a").var(), a);
    EXPECT_EQ(data.discrete("a").missing(), 0U);
    EXPECT_EQ(data.discrete("a").code(0), 0U);  // NA, the state
    auto request = family_request(policy, {{"a", {"b"}}});
    request.columns = {"a", "b"};
    request.variables.emplace("a", a);
    const auto counts = count_text(text, request);
    EXPECT_EQ(counts.dropped, policy == missing_policy::drop ? 1U : 0U);
    EXPECT_EQ(counts.families[0].total(), 2U);  // rows 1 and 3; row 2 lacks b
  }
  auto options = with_policy(missing_policy::error);
  options.variables.emplace("a", a);
  EXPECT_THAT([&] { static_cast<void>(parse_csv_data(text, "m.csv", options)); },
              ThrowsMessage<missing_value_error>(HasSubstr("m.csv:3:3: column 'b': 'NA' is a missing value")));
}

TEST(missing_test, the_tokens_can_be_chosen) {
  csv_options options = with_policy(missing_policy::available);
  options.missing.tokens = {"-"};
  const auto data = parse_csv("a,b\nNA,-\n?,1\n", "m.csv", options);
  EXPECT_EQ(data.discrete("a").var().states(), (std::vector<std::string>{"?", "NA"}));  // states now
  EXPECT_EQ(data.discrete("a").missing(), 0u);
  EXPECT_EQ(data.discrete("b").missing(), 1u);
  // An empty field that is no token stays an error.
  EXPECT_THAT(
      [&] { static_cast<void>(parse_csv("a,b\n1,\n", "m.csv", options)); },
      ThrowsMessage<parse_error>(HasSubstr("m.csv:2:3: column 'b': the value is empty (the empty field is not")));
}

TEST(missing_test, drop_leaves_out_whole_rows_and_says_how_many) {
  const auto read = parse_csv_data(small, "m.csv", with_policy(missing_policy::drop));
  EXPECT_EQ(read.dropped, 3u);
  ASSERT_EQ(read.data.rows(), 3u);
  EXPECT_THAT(read.data.discrete("a").var().states(), ElementsAre("x", "y"));
  EXPECT_EQ(read.data.discrete("b").missing(), 0u);
  EXPECT_EQ(read.data.discrete("b").label(0), "0");
  EXPECT_EQ(read.data.discrete("b").label(2), "1");
  // A label seen only in a dropped row is no state.
  const auto only = parse_csv_data("a,b\nx,1\nz,NA\n", "m.csv", with_policy(missing_policy::drop));
  EXPECT_THAT(only.data.discrete("a").var().states(), ElementsAre("x"));
  const auto counts = count_text("a,b,c\nx,1,0\nz,NA,1\n", family_request(missing_policy::drop, {{"a", {"b"}}}));
  EXPECT_EQ(counts.dropped, 1u);
  EXPECT_EQ(counts.rows, 1u);
  EXPECT_THAT(counts.variables[0].states(), ElementsAre("x"));
  // Nothing left is an error that says why.
  EXPECT_THAT([] { static_cast<void>(parse_csv("a\nNA\n?\n", "m.csv", with_policy(missing_policy::drop))); },
              ThrowsMessage<data_error>(HasSubstr("m.csv: every one of the 2 data rows has a missing value")));
  EXPECT_THAT(
      [] {
        static_cast<void>(count_text("a,b,c\nNA,1,1\n", family_request(missing_policy::drop, {{"a", {}}})));
      },
      ThrowsMessage<data_error>(HasSubstr("every one of the 1 data rows has a missing value")));
}

TEST(missing_test, available_keeps_missing_values_in_the_data_set) {
  const auto data = parse_csv(small, "m.csv", with_policy(missing_policy::available));
  ASSERT_EQ(data.rows(), 6u);
  const auto& b = data.discrete("b");
  EXPECT_EQ(b.missing(), 1u);
  EXPECT_TRUE(b.is_missing(1));
  EXPECT_FALSE(b.is_missing(0));
  EXPECT_EQ(b.code(1), missing_code<std::uint8_t>);
  EXPECT_THAT([&] { static_cast<void>(b.label(1)); },
              ThrowsMessage<data_error>(HasSubstr("column 'b' row 2: the value is missing")));
  EXPECT_THAT(data.discrete("a").var().states(), ElementsAre("x", "y"));
  // Numbers: NaN, and the column stays continuous.
  const auto numbers =
      parse_csv("u,v\n1.5,2\nNA,3\n", "m.csv", with_policy(missing_policy::available, column_kind::automatic));
  EXPECT_TRUE(std::isnan(numbers.continuous("u").values()[1]));
  EXPECT_EQ(numbers.continuous("u").missing(), 1u);
  // A selection keeps the count right.
  const std::vector<std::size_t> rows{0, 1, 1};
  EXPECT_EQ(data.select_rows(rows).discrete("b").missing(), 2u);
  EXPECT_EQ(data.slice(2, 6).discrete("b").missing(), 0u);
}

TEST(missing_test, a_column_with_256_states_and_a_missing_value_takes_wider_codes) {
  std::string text = "s\n";
  for (int i = 0; i < 256; ++i) text += "v" + std::to_string(i) + "\n";
  const auto full = parse_csv(text, "m.csv", with_policy(missing_policy::available));
  EXPECT_EQ(full.discrete("s").code_width(), 1u);
  text += "NA\n";
  const auto data = parse_csv(text, "m.csv", with_policy(missing_policy::available));
  const auto& s = data.discrete("s");
  EXPECT_EQ(s.var().cardinality(), 256u);
  EXPECT_EQ(s.code_width(), 2u);
  EXPECT_TRUE(s.is_missing(256));
  EXPECT_FALSE(s.is_missing(255));
  EXPECT_EQ(count_family(s, {}).counts().size(), 256u);
}

// The counts of `small` by hand: each family over the rows where its variables are present.
TEST(missing_test, available_counts_each_family_over_its_present_rows) {
  const auto data = parse_csv(small, "m.csv", with_policy(missing_policy::available));
  // a | b: rows 1, 3, 4, 6 (row 2 lacks b, row 5 lacks a).
  // b=0: x (row 1), y (row 4); b=1: y (row 3), x (row 6). Layout: a fastest.
  const std::vector<std::string> b{"b"};
  const auto ab = count_family(data, "a", b);
  EXPECT_THAT(std::vector<std::uint64_t>(ab.counts().begin(), ab.counts().end()), ElementsAre(1, 1, 1, 1));
  // c | a: rows 1, 2, 3, 6 (row 4 lacks c, row 5 lacks a). a=x: c=1, 0, 1; a=y: c=1.
  const std::vector<std::string> a{"a"};
  const auto ca = count_family(data, "c", a);
  EXPECT_THAT(std::vector<std::uint64_t>(ca.counts().begin(), ca.counts().end()), ElementsAre(1, 2, 0, 1));
  // b alone: the five rows where b is present.
  const auto bb = count_family(data, "b", {});
  EXPECT_THAT(std::vector<std::uint64_t>(bb.counts().begin(), bb.counts().end()), ElementsAre(2, 3));
  // The streaming counter gives the same tables, for any chunking and threads.
  const std::vector<family_names> families{{"a", {"b"}}, {"c", {"a"}}, {"b", {}}};
  for (unsigned threads : {1u, 2u}) {
    for (std::size_t chunk : {std::size_t{1}, std::size_t{7}, std::size_t{0}}) {
      auto request = family_request(missing_policy::available, families);
      request.threads = threads;
      request.chunk_bytes = chunk;
      const auto counts = count_text(small, request);
      EXPECT_EQ(counts.rows, 6u);
      EXPECT_EQ(counts.families[0], ab) << threads << " " << chunk;
      EXPECT_EQ(counts.families[1], ca) << threads << " " << chunk;
      EXPECT_EQ(counts.families[2], bb) << threads << " " << chunk;
    }
  }
}

/// A random CSV of codes with about `rate` of the values missing (NA, empty or ?).
std::string random_missing_csv(unsigned seed, std::size_t rows, double rate) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> code(0, 3);
  std::uniform_real_distribution<double> unit(0, 1);
  const char* tokens[] = {"NA", "", "?"};
  std::string text = "p,q,r,s\n";
  for (std::size_t row = 0; row < rows; ++row) {
    for (int c = 0; c < 4; ++c) {
      if (c) text += ',';
      text += unit(random) < rate ? tokens[random() % 3] : std::to_string(code(random));
    }
    text += '\n';
  }
  return text;
}

TEST(missing_test, streamed_counts_equal_the_data_set_counts_and_add_up_over_byte_ranges) {
  const auto text = random_missing_csv(7, 3000, 0.05);
  const std::vector<family_names> families{{"p", {"q", "r"}}, {"s", {}}, {"r", {"s", "p"}}};
  for (auto policy : {missing_policy::drop, missing_policy::available}) {
    const auto read = parse_csv_data(text, "m.csv", with_policy(policy));
    family_count_request request;
    request.columns = {"p", "q", "r", "s"};
    request.families = families;
    request.missing.policy = policy;
    request.chunk_bytes = 300;
    request.window_bytes = 1000;
    const auto counts = count_text(text, request);
    EXPECT_EQ(counts.rows, read.data.rows());
    EXPECT_EQ(counts.dropped, read.dropped);
    for (std::size_t f = 0; f < families.size(); ++f) {
      EXPECT_EQ(counts.families[f], count_family(read.data, families[f].child, families[f].parents));
    }
    // The byte-range API: three ranges, summed in another order.
    csv_reader input(text, "m.csv");
    const csv_counter counter("m.csv", input.header(), request);
    const auto body = std::string_view(text).substr(text.find('\n') + 1);
    const auto cut1 = body.find('\n', body.size() / 3) + 1;
    const auto cut2 = body.find('\n', 2 * body.size() / 3) + 1;
    auto first = counter.count(body.substr(0, cut1), 2);
    auto second = counter.count(body.substr(cut1, cut2 - cut1), 2 + first.lines());
    auto third = counter.count(body.substr(cut2), 2 + first.lines() + second.lines());
    EXPECT_EQ(first.dropped() + second.dropped() + third.dropped(), read.dropped);
    csv_partial_counts total;
    total += std::move(third);
    total += std::move(first);
    total += std::move(second);
    const auto summed = counter.finish(total);
    EXPECT_EQ(summed.dropped, read.dropped);
    for (std::size_t f = 0; f < families.size(); ++f) EXPECT_EQ(summed.families[f], counts.families[f]);
  }
}

TEST(missing_test, an_independence_test_counts_the_rows_where_its_variables_are_present) {
  const auto text = random_missing_csv(11, 500, 0.1);
  const auto data = parse_csv(text, "m.csv", with_policy(missing_policy::available));
  const auto& p = data.discrete("p");
  const auto& q = data.discrete("q");
  const auto& r = data.discrete("r");
  std::vector<const discrete_column*> given{&r};
  std::vector<std::uint64_t> counts;
  detail::count_ci_table(p, q, given, counts, 2);
  // By hand: rows where p, q and r are all present.
  std::vector<std::uint64_t> expected(counts.size(), 0);
  std::uint64_t present = 0;
  for (std::size_t row = 0; row < data.rows(); ++row) {
    if (p.is_missing(row) || q.is_missing(row) || r.is_missing(row)) continue;
    ++present;
    ++expected[(r.code(row) * q.var().cardinality() + q.code(row)) * p.var().cardinality() + p.code(row)];
  }
  EXPECT_EQ(counts, expected);
  EXPECT_LT(present, data.rows());
  EXPECT_EQ(test_independence(counts, 4, 4, ci_test_options{}).rows, present);
}

TEST(missing_test, discretizing_keeps_missing_values_missing) {
  const auto data = parse_csv("x,y\n0.5,a\nNA,b\n2.5,a\n1.5,b\n3.5,a\n", "m.csv",
                              with_policy(missing_policy::available, column_kind::automatic));
  const auto edges = quantile_edges(data.continuous("x").values(), 2, "x");
  EXPECT_THAT(edges, ElementsAre(0.5, 2.0, 3.5));  // the quantiles of the four values present
  column_binning request;
  request.bins = 2;
  const auto binned = bin_columns(data, request);
  const auto& x = binned.data.discrete("x");
  EXPECT_EQ(x.missing(), 1u);
  EXPECT_TRUE(x.is_missing(1));
  std::ostringstream out;
  write_csv(binned.data, out, ',', "NA");
  EXPECT_EQ(out.str(), "x,y\n0,a\nNA,b\n1,a\n0,b\n1,a\n");  // bin indices
  std::ostringstream empty;
  write_csv(data, empty, ',', "");
  EXPECT_EQ(empty.str(), "x,y\n0.5,a\n,b\n2.5,a\n1.5,b\n3.5,a\n");
  EXPECT_THAT(
      [] {
        static_cast<void>(quantile_edges(std::vector<double>{1, INFINITY}, 2, "z"));
      },
      ThrowsMessage<data_error>(HasSubstr("column 'z' row 2: cannot discretize a value that is not finite")));
  EXPECT_THAT(
      [] {
        static_cast<void>(equal_width_edges(std::vector<double>{NAN, NAN}, 2, "z"));
      },
      ThrowsMessage<data_error>(HasSubstr("column 'z' has no values to discretize")));
}

}  // namespace
}  // namespace pgm::missing_tests
