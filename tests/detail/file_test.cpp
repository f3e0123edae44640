#include "pgm/core/file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>
#include <thread>

namespace file_tests {
namespace {

namespace fs = std::filesystem;

class file_test : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("pgm_file_test_" + std::to_string(::getpid()));
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path folder_;
};

void write_text(const fs::path& path, const std::string& text) {
  pgm::write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

TEST_F(file_test, replaces_a_file_and_leaves_nothing_beside_it) {
  write_text(folder_ / "a.txt", "old");
  write_text(folder_ / "a.txt", "new");
  EXPECT_EQ(pgm::read_file(folder_ / "a.txt"), "new");
  EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()), 1);
}

TEST_F(file_test, a_failed_write_keeps_the_old_content) {
  write_text(folder_ / "a.txt", "old");
  EXPECT_THROW(pgm::write_file_atomically(folder_ / "a.txt", [](std::ostream&) { throw pgm::io_error("stopped"); }),
               pgm::io_error);
  EXPECT_EQ(pgm::read_file(folder_ / "a.txt"), "old");
  EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()), 1);
}

TEST_F(file_test, a_symbolic_link_stays_a_link_to_the_new_content) {
  write_text(folder_ / "target.txt", "old");
  fs::create_symlink(folder_ / "target.txt", folder_ / "link.txt");
  write_text(folder_ / "link.txt", "new");
  EXPECT_TRUE(fs::is_symlink(folder_ / "link.txt"));
  EXPECT_EQ(pgm::read_file(folder_ / "target.txt"), "new");
}

TEST_F(file_test, a_named_pipe_is_written_through_not_replaced) {
  const auto pipe = folder_ / "pipe";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = pgm::read_file(pipe); });
  write_text(pipe, "through");
  reader.join();
  EXPECT_EQ(received, "through");
  EXPECT_TRUE(fs::is_fifo(pipe));
}

TEST_F(file_test, a_missing_folder_is_named) {
  EXPECT_THAT([&] { write_text(folder_ / "none" / "a.txt", "x"); },
              ::testing::ThrowsMessage<pgm::io_error>(::testing::HasSubstr("does not exist")));
}

// A file read whole is bounded (pgm::max_file_bytes): a regular file by its size before it is
// read, a device that never ends (/dev/zero) once it has given more (issue 28).
TEST_F(file_test, reading_a_file_whole_stops_at_the_limit) {
  write_text(folder_ / "m.bif", std::string(2000, 'x'));
  EXPECT_EQ(pgm::read_file(folder_ / "m.bif", 2000).size(), 2000U);
  EXPECT_THAT([&] { static_cast<void>(pgm::read_file(folder_ / "m.bif", 1999)); },
              ::testing::ThrowsMessage<pgm::io_error>(
                  ::testing::HasSubstr("m.bif': it is larger than 1999 bytes, pgm's limit of a file it reads whole")));
  EXPECT_THAT([&] { static_cast<void>(pgm::read_file("/dev/zero", std::uint64_t{1} << 20)); },
              ::testing::ThrowsMessage<pgm::io_error>(::testing::HasSubstr(
                  "cannot read '/dev/zero': it is larger than 1 MiB, pgm's limit of a file it reads whole "
                  "(models, tasks, scenarios; docs/limits.md)")));
  EXPECT_EQ(pgm::max_file_bytes, std::uint64_t{256} << 20);
}

}  // namespace
}  // namespace file_tests
