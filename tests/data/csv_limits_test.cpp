// The CSV readers' limits (pgm/core/limits.hpp) and how they read the numbers users type
// (docs/limits.md): a header of 10^6 columns, a record of more than 64 MiB in memory, in a
// file and in an endless stream, and numbers written as other tools write them.

#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstddef>
#include <string>
#include <thread>

#include "pgm/core/limits.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/csv_counts.hpp"
#include "support/folder_test.hpp"

namespace pgm::csv_limits_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

using csv_limits_test = pgm::testing::folder_test;

family_counts count_all(csv_reader& input) {
  family_count_request request;
  request.columns = {input.header().front()};
  request.families = {{input.header().front(), {}}};
  return count_csv(input, request);
}

std::string wide_header(std::size_t columns) {
  std::string text;
  for (std::size_t i = 0; i < columns; ++i) text += (i ? ",c" : "c") + std::to_string(i);
  return text + "\n";
}

TEST(limits_test, a_header_of_a_million_columns_is_refused_at_the_first_column_past_the_limit) {
  const auto text = wide_header(1'000'000) + "1\n";
  const std::string message = "more than 65536 fields in a record, pgm's limit of CSV columns (docs/limits.md)";
  EXPECT_THAT([&] { static_cast<void>(parse_csv(text, "wide.csv")); },
              ThrowsMessage<parse_error>(
                  HasSubstr("wide.csv:1:" + std::to_string(text.find(",c65536,") + 2) + ": " + message)));
  EXPECT_THAT([&] { csv_reader input(text, "wide.csv"); }, ThrowsMessage<parse_error>(HasSubstr(message)));
  // At the limit the header is read (and quickly: duplicates are found by hashing).
  csv_reader input(wide_header(csv_max_columns), "wide.csv");
  EXPECT_EQ(input.header().size(), csv_max_columns);
}

TEST(limits_test, a_data_record_of_too_many_fields_is_refused_before_they_are_all_read) {
  const auto text = "a\n1\n" + std::string(200'000, ',') + "\n";
  EXPECT_THAT([&] { static_cast<void>(parse_csv(text, "d.csv")); },
              ThrowsMessage<parse_error>(HasSubstr("d.csv:3:65537: more than 65536 fields")));
}

TEST(limits_test, a_record_longer_than_64_mib_in_memory) {
  std::string text = "a,b\n1,2\n\"" + std::string(csv_max_record_bytes, 'x') + "\",3\n";
  EXPECT_THAT([&] { static_cast<void>(parse_csv(text, "long.csv")); },
              ThrowsMessage<parse_error>(HasSubstr(
                  "long.csv:3:1: a record longer than 64 MiB, pgm's limit of a CSV record (docs/limits.md)")));
  text = "a,b\n1,2\n" + std::string(csv_max_record_bytes, 'x') + ",3\n";  // no quote: the plain reader
  EXPECT_THAT([&] { static_cast<void>(parse_csv(text, "long.csv")); },
              ThrowsMessage<parse_error>(HasSubstr("long.csv:3:1: a record longer than 64 MiB")));
  EXPECT_THAT([&] { csv_reader header("\"" + std::string(csv_max_record_bytes, 'x') + "\"\n1\n", "h.csv"); },
              ThrowsMessage<parse_error>(HasSubstr("h.csv:1:1: a record longer than 64 MiB")));
}

TEST_F(csv_limits_test, a_record_longer_than_64_mib_in_a_file_is_refused_while_counting_it) {
  const auto csv = file("long.csv", "a\n1\n" + std::string(csv_max_record_bytes + 10, '7') + "\n2\n");
  csv_reader input(csv);
  EXPECT_THAT([&] { static_cast<void>(count_all(input)); },
              ThrowsMessage<parse_error>(HasSubstr("long.csv:3:1: a record longer than 64 MiB")));
  EXPECT_THAT([&] { static_cast<void>(read_csv(csv)); },
              ThrowsMessage<parse_error>(HasSubstr("long.csv:3:1: a record longer than 64 MiB")));
}

// A line of 1 GB from a pipe: both readers stop a little past the limit (the writer sees the
// pipe closed), so neither time nor memory grows with the line.
TEST_F(csv_limits_test, an_endless_line_from_a_pipe_is_refused_after_the_limit) {
  std::signal(SIGPIPE, SIG_IGN);
  const auto fifo = path("endless.csv");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  constexpr std::size_t gigabyte = std::size_t{1} << 30;
  for (const bool counting : {true, false}) {
    std::size_t written = 0;
    {
      std::jthread writer([&] {
        const int fd = ::open(fifo.c_str(), O_WRONLY);
        const std::string head = "a\n1\n";
        if (::write(fd, head.data(), head.size()) < 0) return;
        const std::string block(1 << 16, '5');
        while (written < gigabyte) {
          const auto n = ::write(fd, block.data(), block.size());
          if (n <= 0) break;  // the reader gave up
          written += static_cast<std::size_t>(n);
        }
        ::close(fd);
      });
      if (counting) {
        csv_reader input(fifo);
        EXPECT_THAT([&] { static_cast<void>(count_all(input)); },
                    ThrowsMessage<parse_error>(HasSubstr("endless.csv:3:1: a record longer than 64 MiB")));
      } else {
        EXPECT_THAT([&] { static_cast<void>(read_csv(fifo)); },
                    ThrowsMessage<parse_error>(HasSubstr("endless.csv:3:1: a record longer than 64 MiB")));
      }
    }
    EXPECT_LT(written, 4 * csv_max_record_bytes) << (counting ? "count_csv" : "read_csv");
  }
}

TEST(numbers_in_csv_test, numbers_written_otherwise_are_refused_with_the_reason) {
  csv_options continuous;
  continuous.default_kind = column_kind::continuous;
  const auto fails = [&](const std::string& value, const std::string& message) {
    EXPECT_THAT([&] { static_cast<void>(parse_csv("x\n1\n" + value + "\n", "n.csv", continuous)); },
                ThrowsMessage<parse_error>(HasSubstr("n.csv:3:1: column 'x': " + message)))
        << value;
  };
  fails("\"1,5\"", "expected a number, got '1,5' (a comma is no decimal mark: write 1.5)");
  fails("\"1,000\"", "expected a number, got '1,000' (neither thousands separators nor a decimal comma are accepted");
  fails("0x1p-3", "expected a number, got '0x1p-3' (hexadecimal is not accepted: write the value in decimal)");
  fails("1e400", "'1e400' is not a finite number (out of the range of a double");
  fails("nan", "'nan' is not a finite number (NaN is not accepted)");
  fails("-inf", "'-inf' is not a finite number (infinities are not accepted)");
  // In an automatic column the same values are text: the column is one of labels.
  EXPECT_TRUE(parse_csv("x\n1\n\"1,5\"\n", "n.csv").is_discrete("x"));
}

TEST(numbers_in_csv_test, minus_zero_is_zero_and_underflow_is_zero) {
  const auto data = parse_csv("x\n-0\n1e-400\n+2.5\n", "n.csv");
  const auto& values = data.continuous("x").values();
  ASSERT_EQ(values.size(), 3u);
  EXPECT_EQ(values[0], 0.0);
  EXPECT_FALSE(std::signbit(values[0]));  // written back as 0, not -0
  EXPECT_EQ(values[1], 0.0);
  EXPECT_EQ(values[2], 2.5);
}

}  // namespace
}  // namespace pgm::csv_limits_tests
