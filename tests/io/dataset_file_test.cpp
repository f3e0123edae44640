// The binary dataset file: what is written reads back exactly, and a file that was cut short,
// changed or is not one at all is an error naming it.

#include "pgm/io/dataset_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "support/folder_test.hpp"

namespace pgm::dataset_file_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// Every kind of column: doubles that text would round, codes of each width, interval edges,
// tags, and state labels that need quoting.
dataset awkward() {
  dataset d("awkward (made by hand)");
  d.add(continuous_column("x", {0.1 + 0.2, -0.0, 1e-310, std::numeric_limits<double>::max(), -3.5},
                          {"x-offset", "cm", "cube \"1\""}));
  d.add(discrete_column(variable("colour", {"Red", "Blue, dark", "Green"}), std::vector<unsigned>{0, 1, 2, 1, 0}));
  std::vector<std::string> many;
  for (int i = 0; i < 300; ++i) many.push_back("s" + std::to_string(i));
  d.add(discrete_column(variable("wide", many), std::vector<unsigned>{299, 0, 256, 7, 128}));
  d.add(discrete_column(variable::intervals("bin", {-1.0, 0.0, 2.5}, {"x-offset", "cm", ""}),
                        std::vector<unsigned>{1, 0, 0, 1, 1}));
  return d;
}

TEST(dataset_file_test, what_is_written_reads_back_exactly) {
  const auto data = awkward();
  const auto back = decode_dataset(encode_dataset(data, {{"task", "2-stack"}, {"seed", "18446744073709551615"}}), "a");
  EXPECT_EQ(back.data, data);
  EXPECT_EQ(back.data.source(), data.source());
  EXPECT_TRUE(std::signbit(back.data.continuous("x").values()[1])) << "-0 stays -0";
  EXPECT_EQ(back.data.discrete("wide").code_width(), 2U);
  EXPECT_EQ(back.data.discrete("bin").var().edges(), (std::vector<double>{-1.0, 0.0, 2.5}));
  EXPECT_EQ(back.meta.at("seed"), "18446744073709551615");
  EXPECT_EQ(back.meta.size(), 2U);

  const dataset empty("none");
  EXPECT_EQ(decode_dataset(encode_dataset(empty), "e").data, empty);
}

TEST(dataset_file_test, a_cut_short_or_lengthened_file_is_an_error) {
  const auto bytes = encode_dataset(awkward());
  EXPECT_THAT([&] { (void)decode_dataset(bytes.substr(0, bytes.size() - 3), "cut.pgmdata"); },
              ThrowsMessage<data_error>(HasSubstr("cut.pgmdata: truncated: the header promises")));
  EXPECT_THAT([&] { (void)decode_dataset(bytes.substr(0, bytes.find('\n') / 2), "half.pgmdata"); },
              ThrowsMessage<data_error>(HasSubstr("half.pgmdata: not a pgm-data file")));
  EXPECT_THAT([&] { (void)decode_dataset(bytes + "xy", "long.pgmdata"); },
              ThrowsMessage<data_error>(HasSubstr("long.pgmdata: 2 unexpected bytes after the data")));
}

TEST(dataset_file_test, a_changed_byte_is_found_by_the_checksum) {
  auto bytes = encode_dataset(awkward());
  bytes[bytes.find('\n') + 9] ^= 0x10;  // a bit of the second double
  EXPECT_THAT([&] { (void)decode_dataset(bytes, "flip.pgmdata"); },
              ThrowsMessage<data_error>(HasSubstr("flip.pgmdata: corrupt: the data's CRC-32 is")));
}

TEST(dataset_file_test, a_header_that_does_not_fit_its_data_is_an_error) {
  const auto bytes = encode_dataset(awkward());
  auto edited = [&](const std::string& from, const std::string& to) {
    auto copy = bytes;
    const auto at = copy.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return copy.replace(at, from.size(), to);
  };
  EXPECT_THAT([&] { (void)decode_dataset("plain text\n", "t.csv"); },
              ThrowsMessage<data_error>(HasSubstr("t.csv: not a pgm-data file")));
  EXPECT_THAT([&] { (void)decode_dataset(edited("\"pgm-data\"", "\"pgm-date\""), "f"); },
              ThrowsMessage<data_error>(HasSubstr("f: /format: expected \"pgm-data\"")));
  EXPECT_THAT([&] { (void)decode_dataset(edited("\"rows\":5", "\"rows\":6"), "r"); },
              ThrowsMessage<data_error>(HasSubstr("r: /columns/2: its data run past the end of the data")));
  EXPECT_THAT([&] { (void)decode_dataset(edited("\"rows\":5", "\"rows\":4"), "r"); },
              ThrowsMessage<data_error>(HasSubstr("r: /payload_bytes: 60 bytes, but the columns hold 48")));
  EXPECT_THAT([&] { (void)decode_dataset(edited("\"width\":2", "\"width\":1"), "w"); },
              ThrowsMessage<data_error>(HasSubstr("w: /columns/2/width: does not fit the variable's states")));
  EXPECT_THAT([&] { (void)decode_dataset(edited("\"kind\":\"discrete\"", "\"kind\":\"ordinal\""), "k"); },
              ThrowsMessage<data_error>(HasSubstr("k: /columns/1/kind: expected \"continuous\" or \"discrete\"")));
}

TEST(dataset_file_test, a_code_beyond_the_states_is_an_error) {
  dataset d;
  d.add(discrete_column(variable("c", {"a", "b"}), std::vector<unsigned>{0, 1}));
  auto bytes = encode_dataset(d);
  // The last code becomes 2, and the checksum is made to match, as a bad writer would.
  bytes.back() = 2;
  const auto newline = bytes.find('\n');
  const auto crc_at = bytes.find("\"crc32\":\"") + 9;
  bytes.replace(crc_at, 8, detail::crc32_hex(std::string_view(bytes).substr(newline + 1)));
  EXPECT_THAT(
      [&] { (void)decode_dataset(bytes, "c.pgmdata"); },
      ThrowsMessage<data_error>(HasSubstr("c.pgmdata: /columns/0: column 'c' row 2: state code 2 is out of range")));
}

using dataset_file_io_test = pgm::testing::folder_test;

TEST_F(dataset_file_io_test, files_are_written_whole_and_read_with_their_name_in_errors) {
  const auto at = path("d.pgmdata");
  write_dataset_file(at, awkward(), {{"k", "v"}});
  EXPECT_EQ(read_dataset_file(at).data, awkward());
  EXPECT_EQ(read_dataset_file(at).meta.at("k"), "v");
  EXPECT_THAT([&] { write_dataset_file(path("no/such/folder.pgmdata"), awkward()); },
              ThrowsMessage<io_error>(HasSubstr("does not exist")));
  EXPECT_THAT([&] { (void)read_dataset_file(path("missing.pgmdata")); },
              ThrowsMessage<io_error>(HasSubstr("missing.pgmdata")));
}

}  // namespace
}  // namespace pgm::dataset_file_tests
