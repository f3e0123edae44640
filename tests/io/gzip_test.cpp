#include "pgm/io/gzip.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <string>

#include "pgm/io/network_file.hpp"
#include "support/folder_test.hpp"

namespace pgm::gzip_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// gzip data of `text`, made with zlib's deflate (window bits 15 + 16: a gzip wrapper).
std::string gzip(const std::string& text) {
  z_stream stream{};
  EXPECT_EQ(deflateInit2(&stream, Z_BEST_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY), Z_OK);
  std::string out(deflateBound(&stream, text.size()) + 32, '\0');
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  stream.avail_in = static_cast<uInt>(text.size());
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(deflate(&stream, Z_FINISH), Z_STREAM_END);
  out.resize(stream.total_out);
  deflateEnd(&stream);
  return out;
}

class gzip_models : public testing::folder_test {};

TEST_F(gzip_models, every_format_reads_the_same_network_compressed) {
  const auto network = read_network(std::filesystem::path(PGM_NETWORKS_DIR) / "asia.bif");
  for (const std::string extension : {".bif", ".xml", ".net", ".json"}) {
    const auto plain = path("asia" + extension);
    write_network(network, plain);
    const auto compressed = file("asia" + extension + ".gz", gzip(slurp(plain)));
    const auto read = read_network(compressed);
    ASSERT_EQ(read.size(), network.size()) << extension;
    for (std::size_t i = 0; i < network.size(); ++i) {
      const variable_id node = index_at<variable_id>(i);
      const auto a = read.table(node).values();
      const auto b = network.table(node).values();
      EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end())) << extension;
    }
    EXPECT_EQ(read_model(compressed).structure.size(), network.size()) << extension;
  }
}

TEST_F(gzip_models, gzip_data_is_known_by_its_magic_bytes_and_a_gz_name_requires_them) {
  const auto network = read_network(std::filesystem::path(PGM_NETWORKS_DIR) / "asia.bif");
  write_network(network, path("asia.bif"));
  const auto misnamed = file("compressed.bif", gzip(slurp(path("asia.bif"))));
  EXPECT_EQ(read_network(misnamed).size(), network.size());
  const auto plain = file("plain.bif.gz", slurp(path("asia.bif")));
  EXPECT_THAT([&] { static_cast<void>(read_network(plain)); }, ThrowsMessage<io_error>(HasSubstr("not gzip data")));
  EXPECT_THAT([&] { static_cast<void>(read_network(file("asia.txt.gz", gzip("x")))); },
              ThrowsMessage<io_error>(HasSubstr("not a network file")));
}

TEST_F(gzip_models, damaged_or_truncated_data_is_an_error) {
  const auto data = gzip(std::string(5000, 'a'));
  EXPECT_THAT([&] { static_cast<void>(inflate_gzip(data.substr(0, data.size() / 2), "half.gz", 1 << 20)); },
              ThrowsMessage<io_error>(HasSubstr("'half.gz': the gzip data ends early")));
  auto damaged = data;
  damaged[12] = static_cast<char>(damaged[12] ^ 0x5a);
  damaged[13] = static_cast<char>(damaged[13] ^ 0x5a);
  EXPECT_THROW(static_cast<void>(inflate_gzip(damaged, "damaged.gz", 1 << 20)), io_error);
  EXPECT_EQ(inflate_gzip(data, "whole.gz", 1 << 20), std::string(5000, 'a'));
  EXPECT_EQ(inflate_gzip(data + gzip("bc"), "two members.gz", 1 << 20), std::string(5000, 'a') + "bc");
}

// A small file that inflates past the bound stops at the bound, not after inflating it all.
TEST_F(gzip_models, inflating_stops_at_the_byte_bound) {
  const auto bomb = gzip(std::string(std::size_t{4} << 20, '\0'));
  EXPECT_LT(bomb.size(), 10000U);
  EXPECT_THAT([&] { static_cast<void>(inflate_gzip(bomb, "bomb.bif.gz", std::uint64_t{1} << 20)); },
              ThrowsMessage<io_error>(HasSubstr("inflates to more than 1 MiB")));
}

}  // namespace
}  // namespace pgm::gzip_tests
