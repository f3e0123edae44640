// Tasks by name and variant, as `pgm simulate --task --variant` and pgm.simulate name them.

#include "pgm/sim/task_variant.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace pgm::sim::task_variant_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(task_variant_test, reality_is_the_tasks_reality_file) {
  EXPECT_EQ(task_variant_name("2-stack", "sim"), "2-stack");
  EXPECT_EQ(task_variant_name("2-stack", "reality"), "2-stack-reality");
  EXPECT_EQ(task_variant_name("2-stack-reality", "reality"), "2-stack-reality");
  EXPECT_THAT([] { (void)task_variant_name("2-stack-reality", "sim"); },
              ThrowsMessage<error>(HasSubstr("is a reality variant")));
  EXPECT_THAT([] { (void)task_variant_name("2-stack", "real"); }, ThrowsMessage<error>(HasSubstr("unknown variant")));
}

TEST(task_variant_test, loads_the_variant_or_says_there_is_none) {
  const std::vector<std::filesystem::path> dirs{std::filesystem::path(PGM_SOURCE_DIR) / "tasks"};
  EXPECT_EQ(load_task_variant("1-stack", "reality", dirs).name, "1-stack-reality");
  EXPECT_THAT([&] { (void)load_task_variant("drop-glass", "reality", dirs); },
              ThrowsMessage<data_error>(HasSubstr("task 'drop-glass' has no reality variant")));
  EXPECT_THAT([&] { (void)load_task_variant("9-stack", "reality", dirs); },
              ThrowsMessage<unknown_name>(HasSubstr("unknown task '9-stack'")));
}

}  // namespace
}  // namespace pgm::sim::task_variant_tests
