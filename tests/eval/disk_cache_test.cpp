// The data cache on disk: data made once and read back the same in a later run; a file made
// for another key or from other inputs, a truncated or a corrupt one is an error naming it.

#include "pgm/eval/disk_cache.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "eval/tiny_scenario.hpp"
#include "support/folder_test.hpp"

namespace pgm::disk_cache_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

class disk_cache_test : public pgm::testing::folder_test {
 protected:
  // The tiny scenario's tasks, counting how often data are made, with an origin that the
  // test can change.
  task_source counted() {
    auto inner = pgm::test::deterministic_tasks();
    inner.data = [calls = calls_, make = inner.data](const std::string& task, std::size_t rows, std::uint64_t seed) {
      ++*calls;
      return make(task, rows, seed);
    };
    inner.origin = [origin = origin_](const std::string& task) { return task + " from " + *origin; };
    return inner;
  }
  task_source cache() {
    return disk_cached(counted(), {path("cache"), "hand", [this](const std::string& line) { notes_.push_back(line); }});
  }
  std::filesystem::path file_of(const std::string& task, std::size_t rows, std::uint64_t seed) const {
    return disk_cache_file(path("cache"), task, "hand", rows, seed);
  }

  std::shared_ptr<int> calls_ = std::make_shared<int>(0);
  std::shared_ptr<std::string> origin_ = std::make_shared<std::string>("v1");
  std::vector<std::string> notes_;
};

TEST_F(disk_cache_test, data_are_made_once_and_read_back_the_same_by_a_later_run) {
  const auto made = cache().data("two", 30, 7);
  EXPECT_EQ(*calls_, 1);
  const auto file = file_of("two", 30, 7);
  EXPECT_EQ(file.filename(), "two.hand.seed-7.rows-30.pgmdata");
  ASSERT_TRUE(std::filesystem::exists(file));
  const auto again = cache().data("two", 30, 7);  // a new source, as a later run has
  EXPECT_EQ(*calls_, 1) << "read, not made again";
  EXPECT_EQ(again, made);
  EXPECT_THAT(notes_, ::testing::ElementsAre("wrote 30 rows of two to " + file.string(),
                                             "read 30 rows of two from " + file.string()));
  // Another seed, size or task is another file.
  (void)cache().data("two", 30, 8);
  (void)cache().data("two", 31, 7);
  (void)cache().data("one", 30, 7);
  EXPECT_EQ(*calls_, 4);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(path("cache")), {}), 4);
  // Facts and origin pass through.
  EXPECT_EQ(cache().facts("two", "ok2").parents, (std::vector<std::string>{"x1", "x2"}));
  EXPECT_EQ(cache().origin("two"), "two from v1");
}

TEST_F(disk_cache_test, a_file_of_another_key_is_an_error) {
  (void)cache().data("two", 30, 7);
  std::filesystem::rename(file_of("two", 30, 7), file_of("two", 30, 9));
  EXPECT_THAT([&] { (void)cache().data("two", 30, 9); },
              ThrowsMessage<data_error>(HasSubstr(file_of("two", 30, 9).string() +
                                                  ": made for another seed (the file has '7', this run needs '9')")));
  std::filesystem::rename(file_of("two", 30, 9), file_of("one", 30, 7));
  EXPECT_THAT([&] { (void)cache().data("one", 30, 7); },
              ThrowsMessage<data_error>(HasSubstr("made for another task (the file has 'two', this run needs 'one')")));
  EXPECT_EQ(*calls_, 1);
}

TEST_F(disk_cache_test, data_made_from_other_inputs_are_an_error) {
  (void)cache().data("two", 30, 7);
  *origin_ = "v2";  // e.g. the task file was edited since
  EXPECT_THAT([&] { (void)cache().data("two", 30, 7); },
              ThrowsMessage<data_error>(HasSubstr("made for another origin (the file has 'two from v1', this run "
                                                  "needs 'two from v2'); delete it to make the data again")));
}

TEST_F(disk_cache_test, a_truncated_or_corrupt_file_is_an_error_never_data) {
  (void)cache().data("two", 30, 7);
  const auto file = file_of("two", 30, 7);
  const auto bytes = slurp(file);
  std::ofstream(file, std::ios::binary) << bytes.substr(0, bytes.size() - 10);
  EXPECT_THAT([&] { (void)cache().data("two", 30, 7); },
              ThrowsMessage<data_error>(HasSubstr(file.string() + ": truncated")));
  auto flipped = bytes;
  flipped[flipped.size() - 40] ^= 0x01;
  std::ofstream(file, std::ios::binary) << flipped;
  EXPECT_THAT([&] { (void)cache().data("two", 30, 7); },
              ThrowsMessage<data_error>(HasSubstr(file.string() + ": corrupt")));
  EXPECT_EQ(*calls_, 1);
}

TEST_F(disk_cache_test, the_folder_is_made_and_must_be_a_folder) {
  EXPECT_FALSE(std::filesystem::exists(path("cache")));
  (void)cache();
  EXPECT_FALSE(std::filesystem::exists(path("cache"))) << "nothing is made before data are";
  const auto a_file = file("cache", "x");
  EXPECT_THAT([&] { (void)cache(); }, ThrowsMessage<io_error>(HasSubstr("is a file, not a folder")));
}

}  // namespace
}  // namespace pgm::disk_cache_tests
