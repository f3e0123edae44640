#pragma once
/// \file
/// The conformance kit of network file formats: a GoogleTest suite that holds a registered
/// format's codec to reading back what it writes, bit for bit, on random networks and on the
/// published networks a case lists, and to refusing a truncated file with pgm's error rather
/// than a crash or a network. Instantiate it in one test source of a program that links
/// GoogleTest and pgm::pgm:
///
///     #include <pgm/testing/format_conformance.hpp>
///     using pgm::testing::format_conformance;  // the macro takes the suite's name unqualified
///     INSTANTIATE_TEST_SUITE_P(mine, format_conformance,
///                              ::testing::Values(pgm::testing::format_case{.format = "fg"}),
///                              pgm::testing::format_case_name);

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/io/network_format.hpp"
#include "pgm/testing/case_names.hpp"
#include "pgm/testing/random_network.hpp"

namespace pgm::testing {

/// One format as the kit checks it.
struct format_case {
  /// The registered name: "bif".
  std::string format;
  /// Networks to write and read back besides the random ones (read from their own files).
  std::vector<std::filesystem::path> networks;
  /// False for a format that numbers variables and states rather than naming them (UAI): then
  /// the structure, the cardinalities and the values must come back.
  bool keeps_names = true;
};

inline void PrintTo(const format_case& c, std::ostream* out) { *out << c.format; }

/// Every registered format, each checked as the case of `cases` with its name, or with the
/// defaults where none has it.
[[nodiscard]] inline std::vector<format_case> registered_format_cases(const std::vector<format_case>& cases) {
  return cases_of(known_network_formats(), cases, [](const format_case& c) { return c.format; });
}

[[nodiscard]] inline std::string format_case_name(const ::testing::TestParamInfo<format_case>& info) {
  return test_name(info.param.format);
}

class format_conformance : public ::testing::TestWithParam<format_case> {
 protected:
  /// The registry's codec, which lives as long as the program.
  [[nodiscard]] const network_format_codec& codec() const { return network_format(GetParam().format).codec(); }

  [[nodiscard]] bayesian_network read_back(const std::string& text) const {
    return codec().read(text, "written." + GetParam().format, {}).network();
  }

  /// `again` is `net` as the case's format keeps it.
  void expect_same(const bayesian_network& again, const bayesian_network& net) const {
    if (GetParam().keeps_names) {
      EXPECT_EQ(again, net);
      return;
    }
    ASSERT_EQ(again.size(), net.size());
    for (std::size_t i = 0; i < net.size(); ++i) {
      const variable_id v = index_at<variable_id>(i);
      EXPECT_EQ(again.variables()[i].cardinality(), net.variables()[i].cardinality()) << i;
      EXPECT_EQ(again.graph().parents(v), net.graph().parents(v)) << i;
      EXPECT_TRUE(std::ranges::equal(again.tables()[i].values(), net.tables()[i].values())) << i;
    }
  }
};

TEST_P(format_conformance, random_networks_read_back_as_written) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto net = random_network(seed, {.nodes = 3 + seed % 8, .max_parents = 3, .max_states = 4});
    expect_same(read_back(codec().write(net, {})), net);
  }
}

TEST_P(format_conformance, published_networks_read_back_as_written) {
  for (const auto& path : GetParam().networks) {
    SCOPED_TRACE(path.string());
    const auto net = read_network(path);
    expect_same(read_back(codec().write(net, {})), net);
  }
}

TEST_P(format_conformance, a_truncated_file_is_refused_by_a_pgm_error) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const auto text = codec().write(random_network(seed, {.nodes = 4, .max_parents = 2, .max_states = 3}), {});
    for (const auto share : {0.25, 0.5, 0.9}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", the first " + std::to_string(share) + " of the text");
      const auto cut = text.substr(0, static_cast<std::size_t>(share * static_cast<double>(text.size())));
      EXPECT_THROW(static_cast<void>(read_back(cut)), error);
    }
  }
}

}  // namespace pgm::testing
