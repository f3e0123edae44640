// The reader's fast path: text without quotes is scanned by csv_plain_reader, which must give
// exactly the records, fields, lines and columns of the general csv_record_reader.

#include "data/csv_engine.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/random_csv.hpp"

namespace pgm::csv_engine_tests {
namespace {

struct scanned {
  std::vector<std::vector<detail::csv_field>> records;
  std::size_t lines = 0;
};

scanned general(std::string_view text) {
  scanned result;
  detail::csv_record_reader reader(text, ',', true, {0, 0, 0});
  std::vector<detail::csv_field> fields;
  while (reader.next(fields) == detail::csv_record::complete) result.records.push_back(fields);
  result.lines = reader.cursor().line;
  return result;
}

scanned plain(std::string_view text) {
  scanned result;
  detail::csv_plain_reader reader(text, ',');
  std::vector<detail::csv_field> fields;
  while (reader.next(fields)) result.records.push_back(fields);
  result.lines = reader.lines();
  return result;
}

void expect_same(std::string_view text) {
  const auto expected = general(text);
  const auto actual = plain(text);
  const std::string context = "text: '" + std::string(text.substr(0, 200)) + "'";
  ASSERT_EQ(actual.records.size(), expected.records.size()) << context;
  EXPECT_EQ(actual.lines, expected.lines) << context;
  for (std::size_t r = 0; r < expected.records.size(); ++r) {
    ASSERT_EQ(actual.records[r].size(), expected.records[r].size()) << context << " record " << r;
    for (std::size_t f = 0; f < expected.records[r].size(); ++f) {
      const auto& a = actual.records[r][f];
      const auto& e = expected.records[r][f];
      EXPECT_EQ(a.text, e.text) << context << " record " << r << " field " << f;
      EXPECT_EQ(a.line, e.line) << context << " record " << r << " field " << f;
      EXPECT_EQ(a.column, e.column) << context << " record " << r << " field " << f;
    }
  }
}

TEST(csv_engine_test, plain_reader_reads_as_the_general_reader) {
  for (const std::string text :
       {"", "\n", "a", "a\n", "a,b\n1,2", "a,b\r\n1,2\r\n", " a , b \n\t1\t,2 \n", "a,b\n\n  \n\t\r\n1,2\n   ",
        "a\rb\rc", "a,\n,\n,,\n", "x, y\r\r\n z\n", "a,b\n \r x,1\n", "1e3,-0,1.0,01\n"}) {
    expect_same(text);
  }
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const auto csv = testing::make_random_csv(seed, {.rows = 300, .quotes = false, .final_newline = seed % 3 != 0});
    const std::string_view text(csv.text);
    ASSERT_EQ(text.find('"'), std::string_view::npos);
    expect_same(text.substr(detail::byte_order_mark(text)));
  }
}

TEST(csv_engine_test, a_lone_cr_ends_a_blank_line_as_it_ends_a_record) {
  // A chunk may start at any line's start, a lone CR's included, so a blank line ends where a
  // record's line would: "\r b" is the line " b", not an empty field before it. (The fuzzer
  // found two readings of one file that differed here.)
  for (const bool quoted : {false, true}) {
    const std::string text = std::string(quoted ? "\"a\"" : "a") + "\r\r\r\n\r b\r\r c\n";
    std::vector<detail::csv_field> fields;
    std::vector<std::pair<std::string, std::size_t>> seen;  // text, line
    const auto lines = detail::for_each_record(text, ',', fields, [&](const auto& record) {
      ASSERT_EQ(record.size(), 1u);
      seen.emplace_back(record[0].text, record[0].line);
    });
    EXPECT_EQ(lines, 7u) << "quoted " << quoted;
    EXPECT_EQ(seen, (std::vector<std::pair<std::string, std::size_t>>{{"a", 0}, {"b", 4}, {"c", 6}}))
        << "quoted " << quoted;
  }
  expect_same("x\r\r\n\ry\r \t\rz");
}

TEST(csv_engine_test, records_are_read_alike_with_and_without_quotes) {
  // for_each_record takes the plain reader only for text without a quote.
  std::vector<detail::csv_field> fields;
  std::vector<std::string> seen;
  const auto lines = detail::for_each_record("a,\"b\nc\"\n\nd,e\n", ',', fields, [&](const auto& record) {
    for (const auto& field : record) seen.emplace_back(field.text);
  });
  EXPECT_EQ(lines, 4u);
  EXPECT_EQ(seen, (std::vector<std::string>{"a", "b\nc", "d", "e"}));
  seen.clear();
  EXPECT_EQ(detail::for_each_record("a,b\n\nd,e", ',', fields,
                                    [&](const auto& record) {
                                      for (const auto& field : record) seen.emplace_back(field.text);
                                    }),
            2u);
  EXPECT_EQ(seen, (std::vector<std::string>{"a", "b", "d", "e"}));
}

}  // namespace
}  // namespace pgm::csv_engine_tests
