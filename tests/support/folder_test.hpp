#pragma once
// A fixture that gives each test its own empty folder under the system's temporary folder,
// removed afterwards, with helpers to write and read files in it.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace pgm::testing {

class folder_test : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ =
        std::filesystem::temp_directory_path() / ("pgm_" + std::string(info->test_suite_name()) + "_" + info->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  /// A file of this test's folder with `content`.
  std::filesystem::path file(const std::string& name, const std::string& content) const {
    const auto at = dir_ / name;
    std::ofstream(at) << content;
    return at;
  }
  std::filesystem::path path(const std::string& name) const { return dir_ / name; }

  static std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p);
    return {std::istreambuf_iterator<char>(in), {}};
  }

  std::filesystem::path dir_;
};

}  // namespace pgm::testing
