#pragma once
// A fixture for tests that run the `pgm` program as a user does: each test gets its own empty
// folder, runs commands with their output captured, and checks failures by exit code, message
// and the absence of any half-written output. PGM_PROGRAM is the program's path.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace pgm::testing {

struct program_result {
  int code;
  std::string out;
  std::string err;
};

class program_test : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() / ("pgm_" + std::string(info->test_suite_name()) + "_" + info->name());
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

  /// Runs `pgm <arguments>` through the shell (quote what the shell would split).
  program_result run(const std::string& arguments) const {
    const auto out = dir_ / "stdout.txt";
    const auto err = dir_ / "stderr.txt";
    const auto command = std::string(PGM_PROGRAM) + " " + arguments + " >" + out.string() + " 2>" + err.string();
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
  }

  /// Expects a non-zero exit with `message` on stderr and, if given, no file at `output`.
  void expect_failure(const std::string& arguments, const std::string& message,
                      const std::filesystem::path& output = {}) const {
    const auto r = run(arguments);
    EXPECT_NE(r.code, 0) << arguments;
    EXPECT_THAT(r.err, ::testing::HasSubstr(message)) << arguments;
    if (!output.empty()) {
      EXPECT_FALSE(std::filesystem::exists(output)) << output;
    }
  }

  std::filesystem::path dir_;
};

}  // namespace pgm::testing
