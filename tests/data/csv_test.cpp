#include "pgm/io/csv.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "pgm/io/csv_counts.hpp"
#include "support/random_csv.hpp"

namespace pgm::csv_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

dataset parse(std::string_view text, const csv_options& options = {}) { return parse_csv(text, "runs.csv", options); }

TEST(csv_test, numeric_columns_are_continuous_text_columns_discrete) {
  const auto data = parse("xOff1,colour,onTop1\n0.5,Red,1\n-1.25,Blue,0\n3e-1,Red,1\n");
  EXPECT_EQ(data.rows(), 3u);
  EXPECT_THAT(data.continuous("xOff1").values(), ElementsAre(0.5, -1.25, 0.3));
  const auto& colour = data.discrete("colour");
  EXPECT_EQ(colour.var().states(), (std::vector<std::string>{"Blue", "Red"}));  // sorted
  EXPECT_EQ(colour.code(0), 1u);
  EXPECT_EQ(colour.code_width(), 1u);
  EXPECT_FALSE(data.is_discrete("onTop1"));
}

TEST(csv_test, discrete_numeric_labels_sort_numerically) {
  csv_options options;
  options.default_kind = column_kind::discrete;
  const auto data = parse("n\n10\n9\n-1\n9.0\n0.5\n", options);
  const auto& n = data.discrete("n");
  EXPECT_EQ(n.var().states(), (std::vector<std::string>{"-1", "0.5", "9", "10"}));  // "9.0" is 9
  EXPECT_EQ(n.code(0), 3u);
  EXPECT_EQ(n.code(3), 2u);
}

// Issue 28: two integers one double cannot tell apart are two states, read alike by the data
// set and the streaming counter; "1", "1.0" and "1e0" (and "0" and "-0") are one.
TEST(csv_test, labels_are_one_state_only_when_exactly_the_same_number) {
  csv_options options;
  options.default_kind = column_kind::discrete;
  const std::string text = "n,w\n9007199254740992,a\n9007199254740993,b\n1,a\n1.0,b\n1e0,a\n-0,b\n0,a\n";
  const auto data = parse(text, options);
  const auto& n = data.discrete("n");
  EXPECT_EQ(n.var().states(), (std::vector<std::string>{"-0", "1", "9007199254740992", "9007199254740993"}));
  EXPECT_THAT(std::vector<unsigned>({n.code(0), n.code(1), n.code(2), n.code(3), n.code(4), n.code(5), n.code(6)}),
              ElementsAre(2, 3, 1, 1, 1, 0, 0));
  family_count_request request;
  request.columns = {"n", "w"};
  request.families = {{"n", {"w"}}};
  csv_reader input(text, "runs.csv");
  EXPECT_EQ(count_csv(input, request).variables[0].states(), n.var().states());
}

// A label is a model's state when it is the state's text or exactly the same number.
TEST(csv_test, a_known_state_is_its_text_or_exactly_its_number) {
  csv_options options;
  options.variables.emplace("n", variable("n", {"0", "1", "2.5"}));
  const auto data = parse("n\n1.0\n2.50\n-0\n1\n", options);
  const auto& n = data.discrete("n");
  EXPECT_THAT(std::vector<unsigned>({n.code(0), n.code(1), n.code(2), n.code(3)}), ElementsAre(1, 2, 0, 1));
  family_count_request request;
  request.columns = {"n"};
  request.families = {{"n", {}}};
  request.variables.emplace("n", options.variables.at("n"));
  const std::string text = "n\n1.0\n2.50\n-0\n1\n";
  csv_reader input(text, "runs.csv");
  const auto counts = count_csv(input, request);
  EXPECT_EQ(counts.families[0](state_index(1), config_index(0)), 2U);
  EXPECT_THAT([&] { parse("n\n1.0\n2.51\n", options); },
              ThrowsMessage<parse_error>(
                  HasSubstr("runs.csv:3:1: column 'n': '2.51' is not a state of 'n' (states: 0, 1, 2.5)")));
}

TEST(csv_test, quoting_crlf_bom_and_blank_lines) {
  const auto data = parse(
      "\xEF\xBB\xBF"
      "name,note\r\n\"a, b\",\"say \"\"hi\"\"\"\r\n\r\nc,\"two\nlines\"\r\n  d , e \r\n");
  const auto& name = data.discrete("name");
  EXPECT_EQ(name.var().states(), (std::vector<std::string>{"a, b", "c", "d"}));
  const auto& note = data.discrete("note");
  EXPECT_EQ(note.label(0), "say \"hi\"");
  EXPECT_EQ(note.label(1), "two\nlines");
  EXPECT_EQ(note.label(2), "e");
}

TEST(csv_test, selects_columns_and_uses_known_variables) {
  csv_options options;
  options.columns = {"onTop1"};
  options.variables.emplace("onTop1", variable("onTop1", {"1", "0"}));
  const auto data = parse("x,onTop1\n1,0\n2,1\n", options);
  EXPECT_EQ(data.names(), (std::vector<std::string>{"onTop1"}));
  EXPECT_EQ(data.discrete("onTop1").code(0), 1u);  // the known order, not sorted
  options.columns = {"onTop1", "nope"};
  EXPECT_THAT([&] { parse("x,onTop1\n1,0\n", options); },
              ThrowsMessage<data_error>(HasSubstr("runs.csv: there is no column 'nope' (columns: x, onTop1)")));
}

TEST(csv_test, a_label_outside_a_known_variable_is_located) {
  csv_options options;
  options.variables.emplace("onTop1", variable("onTop1", {"0", "1"}));
  EXPECT_THAT([&] { parse("onTop1\n0\n2\n", options); },
              ThrowsMessage<parse_error>(
                  HasSubstr("runs.csv:3:1: column 'onTop1': '2' is not a state of 'onTop1' (states: 0, 1)")));
}

TEST(csv_test, non_numeric_value_in_numeric_column) {
  csv_options options;
  options.kinds["xOff1"] = column_kind::continuous;
  try {
    parse("id,xOff1\n1,0.5\n2,abc\n", options);
    FAIL();
  } catch (const parse_error& e) {
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.column(), 3u);
    EXPECT_EQ(e.file(), "runs.csv");
    EXPECT_THAT(e.what(), HasSubstr("column 'xOff1': expected a number, got 'abc'"));
  }
}

TEST(csv_test, nan_and_infinity_are_refused_in_numeric_columns) {
  EXPECT_THAT([] { parse("x\n1\nNaN\n2\n"); },
              ThrowsMessage<parse_error>(HasSubstr("runs.csv:3:1: column 'x': 'NaN' is not a finite number")));
  EXPECT_THAT([] { parse("x\n1\ninf\n"); }, ThrowsMessage<parse_error>(HasSubstr("not a finite number")));
  csv_options discrete;
  discrete.default_kind = column_kind::discrete;
  EXPECT_THAT([&] { parse("x\n1\nnan\n", discrete); }, ThrowsMessage<parse_error>(HasSubstr("runs.csv:3:1")));
  // In a text column "nan" is just a label.
  EXPECT_EQ(parse("x\nnan\nbread\n").discrete("x").var().cardinality(), 2u);
}

TEST(csv_test, empty_file_header_only_and_empty_values) {
  EXPECT_THAT([] { parse(""); }, ThrowsMessage<parse_error>(HasSubstr("runs.csv:1:1: the file is empty")));
  EXPECT_THAT([] { parse("\n \n"); }, ThrowsMessage<parse_error>(HasSubstr("the file is empty")));
  EXPECT_THAT([] { parse("a,b\n"); }, ThrowsMessage<data_error>(HasSubstr("no data rows")));
  csv_options allow;
  allow.allow_empty = true;
  EXPECT_EQ(parse("a,b\n", allow).rows(), 0u);
  EXPECT_THAT([] { parse("a,b\n1,\n"); },
              ThrowsMessage<parse_error>(HasSubstr("runs.csv:2:3: column 'b': the value is empty")));
}

TEST(csv_test, ragged_rows) {
  EXPECT_THAT([] { parse("a,b,c\n1,2,3\n1,2\n"); },
              ThrowsMessage<parse_error>(HasSubstr("runs.csv:3:3: expected 3 fields as in the header, found 2")));
  EXPECT_THAT([] { parse("a,b\n1,2,3\n"); },
              ThrowsMessage<parse_error>(HasSubstr("expected 2 fields as in the header, found 3")));
}

TEST(csv_test, malformed_quotes_and_headers) {
  EXPECT_THAT([] { parse("a\n\"open\n"); },
              ThrowsMessage<parse_error>(HasSubstr("runs.csv:2:1: a quoted field is never closed")));
  EXPECT_THAT([] { parse("a,b\n\"x\"y,1\n"); }, ThrowsMessage<parse_error>(HasSubstr("after a closing quote")));
  EXPECT_THAT([] { parse("a,a\n1,2\n"); },
              ThrowsMessage<parse_error>(HasSubstr("runs.csv:1:3: the column 'a' appears twice")));
  EXPECT_THAT([] { parse("a,,c\n1,2,3\n"); }, ThrowsMessage<parse_error>(HasSubstr("has no name")));
}

TEST(csv_test, three_hundred_states_use_wider_codes) {
  std::string text = "id\n";
  for (int i = 0; i < 600; ++i) text += "item" + std::to_string(i % 300) + "\n";
  const auto data = parse(text);
  const auto& id = data.discrete("id");
  EXPECT_EQ(id.var().cardinality(), 300u);
  EXPECT_EQ(id.code_width(), 2u);
  EXPECT_EQ(id.label(299), "item299");
  EXPECT_EQ(id.label(300), "item0");
}

TEST(csv_test, write_then_read_gives_the_same_bits) {
  std::mt19937_64 engine(3);
  std::vector<double> values;
  for (int i = 0; i < 1000; ++i) values.push_back(std::ldexp(static_cast<double>(engine()), -40) - 8e6);
  values.push_back(5e-324);
  values.push_back(-0.1);
  dataset data;
  data.add(continuous_column("x", values));
  std::vector<std::uint32_t> codes(values.size());
  for (std::size_t i = 0; i < codes.size(); ++i) codes[i] = static_cast<std::uint32_t>(i % 3);
  data.add(discrete_column(variable("label", {"a,b", "say \"x\"", " padded"}), codes));
  std::ostringstream out;
  write_csv(data, out);
  csv_options options;
  options.variables.emplace("label", data.discrete("label").var());
  const auto back = parse(out.str(), options);
  EXPECT_EQ(back, data);
}

TEST(csv_test, the_same_data_for_any_threads_and_chunk_size) {
  // Tiny chunks put a boundary at every line: inside quoted fields that hold line ends, between
  // the CR and LF of a line end, before blank lines.
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    for (const bool quotes : {false, true}) {
      const auto csv = testing::make_random_csv(seed, {.rows = 300, .quotes = quotes, .final_newline = seed % 2 == 0});
      for (const auto kind : {column_kind::automatic, column_kind::discrete}) {
        csv_options options;
        options.default_kind = kind;
        options.threads = 1;
        options.chunk_bytes = 1 << 20;
        const auto expected = parse(csv.text, options);
        ASSERT_EQ(expected.rows(), csv.rows);
        for (unsigned threads : {1u, 2u, 3u, 8u}) {
          for (std::size_t chunk : {1u, 2u, 7u, 64u, 0u}) {
            options.threads = threads;
            options.chunk_bytes = chunk;
            EXPECT_EQ(parse(csv.text, options), expected)
                << "seed " << seed << " quotes " << quotes << " threads " << threads << " chunk " << chunk;
          }
        }
      }
    }
  }
}

TEST(csv_test, tricky_text_in_tiny_chunks) {
  csv_options options;
  options.chunk_bytes = 1;
  options.threads = 4;
  // A quoted line end right at a chunk boundary, CRLF, blank lines with blanks, a BOM, numbers
  // written several ways, and no line end at the end.
  const auto data = parse(
      "\xEF\xBB\xBF"
      "id,label,n\r\n1,\"a\nb\",1e3\r\n\r\n  \t\n2,\"c,\r\nd\",-0\n3, plain ,1.0\n"
      "4,\"\"\"q\"\"\",1",
      options);
  EXPECT_EQ(data.rows(), 4u);
  EXPECT_THAT(data.continuous("n").values(), ElementsAre(1000.0, -0.0, 1.0, 1.0));
  const auto& label = data.discrete("label");
  EXPECT_EQ(label.label(0), "a\nb");
  EXPECT_EQ(label.label(1), "c,\r\nd");
  EXPECT_EQ(label.label(2), "plain");
  EXPECT_EQ(label.label(3), "\"q\"");
  options.default_kind = column_kind::discrete;
  const auto discrete = parse("n\n1\n1.0\n01\n-0\n0\n1e3\n1000\n", options);
  EXPECT_EQ(discrete.discrete("n").var().states(), (std::vector<std::string>{"-0", "1", "1e3"}));
  EXPECT_EQ(discrete.discrete("n").code(4), 0u);  // "0" is the state "-0"
  // A trailing delimiter is one more (empty) field.
  EXPECT_THAT([] { parse("a,b\n1,2,\n"); },
              ThrowsMessage<parse_error>(HasSubstr("runs.csv:2:5: expected 2 fields as in the header, found 3")));
  EXPECT_THAT([] { parse("a,b,\n1,2,\n"); },
              ThrowsMessage<parse_error>(HasSubstr("runs.csv:1:5: a column in the header has no name")));
  // A column that turns out to hold text in a later chunk is read as labels throughout.
  options.default_kind = column_kind::automatic;
  const auto mixed = parse("x\n1\n2\n2.0\nlate\n", options);
  EXPECT_EQ(mixed.discrete("x").var().states(), (std::vector<std::string>{"1", "2", "2.0", "late"}));
}

TEST(csv_test, lone_crs_read_alike_in_any_chunks) {
  // Lone CRs end lines, blank or not, wherever a chunk starts; an error names the same place.
  const std::string text = "x\n1\r\r\r\n\r-2\r\r3\r\n\r\r4";
  csv_options options;
  options.threads = 1;
  const auto whole = parse(text, options);
  EXPECT_THAT(whole.continuous("x").values(), ElementsAre(1.0, -2.0, 3.0, 4.0));
  const std::string bad = "x\n1\r\r\r\n\r-2\r\r,\r\n\r\r4";
  for (unsigned threads : {1u, 2u}) {
    for (std::size_t chunk : {1u, 2u, 3u, 5u, 0u}) {
      options.threads = threads;
      options.chunk_bytes = chunk;
      EXPECT_EQ(parse(text, options), whole) << "threads " << threads << " chunk " << chunk;
      EXPECT_THAT([&] { parse(bad, options); },
                  ThrowsMessage<parse_error>(HasSubstr("runs.csv:8:2: expected 1 fields as in the header, found 2")))
          << "threads " << threads << " chunk " << chunk;
    }
  }
}

TEST(csv_test, the_scanner_reads_records_one_at_a_time) {
  detail::csv_scanner scanner(
      "\xEF\xBB\xBF"
      "a,b\n\n\"x\ny\",2\r\n3 , 4",
      "s.csv", ',');
  std::vector<detail::csv_field> fields;
  ASSERT_TRUE(scanner.next(fields));
  EXPECT_EQ(fields[1].text, "b");
  ASSERT_TRUE(scanner.next(fields));
  EXPECT_EQ(scanner.record_line(), 3u);
  EXPECT_EQ(fields[0].text, "x\ny");
  EXPECT_EQ(fields[1].line, 4u);
  EXPECT_EQ(fields[1].column, 4u);
  ASSERT_TRUE(scanner.next(fields));
  EXPECT_EQ(fields[0].text, "3");
  EXPECT_EQ(fields[1].text, "4");
  EXPECT_FALSE(scanner.next(fields));
  detail::csv_scanner bad("a\n\"x\"y\n", "s.csv", ',');
  ASSERT_TRUE(bad.next(fields));
  EXPECT_THAT([&] { bad.next(fields); },
              ThrowsMessage<parse_error>(HasSubstr("s.csv:2:4: expected a delimiter or the end of the line")));
}

}  // namespace
}  // namespace pgm::csv_tests
