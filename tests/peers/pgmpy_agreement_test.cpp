// Agreement with pgmpy, run only where pgmpy imports (tests/CMakeLists.txt): posteriors on the
// published sachs network against pgmpy's VariableElimination, every engine's posteriors and
// most probable states on published networks against its query and map_query, the Yates-corrected
// chi-square and G² statistics against pgmpy's chi_square and g_sq on a sample of sachs, and
// the BIF and XMLBIF files each side writes read by the other with the same tables.
// PGM_PYTHON runs tests/peers/pgmpy_oracle.py with PYTHONPATH=PGM_PGMPY_PATH.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "pgm/causal/adjustment.hpp"
#include "pgm/inference/engine_registry.hpp"
#include "pgm/inference/sampling.hpp"
#include "pgm/inference/variable_elimination.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/io/xmlbif.hpp"
#include "pgm/learn/independence_test.hpp"
#include "support/folder_test.hpp"

namespace pgm::pgmpy_agreement_tests {
namespace {

const auto sachs_path = std::filesystem::path(PGM_NETWORKS_DIR) / "sachs.bif";

class pgmpy_agreement_test : public pgm::testing::folder_test {
 protected:
  /// pgmpy's answers to `requests` ("queries" on a network or "ci" on a CSV file).
  nlohmann::json ask_pgmpy(const std::string& mode, const std::filesystem::path& input,
                           const nlohmann::json& requests) const {
    const auto request_file = file("request.json", requests.dump());
    const auto answer_file = path("answer.json");
    const auto command = std::string("PYTHONPATH='") + PGM_PGMPY_PATH + "' " + PGM_PYTHON + " " + PGM_ORACLE + " " +
                         mode + " " + input.string() + " " + request_file.string() + " >" + answer_file.string() +
                         " 2>" + path("oracle.err").string();
    const int status = std::system(command.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << slurp(path("oracle.err"));
    return nlohmann::json::parse(slurp(answer_file));
  }
};

/// The network with every column divided by its sum, so that both libraries compute with the
/// same distributions (the files print a few digits; pgm reads each column as its distribution,
/// pgmpy uses it as printed but leaves barren nodes out, which assumes the same).
bayesian_network normalized(const bayesian_network& net) {
  std::vector<cpt<double>> tables;
  for (const auto& t : net.tables()) {
    std::vector<double> values(t.values().begin(), t.values().end());
    const auto j = t.child_cardinality();
    for (std::size_t u = 0; u * j < values.size(); ++u) {
      double sum = 0.0;
      for (std::size_t x = 0; x < j; ++x) sum += values[u * j + x];
      for (std::size_t x = 0; x < j; ++x) values[u * j + x] /= sum;
    }
    tables.emplace_back(t.child(), t.parents(), std::move(values));
  }
  return bayesian_network(net.structure(), std::move(tables));
}

/// How far the columns of `net` miss 1, added over its tables (each table's worst column): a
/// bound on how much reading each column as its distribution can move a posterior, to first order.
double column_rounding(const bayesian_network& net) {
  double total = 0.0;
  for (const auto& t : net.tables()) {
    double worst = 0.0;
    const auto j = t.child_cardinality();
    for (std::size_t u = 0; u < t.configurations(); ++u) {
      double sum = 0.0;
      for (std::size_t x = 0; x < j; ++x) sum += t.values()[u * j + x];
      worst = std::max(worst, std::abs(sum - 1.0));
    }
    total += worst;
  }
  return total;
}

TEST_F(pgmpy_agreement_test, posteriors_on_sachs_equal_pgmpy_variable_elimination) {
  // On sachs as published, pgmpy uses the printed values and pgm each column's distribution
  // (docs/inference.md): they differ within the columns' rounding. On sachs with exact columns,
  // they agree to the last bits.
  const auto published = read_bif(sachs_path);
  const auto exact = normalized(published);
  const auto exact_path = path("sachs-exact.xml");
  write_network(exact, exact_path);
  const double rounding = column_rounding(published);
  ASSERT_LT(rounding, 1e-6);
  const std::vector<std::pair<std::vector<std::string>, evidence>> cases{
      {{"Akt"}, {}},
      {{"Akt"}, {{"PKA", "HIGH"}}},
      {{"Raf"}, {{"Mek", "HIGH"}}},  // against the arrows
      {{"Erk", "Akt"}, {{"PKC", "LOW"}, {"Plcg", "AVG"}}},
      {{"P38", "Jnk", "PIP2"}, {{"PIP3", "HIGH"}, {"Erk", "LOW"}}},
  };
  nlohmann::json requests = nlohmann::json::array();
  for (const auto& [variables, observed] : cases) requests.push_back({{"query", variables}, {"evidence", observed}});
  for (const auto& [file, net, tolerance] :
       {std::tuple{sachs_path, &published, 2.0 * rounding}, std::tuple{exact_path, &exact, 1e-12}}) {
    const auto answers = ask_pgmpy("queries", file, requests);
    ASSERT_EQ(answers.size(), cases.size());
    double largest = 0.0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const auto ours = query(*net, cases[i].first, cases[i].second);
      std::size_t states = 1;
      for (const auto& v : ours.variables) states *= v.cardinality();
      ASSERT_EQ(answers[i].size(), states) << requests[i].dump();
      for (const auto& row : answers[i]) {
        std::vector<std::string> labels;
        for (const auto& v : ours.variables) labels.push_back(row["states"][v.name()].get<std::string>());
        const double difference = std::abs(ours.probability(labels) - row["p"].get<double>());
        largest = std::max(largest, difference);
        EXPECT_LT(difference, tolerance) << file << " " << requests[i].dump() << " at " << row["states"].dump();
      }
    }
    std::cout << file.filename() << ": largest difference from pgmpy " << largest << " (allowed " << tolerance << ")\n";
  }
}

TEST_F(pgmpy_agreement_test, every_engine_and_the_most_probable_states_equal_pgmpy_on_published_networks) {
  std::mt19937_64 random(99);
  for (const char* name : {"asia", "child", "insurance", "alarm"}) {
    const auto net = normalized(read_bif(std::filesystem::path(PGM_NETWORKS_DIR) / (std::string(name) + ".bif")));
    const auto file = path(std::string(name) + ".xml");  // pgmpy reads XMLBIF far faster than BIF
    write_network(net, file);
    std::vector<std::pair<std::vector<std::string>, evidence>> cases;
    variable_elimination check(net);
    while (cases.size() < 24) {
      std::vector<std::string> query{net.variables()[random() % net.size()].name()};
      if (cases.size() % 3 == 2) {
        const auto& other = net.variables()[random() % net.size()].name();
        if (other != query.front()) query.push_back(other);
      }
      evidence observed;
      while (observed.size() < cases.size() % 4) {
        const auto& v = net.variables()[random() % net.size()];
        if (std::find(query.begin(), query.end(), v.name()) != query.end()) continue;
        observed.emplace(v.name(), v.states()[random() % v.cardinality()]);
      }
      check.set_evidence(resolve_evidence(net, observed));
      if (std::isinf(check.log_probability_of_evidence())) continue;  // impossible evidence
      cases.emplace_back(std::move(query), std::move(observed));
    }
    nlohmann::json requests = nlohmann::json::array();
    for (const auto& [variables, observed] : cases) requests.push_back({{"query", variables}, {"evidence", observed}});
    for (const auto& [variables, observed] : cases) {
      requests.push_back({{"query", variables}, {"evidence", observed}, {"mpe", true}});
    }
    const auto answers = ask_pgmpy("queries", file, requests);
    ASSERT_EQ(answers.size(), 2 * cases.size());
    double largest = 0.0;
    for (const char* engine_name : {"jt", "ve"}) {
      auto engine = make_engine(engine_name, net);
      for (std::size_t i = 0; i < cases.size(); ++i) {
        set_evidence(engine, cases[i].second);
        const auto ours = query(engine, cases[i].first);
        for (const auto& row : answers[i]) {
          std::vector<std::string> labels;
          for (const auto& v : ours.variables) labels.push_back(row["states"][v.name()].get<std::string>());
          const double difference = std::abs(ours.probability(labels) - row["p"].get<double>());
          largest = std::max(largest, difference);
          EXPECT_LT(difference, 1e-12) << name << " " << engine_name << " " << requests[i].dump();
        }
        const auto best = most_probable(engine, cases[i].first);
        const auto& theirs = answers[cases.size() + i]["mpe"];
        bool same = true;
        for (const auto& [variable, state] : best.assignment()) same = same && theirs[variable] == state;
        if (!same) {
          // A tie: pgmpy's states must be as probable as ours.
          std::vector<std::string> labels;
          for (const auto& v : ours.variables) labels.push_back(theirs[v.name()].get<std::string>());
          EXPECT_NEAR(ours.probability(labels), best.probability, 1e-12) << name << " " << requests[i].dump();
        }
      }
    }
    std::cout << name << ": largest difference from pgmpy " << largest << '\n';
  }
}

TEST_F(pgmpy_agreement_test, interventions_equal_pgmpy_causal_inference_on_published_networks) {
  // Without evidence pgmpy's adjustment by the intervened variable's parents is the do-query,
  // and the two agree. With evidence, pgmpy computes Σ_z P(y | x, z, e) P(z) and drops the
  // evidence's bearing on z — asia, P(smoke | do(tub = no), lung = yes) is 0.5 there, 0.909 by
  // the truncated factorisation (docs/causal.md) — so the cases with evidence are compared with
  // enumeration in causal_test, not with pgmpy; here their disagreements are counted. pgmpy
  // cannot query a parent of the intervened variable (it conditions on it and refuses).
  std::mt19937_64 random(5);
  for (const char* name : {"asia", "child", "insurance", "alarm"}) {
    const auto net = normalized(read_bif(std::filesystem::path(PGM_NETWORKS_DIR) / (std::string(name) + ".bif")));
    const auto file = path(std::string(name) + "-do.xml");
    write_network(net, file);
    std::vector<std::tuple<std::string, intervention, evidence>> cases;
    variable_elimination check(net);
    while (cases.size() < 12) {
      const auto& x = net.variables()[random() % net.size()];
      const auto& y = net.variables()[random() % net.size()];
      if (x.name() == y.name()) continue;
      const variable_id from[] = {net.id(x.name())};
      const auto below = detail::descendants(net.graph(), from);
      const auto parents = net.graph().parents(from[0]);
      const auto is_parent = [&](const variable& v) {
        return std::find(parents.begin(), parents.end(), net.id(v.name())) != parents.end();
      };
      if (is_parent(y)) continue;
      evidence observed;
      if (cases.size() % 2) {
        const auto& e = net.variables()[random() % net.size()];
        if (below[net.id(e.name()).value()] || e.name() == y.name() || is_parent(e)) continue;
        observed.emplace(e.name(), e.states()[random() % e.cardinality()]);
      }
      const intervention set{{x.name(), x.states()[random() % x.cardinality()]}};
      check.set_evidence(resolve_evidence(net, observed, {}, set));
      if (std::isinf(check.log_probability_of_evidence())) continue;
      cases.emplace_back(y.name(), set, observed);
    }
    nlohmann::json requests = nlohmann::json::array();
    for (const auto& [y, set, observed] : cases) {
      requests.push_back({{"query", {y}}, {"evidence", observed}, {"do", set}});
    }
    const auto answers = ask_pgmpy("queries", file, requests);
    ASSERT_EQ(answers.size(), cases.size());
    std::size_t compared = 0;
    std::size_t pgmpy_differs_with_evidence = 0;
    std::size_t pgmpy_undefined = 0;
    for (const char* engine_name : {"jt", "ve"}) {
      auto engine = make_engine(engine_name, net);
      for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto& [y, set, observed] = cases[i];
        // NaN (null) where pgmpy's adjustment set has a stratum in which X never takes the value
        // set: 0/0 in its P(y | x, z), while the do-query itself is defined (docs/causal.md).
        const bool undefined = std::any_of(answers[i].begin(), answers[i].end(),
                                           [](const nlohmann::json& row) { return row["p"].is_null(); });
        if (undefined) {
          pgmpy_undefined += observed.empty();
          continue;
        }
        set_evidence(engine, observed, {}, set);
        const auto ours = marginal(engine, y);
        bool differs = false;
        for (const auto& row : answers[i]) {
          const std::string state = row["states"][y].get<std::string>();
          const double difference = std::abs(ours.probability({state}) - row["p"].get<double>());
          differs = differs || difference > 1e-12;
          if (observed.empty()) {
            EXPECT_LT(difference, 1e-12) << name << " " << engine_name << " " << requests[i].dump();
          }
        }
        compared += observed.empty();
        pgmpy_differs_with_evidence += !observed.empty() && differs;
      }
    }
    EXPECT_GT(compared, 0U) << name;
    std::cout << name << ": " << compared / 2 << " do-queries without evidence equal pgmpy's (" << pgmpy_undefined / 2
              << " more where pgmpy answers NaN); with evidence pgmpy differs in " << pgmpy_differs_with_evidence / 2
              << " of " << cases.size() / 2 << "\n";
  }
}

TEST_F(pgmpy_agreement_test, yates_statistics_equal_pgmpy_chi_square_and_g_sq) {
  // Few rows, so that many strata are sparse and some are 2 x 2.
  const auto net = read_bif(sachs_path);
  const auto data = sample(net, 1000, 11);
  const auto csv = path("sachs.csv");
  write_csv(data, csv);
  struct ci_case {
    std::string x, y;
    std::vector<std::string> z;
  };
  const std::vector<ci_case> cases{{"Raf", "Mek", {}},
                                   {"Raf", "Erk", {"Mek"}},
                                   {"PKA", "Akt", {"Erk", "PKC"}},
                                   {"Plcg", "PIP3", {"PIP2", "PKC", "Jnk"}},
                                   {"P38", "Jnk", {"PKC", "PKA"}},
                                   {"Akt", "Mek", {"Raf", "PKA", "Erk"}}};
  nlohmann::json requests = nlohmann::json::array();
  for (const auto& c : cases) requests.push_back({{"x", c.x}, {"y", c.y}, {"z", c.z}});
  const auto answers = ask_pgmpy("ci", csv, requests);
  ASSERT_EQ(answers.size(), cases.size());
  std::size_t corrected = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    for (const auto test : {ci_test::chi_square, ci_test::g_squared}) {
      const auto theirs = answers[i][std::string(to_string(test))];
      const auto ours = test_independence(data, cases[i].x, cases[i].y, cases[i].z,
                                          {.test = test, .correction = continuity_correction::yates});
      const auto plain = test_independence(data, cases[i].x, cases[i].y, cases[i].z, test);
      corrected += ours.statistic != plain.statistic;
      const double statistic = theirs["statistic"].get<double>();
      EXPECT_NEAR(ours.statistic, statistic, 1e-9 * std::max(1.0, statistic)) << requests[i].dump();
      EXPECT_EQ(ours.df, theirs["df"].get<double>()) << requests[i].dump();
      // pgmpy's p-value of a test with no degrees of freedom is NaN; ours is 1.
      if (ours.df > 0) {
        EXPECT_NEAR(ours.p_value, theirs["p"].get<double>(), 1e-9) << requests[i].dump();
      }
    }
  }
  // The cases must exercise the correction, or the comparison shows nothing about it.
  EXPECT_GT(corrected, 0u);
}

/// Expects pgmpy's reading of a file (one entry of the oracle's "formats" answer) to hold
/// `net`'s tables exactly: the same parents in order, states and every bit of every value.
void expect_same_tables(const nlohmann::json& theirs, const bayesian_network& net, const std::string& what) {
  ASSERT_EQ(theirs.size(), net.size()) << what;
  for (const auto& cpd : theirs) {
    const auto& table = net.table(cpd["variable"].get<std::string>());
    std::vector<std::string> parents;
    for (const auto& p : table.parents()) parents.push_back(p.name());
    EXPECT_EQ(cpd["parents"].get<std::vector<std::string>>(), parents) << what;
    EXPECT_EQ(cpd["states"][table.child().name()].get<std::vector<std::string>>(), table.child().states()) << what;
    const auto& rows = cpd["values"];
    ASSERT_EQ(rows.size(), table.configurations()) << what;
    std::size_t differ = 0;
    for (std::size_t u = 0; u < table.configurations(); ++u) {
      const auto column = table.column(index_at<config_index>(u));
      for (std::size_t x = 0; x < column.size(); ++x) differ += rows[u][x].get<double>() != column[x];
    }
    EXPECT_EQ(differ, 0u) << what << ": " << table.child().name();
  }
}

TEST_F(pgmpy_agreement_test, files_we_write_pgmpy_reads_and_files_pgmpy_writes_we_read) {
  const auto water = read_bif(std::filesystem::path(PGM_NETWORKS_DIR) / "water.bif");
  const auto sachs = read_bif(sachs_path);
  // Names with '-' and states with punctuation, which BIF writes as they are.
  const variable a("x-off", {"<=0.5", "a+b", "1e-3"});
  const variable b("on-top", {"no", "yes"});
  const auto dashed = bayesian_network::from_tables(
      {cpt<double>(a, {}, {0.2, 0.3, 0.5}), cpt<double>(b, {a}, {0.1, 0.9, 0.4, 0.6, 0.5, 0.5})});
  const std::vector<std::pair<std::string, const bayesian_network*>> ours{{"water.bif", &water},
                                                                          {"water.xml", &water},
                                                                          {"sachs.xml", &sachs},
                                                                          {"dashed.bif", &dashed},
                                                                          {"dashed.xml", &dashed}};
  nlohmann::json request = {{"read", nlohmann::json::array()}};
  for (const auto& [name, net] : ours) {
    write_network(*net, path(name));
    request["read"].push_back(path(name).string());
  }
  // A fit's counts, kept in a network-level property (pgm fit --keep-counts), which pgmpy ignores.
  fit_statistics counted;
  counted.rows = 3;
  for (const auto& table : dashed.tables()) {
    expected_count_table counts(table.child(), table.parents());
    counts.counts()[0] = 3;
    counted.counts.push_back(std::move(counts));
    counted.priors.emplace_back(k2_prior{});
  }
  for (const char* name : {"counted.bif", "counted.xml"}) {
    write_network(dashed, path(name), {.statistics = &counted});
    ASSERT_TRUE(read_model(path(name)).statistics.has_value());
    request["read"].push_back(path(name).string());
  }
  request["rewrite"] = {
      {{"in", sachs_path.string()}, {"bif", path("pgmpy.bif").string()}, {"xmlbif", path("pgmpy.xml").string()}}};
  const auto answers = ask_pgmpy("formats", "-", request);
  ASSERT_EQ(answers.size(), ours.size() + 2);
  for (std::size_t i = 0; i < ours.size(); ++i) expect_same_tables(answers[i], *ours[i].second, ours[i].first);
  expect_same_tables(answers[ours.size()], dashed, "counted.bif");
  expect_same_tables(answers[ours.size() + 1], dashed, "counted.xml");
  // pgmpy's BIFWriter and XMLBIFWriter output, read by us: the same network (sachs's states are
  // letters, which pgmpy's XMLBIFWriter leaves alone; it rewrites others to letters, digits, '_').
  EXPECT_EQ(read_network(path("pgmpy.bif")), sachs);
  EXPECT_EQ(read_network(path("pgmpy.xml")), sachs);
}

}  // namespace
}  // namespace pgm::pgmpy_agreement_tests
