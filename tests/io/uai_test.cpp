// The UAI formats (pgm/io/uai.hpp): models both ways, evidence in both forms, queries, results,
// and every error naming where and what.

#include "pgm/io/uai.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "pgm/io/bif.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/testing/random_markov_network.hpp"

namespace pgm {
namespace uai_test {

using ::testing::HasSubstr;

constexpr const char* small_markov = R"(MARKOV
3
2 2 3
3
1 0
2 0 1
2 1 2

2
 0.5 1.5

4
 1 2 3 4

6
 0 1 2 3 4 5
)";

std::string error_of(std::string_view text) {
  try {
    static_cast<void>(parse_uai(text, "m.uai"));
  } catch (const error& e) {
    return e.what();
  }
  return "no error";
}

TEST(uai_test, reads_a_markov_network) {
  const auto file = parse_uai(small_markov, "m.uai");
  EXPECT_EQ(file.kind, uai_kind::markov);
  ASSERT_EQ(file.model.size(), 3U);
  EXPECT_EQ(file.model.variables()[2].name(), "v2");
  EXPECT_EQ(file.model.variables()[2].states(), (std::vector<std::string>{"0", "1", "2"}));
  ASSERT_EQ(file.model.factor_count(), 3U);
  EXPECT_EQ(file.model.factor(2).scope(), (std::vector<variable_id>{variable_id(1), variable_id(2)}));
  EXPECT_EQ(file.model.factor(2).values(), (std::vector<double>{0, 1, 2, 3, 4, 5}));
}

TEST(uai_test, a_markov_network_round_trips_to_the_bit) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const auto model = testing::random_markov_network(seed);
    const auto back = parse_uai(to_uai(model), "m.uai");
    EXPECT_EQ(back.model.factors(), model.factors());
  }
}

TEST(uai_test, a_bayesian_network_round_trips_through_bayes) {
  const auto network = read_bif(std::string(PGM_NETWORKS_DIR) + "/child.bif");
  const auto text = to_uai(network);
  EXPECT_TRUE(text.starts_with("BAYES\n"));
  const auto file = parse_uai(text, "child.uai");
  EXPECT_EQ(file.kind, uai_kind::bayes);
  const auto back = to_bayesian_network(file, "child.uai");
  ASSERT_EQ(back.size(), network.size());
  for (std::size_t i = 0; i < network.size(); ++i) {
    const variable_id node = index_at<variable_id>(i);
    EXPECT_EQ(back.factor(i).values(), network.factor(i).values());
    EXPECT_EQ(back.factor_scope(i), network.factor_scope(i));
    EXPECT_EQ(back.variables()[i].name(), "v" + std::to_string(i));
    static_cast<void>(node);
  }
}

TEST(uai_test, the_format_registry_reads_and_writes_bayes) {
  const auto folder = std::filesystem::temp_directory_path() / "pgm-uai-test";
  std::filesystem::create_directories(folder);
  const auto network = read_bif(std::string(PGM_NETWORKS_DIR) + "/asia.bif");
  write_network(network, folder / "asia.uai");
  const auto back = read_network(folder / "asia.uai");
  EXPECT_EQ(back.free_parameters(), network.free_parameters());
  std::ofstream(folder / "m.uai") << small_markov;
  try {
    static_cast<void>(read_network(folder / "m.uai"));
    FAIL();
  } catch (const model_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("holds a Markov network (MARKOV)"));
  }
  std::filesystem::remove_all(folder);
}

TEST(uai_test, errors_name_the_line_the_column_and_what_was_expected) {
  EXPECT_THAT(error_of("MARKOW\n1\n2\n0\n"), HasSubstr("m.uai:1:1: expected MARKOV or BAYES, found 'MARKOW'"));
  EXPECT_THAT(error_of("MARKOV\n2\n2 0\n"), HasSubstr("m.uai:3:3: a cardinality 0 is out of range"));
  EXPECT_THAT(error_of("MARKOV\n2\n2 x\n"), HasSubstr("m.uai:3:3: expected a cardinality (a whole number), found 'x'"));
  EXPECT_THAT(error_of("MARKOV\n2\n2 2\n1\n1 2\n"),
              HasSubstr("m.uai:5:3: a variable of factor 0's scope 2 is out of range: expected 0 to 1"));
  EXPECT_THAT(error_of("MARKOV\n2\n2 2\n1\n2 0 0\n"), HasSubstr("factor 0 names variable 0 twice"));
  EXPECT_THAT(error_of("MARKOV\n2\n2 2\n1\n2 0 1\n3\n1 2 3\n"),
              HasSubstr("m.uai:6:1: factor 0 has 4 entries (the product of its scope's cardinalities), but its table "
                        "says 3"));
  EXPECT_THAT(error_of("MARKOV\n1\n2\n1\n1 0\n2\n1 nan\n"),
              HasSubstr("m.uai:7:3: expected an entry of factor 0 (a finite number), found 'nan'"));
  EXPECT_THAT(error_of("MARKOV\n1\n2\n1\n1 0\n2\n1 -0.5\n"), HasSubstr("m.uai:7:3: an entry of factor 0 is negative"));
  EXPECT_THAT(error_of("MARKOV\n1\n2\n1\n1 0\n2\n1\n"),
              HasSubstr("m.uai:8:1: expected an entry of factor 0, found the end of the file"));
  EXPECT_THAT(error_of("MARKOV\n1\n2\n1\n1 0\n2\n1 1 1\n"), HasSubstr("m.uai:7:5: expected the end of the file"));
  EXPECT_THAT(error_of("BAYES\n2\n2 2\n1\n"), HasSubstr("a BAYES file has one table per variable"));
  EXPECT_THAT(error_of(""), HasSubstr("m.uai:1:1: expected MARKOV or BAYES, found the end of the file"));
  // A short file declaring millions of states is refused before they are made (docs/limits.md).
  EXPECT_THAT(error_of("MARKOV\n3\n2 9996832 26\n0\n"),
              HasSubstr("m.uai:3:3: the variables have more than 65536 states in all, more than pgm reads from a UAI "
                        "file of 24 bytes"));
}

TEST(uai_test, a_bayes_file_must_hold_distributions) {
  const auto file = parse_uai("BAYES\n1\n2\n1\n1 0\n2\n0.2 0.3\n", "b.uai");
  try {
    static_cast<void>(to_bayesian_network(file, "b.uai"));
    FAIL();
  } catch (const model_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("a distribution of 'v0' sums to 0.5"));
  }
  // Rounded as published files are: within the tolerance, normalized.
  const auto rounded = to_bayesian_network(parse_uai("BAYES\n1\n2\n1\n1 0\n2\n0.3333 0.6666\n", "b.uai"), "b.uai");
  EXPECT_NEAR(rounded.table(variable_id(0)).values()[0], 1.0 / 3.0, 1e-4);
}

TEST(uai_test, evidence_in_both_forms) {
  const auto model = parse_uai(small_markov, "m.uai").model;
  using pairs = std::vector<std::pair<variable_id, std::size_t>>;
  const pairs both{{variable_id(0), 1}, {variable_id(2), 2}};
  EXPECT_EQ(parse_uai_evidence("2 0 1 2 2\n", "e", model), std::vector<pairs>{both});
  EXPECT_EQ(parse_uai_evidence("0\n", "e", model), std::vector<pairs>{pairs{}});
  EXPECT_EQ(parse_uai_evidence("", "e", model), std::vector<pairs>{pairs{}});
  const auto samples = parse_uai_evidence("2\n1 0 1\n2 1 0 2 1\n", "e", model);
  ASSERT_EQ(samples.size(), 2U);
  EXPECT_EQ(samples[1], (pairs{{variable_id(1), 0}, {variable_id(2), 1}}));
  auto evidence_error = [&](std::string_view text) {
    try {
      static_cast<void>(parse_uai_evidence(text, "e.evid", model));
    } catch (const error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(evidence_error("1 0 2\n"),
              HasSubstr("e.evid:1:5: the state of variable 0 2 is out of range: expected 0 to 1"));
  EXPECT_THAT(evidence_error("1 3 0\n"), HasSubstr("e.evid:1:3: an observed variable 3 is out of range"));
  EXPECT_THAT(evidence_error("2 0 1 0 0\n"), HasSubstr("variable 0 is observed twice"));
}

TEST(uai_test, queries_and_results) {
  const auto model = parse_uai(small_markov, "m.uai").model;
  EXPECT_EQ(parse_uai_query("2 2 0\n", "q", model), (std::vector<variable_id>{variable_id(2), variable_id(0)}));
  EXPECT_THROW(static_cast<void>(parse_uai_query("1 5\n", "q", model)), parse_error);
  EXPECT_EQ(uai_pr_text(-1.5), "PR\n-1.5\n");
  EXPECT_EQ(uai_mar_text({{0.25, 0.75}, {1.0 / 3, 2.0 / 3}}),
            "MAR\n2 2 0.25 0.75 2 0.33333333333333331 0.66666666666666663\n");
  const std::size_t states[] = {1, 0, 2};
  EXPECT_EQ(uai_assignment_text("MAP", states), "MAP\n3 1 0 2\n");
  const auto read = parse_uai_result("MAR\n1 2 0.25 0.75\n", "r");
  EXPECT_EQ(read.task, "MAR");
  EXPECT_EQ(read.numbers, (std::vector<double>{1, 2, 0.25, 0.75}));
  EXPECT_THROW(static_cast<void>(parse_uai_result("MARX\n", "r")), parse_error);
}

}  // namespace uai_test
}  // namespace pgm
