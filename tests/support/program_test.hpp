#pragma once
// A fixture for tests that run the `pgm` program as a user does: each test gets its own empty
// folder (folder_test), runs commands with their output captured, and checks failures by exit code, message
// and the absence of any half-written output. PGM_PROGRAM is the program's path.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/folder_test.hpp"

namespace pgm::testing {

struct program_result {
  int code;
  std::string out;
  std::string err;
  /// The largest resident memory the program (or its shell) held, in KiB.
  long peak_kib = 0;
};

class program_test : public folder_test {
 protected:
  void SetUp() override {
    folder_test::SetUp();
    ASSERT_TRUE(std::filesystem::is_regular_file(PGM_PROGRAM))
        << PGM_PROGRAM << " is not there: these tests run the pgm program, which a whole build makes "
        << "(cmake --build --preset release)";
  }

  /// Runs `pgm <arguments>` through the shell (quote what the shell would split).
  program_result run(const std::string& arguments) const { return run_to(arguments, dir_ / "stdout.txt"); }

  /// Runs `pgm <arguments>` with its standard output sent to `output` (e.g. /dev/full).
  program_result run_to(const std::string& arguments, const std::filesystem::path& output) const {
    const auto err = dir_ / "stderr.txt";
    const auto command = std::string(PGM_PROGRAM) + " " + arguments + " >" + output.string() + " 2>" + err.string();
    // As std::system does, but waited for with wait4, which tells the memory the run took.
    const pid_t child = ::fork();
    if (child == 0) {
      ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    int status = -1;
    rusage usage{};
    if (child < 0 || ::wait4(child, &status, 0, &usage) != child) status = -1;
    const bool file = std::filesystem::is_regular_file(output);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, file ? slurp(output) : std::string(), slurp(err),
            usage.ru_maxrss};
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
};

}  // namespace pgm::testing
