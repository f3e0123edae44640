// read_family against a per-row computation by hand: every kind of parent (discrete with
// 16-bit codes, binned continuous, a small grid kept as states, a constant left out).

#include "pgm/eval/family_data.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <random>

#include "pgm/eval/experiment.hpp"

namespace pgm::family_data_tests {
namespace {

using ::testing::HasSubstr;

struct mixed_data {
  dataset data;
  std::vector<unsigned> wide, grid_code, child;
  std::vector<double> offset;
};

mixed_data make_mixed_data(std::size_t rows) {
  std::mt19937_64 engine(11);
  mixed_data m;
  std::vector<double> grid(rows), constant(rows, 2.5);
  m.offset.resize(rows);
  for (std::size_t r = 0; r < rows; ++r) {
    m.wide.push_back(static_cast<unsigned>(engine() % 300));
    m.offset[r] = std::normal_distribution<double>(0.0, 1.6)(engine);
    m.grid_code.push_back(static_cast<unsigned>(engine() % 3));
    grid[r] = std::array{0.0, 0.9, 2.2}[m.grid_code.back()];
    m.child.push_back(static_cast<unsigned>(engine() % 3));
  }
  std::vector<std::string> labels;
  for (int s = 0; s < 300; ++s) labels.push_back("s" + std::to_string(s));
  m.data.add(discrete_column(variable("wide", labels), m.wide));
  m.data.add(continuous_column("offset", m.offset));
  m.data.add(continuous_column("still", constant));
  m.data.add(continuous_column("grid", grid));
  m.data.add(discrete_column(variable("ok", {"0", "1", "2"}), m.child));
  return m;
}

TEST(family_data_test, cells_are_the_mixed_radix_index_of_each_row) {
  const std::size_t rows = 5003;  // more than one block of the counting kernel
  const auto m = make_mixed_data(rows);
  const std::map<std::string, semantic_tags, std::less<>> tags{{"offset", {.quantity = "x-offset"}}};
  const auto family = read_family(m.data, "ok", {"wide", "offset", "still", "grid"}, 5, tags);

  ASSERT_EQ(family.parents.size(), 3U);
  EXPECT_EQ(family.parents[0].name(), "wide");
  EXPECT_EQ(family.parents[1].cardinality(), 5U);  // quantile bins
  EXPECT_EQ(family.parents[1].tags().quantity, "x-offset");
  EXPECT_EQ(family.parents[2].states(), (std::vector<std::string>{"0", "0.9", "2.2"}));
  ASSERT_EQ(family.notes.size(), 1U);
  EXPECT_THAT(family.notes[0], HasSubstr("'still' never varies"));

  ASSERT_EQ(family.rows(), rows);
  for (std::size_t r = 0; r < rows; ++r) {
    const std::size_t u = (m.wide[r] * 5 + family.parents[1].bin(m.offset[r]).value()) * 3 + m.grid_code[r];
    ASSERT_EQ(family.cell[r], u * 3 + m.child[r]) << "row " << r;
  }
}

TEST(family_data_test, fit_all_counts_marginals_and_the_family) {
  const auto m = make_mixed_data(2000);
  const auto family = read_family(m.data, "ok", {"grid", "wide"}, 5);
  const auto network = family.fit_all();
  const auto& grid = network.table("grid");
  for (unsigned s = 0; s < 3; ++s) {
    const auto n = std::count(m.grid_code.begin(), m.grid_code.end(), s);
    EXPECT_DOUBLE_EQ(grid(state_index(s), config_index(0)), static_cast<double>(n) / 2000.0);
  }
  auto counts = family.empty_counts();
  std::vector<std::uint32_t> all(2000);
  std::iota(all.begin(), all.end(), 0U);
  family.add_counts(all, counts);
  EXPECT_EQ(network.table("ok"), estimate_mle(counts));
  std::vector<const discrete_column*> parents{&m.data.discrete("wide")};
  // The grid's codes are 0.0 < 0.9 < 2.2 in order, so the family counts match count_family's
  // over the same codes.
  const discrete_column grid_column(family.parents[0], m.grid_code);
  parents.insert(parents.begin(), &grid_column);
  const auto direct = count_family(m.data.discrete("ok"), parents, {.threads = 1});
  EXPECT_TRUE(std::equal(direct.counts().begin(), direct.counts().end(), counts.counts().begin()));
}

TEST(experiment_test, progress_counts_the_jobs_up_to_all) {
  const auto s = parse_scenario(R"({
    "format": "pgm-scenario", "version": 1, "name": "grid", "title": "Grid",
    "prior": {"task": "one", "rows": 300, "node": "ok"},
    "target": {"node": "ok", "tasks": [{"task": "two", "train_rows": 40, "ground_truth_rows": 260}]},
    "map": "ok=ok", "strategies": ["direct"], "weights": [0, 5], "subsets": 2, "repetitions": 5
  })",
                                "grid.json");
  const task_source source{[](const std::string&, std::size_t rows, std::uint64_t) {
                             const auto m = make_mixed_data(rows);
                             return m.data;
                           },
                           [](const std::string&, const std::string&) {
                             task_facts f;
                             f.parents = {"grid"};
                             f.controllable = {"grid"};
                             f.success_state = "1";
                             return f;
                           }};
  for (unsigned threads : {1U, 2U, 3U}) {
    std::vector<std::pair<std::size_t, std::size_t>> reports;
    experiment_options options{.threads = threads, .automatic_lines = false};
    options.progress = [&](std::size_t done, std::size_t total) { reports.emplace_back(done, total); };
    static_cast<void>(run_experiment(s, source, options));
    ASSERT_EQ(reports.size(), 5U) << threads << " threads";
    for (std::size_t k = 0; k < reports.size(); ++k) EXPECT_EQ(reports[k], std::make_pair(k + 1, std::size_t{5}));
  }
}

}  // namespace
}  // namespace pgm::family_data_tests
