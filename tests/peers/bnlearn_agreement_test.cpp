// Agreement with R bnlearn 4.9, run only where cmake/peers.cmake installed it from ../shared/peers
// (tests/CMakeLists.txt): on samples of the published asia, child, insurance and alarm networks,
// every score of the true DAG, in total and node by node, equals bnlearn's score() to 1e-9
// (relative), and hill climbing and tabu search with BIC reach networks whose BIC is at least that
// of bnlearn's hc() and tabu() on the same data (whose arcs pgm scores as bnlearn does); hill
// climbing's is in the same equivalence class as bnlearn's. PGM_RSCRIPT runs
// tests/peers/bnlearn_oracle.R with R_LIBS=PGM_BNLEARN_LIB.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "pgm/inference/sampling.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/learn/hill_climbing.hpp"
#include "pgm/learn/network_score.hpp"
#include "pgm/learn/orientation.hpp"
#include "pgm/learn/structural_hamming_distance.hpp"
#include "support/folder_test.hpp"

namespace pgm::bnlearn_agreement_tests {
namespace {

struct bnlearn_answers {
  struct score_line {
    std::string type;
    double iss = 1;
    double total = 0;
    std::vector<double> nodes;
  };
  std::vector<score_line> scores;
  double hc_bic = 0;
  double hc_seconds = 0;
  std::vector<named_edge> hc_arcs;
  double tabu_bic = 0;
};

class bnlearn_agreement_test : public pgm::testing::folder_test {
 protected:
  bnlearn_answers ask_bnlearn(const std::filesystem::path& network, const std::filesystem::path& csv) const {
    const auto answer = path("answer.txt");
    const auto command = std::string("R_LIBS='") + PGM_BNLEARN_LIB + "' " + PGM_RSCRIPT + " " + PGM_ORACLE + " " +
                         network.string() + " " + csv.string() + " " + answer.string() + " 2>" +
                         path("oracle.err").string();
    const int status = std::system(command.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << slurp(path("oracle.err"));
    bnlearn_answers answers;
    std::istringstream lines(slurp(answer));
    std::string line;
    while (std::getline(lines, line)) {
      std::istringstream words(line);
      std::string kind;
      words >> kind;
      if (kind == "score") {
        bnlearn_answers::score_line s;
        words >> s.type >> s.iss >> s.total;
        for (double v; words >> v;) s.nodes.push_back(v);
        answers.scores.push_back(s);
      } else if (kind == "hc") {
        words >> answers.hc_bic >> answers.hc_seconds;
      } else if (kind == "arc") {
        named_edge e;
        words >> e.from >> e.to;
        answers.hc_arcs.push_back(e);
      } else if (kind == "tabu") {
        words >> answers.tabu_bic;
      }
    }
    return answers;
  }
};

/// The data as CSV: each value's label.
std::string as_csv(const dataset& data) {
  std::string text;
  const auto names = data.names();
  for (std::size_t k = 0; k < names.size(); ++k) text += (k ? "," : "") + names[k];
  text += '\n';
  for (std::size_t row = 0; row < data.rows(); ++row) {
    for (std::size_t k = 0; k < names.size(); ++k) text += (k ? "," : "") + data.discrete(names[k]).label(row);
    text += '\n';
  }
  return text;
}

void expect_close(double pgm_value, double bnlearn_value, const std::string& what) {
  EXPECT_LE(std::abs(pgm_value - bnlearn_value), 1e-9 * std::max(1.0, std::abs(bnlearn_value)))
      << what << ": pgm " << text::format_double(pgm_value) << ", bnlearn " << text::format_double(bnlearn_value);
}

// bnlearn's score by its name and iss, which only bde reads.
family_score score_named(const std::string& bnlearn_name, double iss) {
  return make_score(bnlearn_name == "bde" ? "bde[iss=" + text::format_double(iss) + "]" : bnlearn_name);
}

TEST_F(bnlearn_agreement_test, scores_and_hill_climbing_on_published_networks) {
  struct sample_plan {
    const char* network;
    std::size_t rows;
  };
  for (const auto& plan : {sample_plan{"asia", 5000}, sample_plan{"child", 10000}, sample_plan{"insurance", 10000},
                           sample_plan{"alarm", 10000}}) {
    SCOPED_TRACE(plan.network);
    const auto bif = std::filesystem::path(PGM_NETWORKS_DIR) / (std::string(plan.network) + ".bif");
    const auto net = read_bif(bif);
    const auto data = sample(net, plan.rows, 24);
    const auto csv = file(std::string(plan.network) + ".csv", as_csv(data));
    const auto answers = ask_bnlearn(bif, csv);
    ASSERT_EQ(answers.scores.size(), 6u);

    // score() of the true DAG, the data under the network's states.
    for (const auto& s : answers.scores) {
      const auto mine = score_network(net.structure(), data, score_named(s.type, s.iss));
      expect_close(mine.total, s.total, s.type + " (iss " + text::format_short(s.iss) + ")");
      ASSERT_EQ(mine.nodes.size(), s.nodes.size());
      for (std::size_t i = 0; i < s.nodes.size(); ++i) {
        expect_close(mine.nodes[i], s.nodes[i], s.type + " of " + net.structure().variables()[i].name());
      }
    }

    // hc() on the states seen, as pgm reads a CSV file.
    const auto seen = read_csv(csv);
    const auto names = seen.names();
    const auto learned = hill_climb(seen, names, {});
    std::vector<variable> variables;
    for (const auto& name : names) variables.push_back(seen.discrete(name).var());
    expect_close(score_network(network_structure(variables, answers.hc_arcs), seen).total, answers.hc_bic,
                 "BIC of bnlearn's hc() network");
    EXPECT_GE(learned.score, answers.hc_bic - 1e-9 * std::abs(answers.hc_bic));
    dag mine(names), theirs(names);
    for (const auto& e : learned.edges) mine.add_edge(e.from, e.to);
    for (const auto& e : answers.hc_arcs) theirs.add_edge(e.from, e.to);
    const auto truth = cpdag_of(net.graph());
    std::cout << plan.network << " " << plan.rows << " rows: BIC pgm hc " << text::format_double(learned.score)
              << ", bnlearn hc " << text::format_double(answers.hc_bic) << " (" << answers.hc_seconds
              << " s), bnlearn tabu " << text::format_double(answers.tabu_bic) << "; CPDAG SHD to the truth: pgm "
              << structural_hamming_distance(cpdag_of(mine), truth) << ", bnlearn "
              << structural_hamming_distance(cpdag_of(theirs), truth) << "; between them "
              << structural_hamming_distance(cpdag_of(mine), cpdag_of(theirs)) << '\n';
    // The same moves in the same order: the same equivalence class as bnlearn's.
    EXPECT_EQ(structural_hamming_distance(cpdag_of(mine), cpdag_of(theirs)), 0u);
    // Tabu search improves on hill climbing, as bnlearn's does.
    search_options tabu;
    tabu.tabu = 10;
    const auto searched = hill_climb(seen, names, tabu);
    EXPECT_GE(searched.score, learned.score - 1e-9 * std::abs(learned.score));
    EXPECT_GE(searched.score, answers.tabu_bic - 1e-9 * std::abs(answers.tabu_bic));
    std::cout << "  pgm tabu " << text::format_double(searched.score) << '\n';
  }
}

}  // namespace
}  // namespace pgm::bnlearn_agreement_tests
