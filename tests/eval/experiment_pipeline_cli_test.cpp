// The experiment's numbers are those a user gets from the commands: on the data of one
// scenario (2-Stack-Simulation, fewer rows), the prior network, the target's table on all its
// rows and each strategy's transferred prior equal, to the bit, what
// `pgm discretize | pgm fit | pgm transfer` write.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <numeric>
#include <string>

#include "pgm/eval/experiment.hpp"
#include "pgm/eval/simulated_source.hpp"
#include "pgm/io/cpt_csv.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/sim/task_lookup.hpp"
#include "support/program_test.hpp"

namespace pgm::experiment_pipeline_cli_tests {
namespace {

class experiment_pipeline_test : public pgm::testing::program_test {
 protected:
  const std::filesystem::path tasks = std::filesystem::path(PGM_SOURCE_DIR) / "tasks";

  /// `pgm simulate`'s data of `task`, read back as the experiment's source reads data.
  [[nodiscard]] std::string simulate(const std::string& task, std::size_t rows, std::uint64_t seed) const {
    const auto file = path(task + ".csv").string();
    const auto r = run("simulate --task " + task + " --rows " + std::to_string(rows) + " --seed " +
                       std::to_string(seed) + " --threads 1 --tasks-dir " + tasks.string() + " --out " + file);
    EXPECT_EQ(r.code, 0) << r.err;
    return file;
  }

  [[nodiscard]] static std::string edges_into(const std::string& node, const std::vector<variable>& parents) {
    std::string text;
    for (const auto& p : parents) text += (text.empty() ? "" : ",") + p.name() + "->" + node;
    return "\"" + text + "\"";
  }

  void discretize_and_fit(const std::string& data, const std::string& node, const std::vector<variable>& parents,
                          std::size_t bins, const std::string& stem) const {
    auto r = run("discretize --in " + data + " --bins " + std::to_string(bins) + " --out " +
                 path(stem + "-binned.csv").string() + " --edges-out " + path(stem + "-edges.json").string());
    ASSERT_EQ(r.code, 0) << r.err;
    r = run("fit --data " + path(stem + "-binned.csv").string() + " --edges " + edges_into(node, parents) +
            " --intervals " + path(stem + "-edges.json").string() + " --out " + path(stem + ".json").string());
    ASSERT_EQ(r.code, 0) << r.err;
  }
};

TEST_F(experiment_pipeline_test, prior_truth_and_transferred_priors_equal_the_commands) {
  auto s = load_scenario(tasks / "scenarios" / "2-stack-sim.json");
  s.prior_rows = 3000;
  s.targets.at(0).train_rows = 1000;
  s.targets.at(0).ground_truth_rows = 3000;
  const std::map<std::string, std::string> files{{s.prior_task, simulate(s.prior_task, s.prior_rows, 3)},
                                                 {s.targets[0].task, simulate(s.targets[0].task, 4000, 4)}};
  task_source source;
  source.data = [&](const std::string& task, std::size_t, std::uint64_t) {
    csv_options options;
    options.kinds = {{"onTop1", column_kind::discrete}, {"onTop2", column_kind::discrete}};
    return read_csv(files.at(task), options);
  };
  source.facts = [&](const std::string& task, const std::string& node) {
    return facts_of(sim::load_task(task, {tasks}), node);
  };
  const auto ignore = [](const std::string&) {};
  const auto prior = prepare_prior(s, source, 1, ignore);
  const auto target = prepare_target(s, 0, source, prior, 1, false, ignore);

  // The prior: pgm discretize, then pgm fit over the prior node's family.
  std::vector<variable> prior_parents;
  for (auto p : prior.network.graph().parents(prior.network.id(s.prior_node)))
    prior_parents.push_back(prior.network.variables()[p.value()]);
  discretize_and_fit(files.at(s.prior_task), s.prior_node, prior_parents, s.bins, "prior");
  const auto fitted_prior = read_network(path("prior.json"));
  ASSERT_EQ(fitted_prior.size(), prior.network.size());
  for (const auto& v : prior.network.variables()) {
    const auto mine = prior.network.table(v.name()).values();
    const auto theirs = fitted_prior.table(v.name()).values();
    EXPECT_TRUE(std::equal(mine.begin(), mine.end(), theirs.begin(), theirs.end())) << v.name();
  }

  // The target: its table on all rows is what pgm fit writes.
  const auto& family = target.family;
  discretize_and_fit(files.at(target.task), s.target_node, family.parents, s.bins, "target");
  const auto fitted_target = read_network(path("target.json"));
  auto all = family.empty_counts();
  std::vector<std::uint32_t> rows(family.rows());
  std::iota(rows.begin(), rows.end(), 0U);
  family.add_counts(rows, all);
  const auto mle = estimate_mle(all);
  const auto theirs = fitted_target.table(fitted_target.id(s.target_node)).values();
  ASSERT_EQ(mle.values().size(), 625U * 2);
  EXPECT_TRUE(std::equal(mle.values().begin(), mle.values().end(), theirs.begin(), theirs.end()));

  // Each strategy's transferred prior is what pgm transfer writes.
  for (const auto& strategy : s.strategies) {
    const auto out = path(strategy + "-prior.csv");
    const auto r =
        run("transfer --prior-model " + path("prior.json").string() + " --model " + path("target.json").string() +
            " --strategy " + strategy + " --map \"" + s.map + "\" --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.err;
    const auto table = parse_cpt_csv(slurp(out), out.string(), family.child, family.parents);
    const auto& mine = target.priors.at(strategy).table().values();
    EXPECT_TRUE(std::equal(mine.begin(), mine.end(), table.values().begin(), table.values().end())) << strategy;
  }
}

}  // namespace
}  // namespace pgm::experiment_pipeline_cli_tests
