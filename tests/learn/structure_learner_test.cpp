#include "pgm/learn/structure_learner.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "pgm/inference/sampling.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/learn/background_knowledge.hpp"
#include "pgm/learn/learn_structure.hpp"
#include "pgm/learn/orientation.hpp"
#include "pgm/learn/structural_hamming_distance.hpp"
#include "pgm/learn/structure_learner_registry.hpp"
#include "pgm/learn/structure_learners.hpp"

namespace pgm::structure_learner_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

bayesian_network asia() { return read_bif(std::filesystem::path(PGM_NETWORKS_DIR) / "asia.bif"); }

std::vector<const discrete_column*> columns_of(const dataset& data) {
  std::vector<const discrete_column*> columns;
  for (const auto& name : data.names()) columns.push_back(&data.discrete(name));
  return columns;
}

/// A user's learner: each column a parent of the next, up to `length` edges, where the
/// background knowledge allows, and the required edges.
class chain_learner {
 public:
  static std::vector<option_declaration> options() { return {count_option("length", 2, "the most edges").at_least(1)}; }
  explicit chain_learner(const option_values& options) : length_(options.count("length")) {}

  structure_result learn(const structure_problem& problem) const {
    const edge_constraints constraints(problem.knowledge, problem.names);
    std::vector<named_edge> edges = problem.knowledge.required;
    for (std::size_t i = 1, added = 0; i < problem.names.size() && added < length_; ++i) {
      if (!constraints.allowed(i - 1, i) || constraints.required(i - 1, i)) continue;
      edges.push_back({problem.names[i - 1], problem.names[i]});
      ++added;
    }
    return dag_result(problem.names, edges);
  }

 private:
  std::size_t length_;
};

const register_structure_learner<chain_learner> chain("chain", "each column a parent of the next");

TEST(structure_learner_test, the_registry_holds_the_built_in_learners_and_a_users) {
  EXPECT_EQ(structure_learners().names(), (std::vector<std::string>{"chain", "empty", "hc", "mmhc", "pc", "tabu"}));
  EXPECT_EQ(make_structure_learner(default_structure_learner).name(), "pc");
  const auto data = sample(asia(), 500, 1);
  const auto learned = learn_structure(data, make_structure_learner("chain[length=3]"));
  EXPECT_EQ(learned.learner, "chain");
  ASSERT_EQ(learned.edges.size(), 3u);
  EXPECT_EQ(learned.edges[2], (named_edge{data.names()[2], data.names()[3]}));
  EXPECT_THAT([] { static_cast<void>(make_structure_learner("chain[length=0]")); },
              ThrowsMessage<model_error>(HasSubstr("option length of the structure learner 'chain' must be")));
}

TEST(structure_learner_test, every_learner_is_its_algorithm_with_its_options) {
  const auto data = sample(asia(), 20000, 4);
  const auto truth = cpdag_of(asia().graph());
  for (const char* name : {"hc", "tabu", "mmhc"}) {
    const auto result = learn_structure(data, make_structure_learner(name));
    EXPECT_EQ(result.learner, name);
    ASSERT_TRUE(result.search.has_value()) << name;
    EXPECT_EQ(result.edges, result.search->edges);
    EXPECT_LE(structural_hamming_distance(result.graph, truth), 4u) << name;
  }
  // pc[test=g2,...] is pc_stable with those options.
  pc_options options;
  options.test = make_independence_test("g2");
  options.alpha = 0.05;
  options.max_conditioning = 2;
  const auto pc = learn_structure(data, make_structure_learner("pc[test=g2, alpha=0.05, max_conditioning=2]"));
  ASSERT_TRUE(pc.pc.has_value());
  EXPECT_EQ(pc.graph, pc_stable(data, data.names(), options).graph);
  // hc is hill_climb with its options; tabu sets a tabu list of 10 (bnlearn's) unless told.
  search_options search;
  search.score = make_score("bdeu[iss=10]");
  search.restarts = 2;
  search.seed = 9;
  const auto hc = learn_structure(data, make_structure_learner("hc[score=bdeu[iss=10],restarts=2,seed=9]"));
  EXPECT_EQ(hc.edges, hill_climb(columns_of(data), search).edges);
  EXPECT_EQ(tabu_search_learner().settings().tabu, 10u);
  EXPECT_EQ(hill_climbing_learner().settings().tabu, 0u);
  search.tabu = 4;
  search.max_tabu = 3;
  const auto tabu =
      learn_structure(data, make_structure_learner("tabu[score=bdeu[iss=10],restarts=2,seed=9,tabu=4,max_tabu=3]"));
  EXPECT_EQ(tabu.edges, hill_climb(columns_of(data), search).edges);
  EXPECT_THAT([] { static_cast<void>(make_structure_learner("tabu[tabu=0]")); },
              ThrowsMessage<model_error>(HasSubstr(
                  "option tabu of the structure learner 'tabu' must be a whole number from 1 to 100000, got '0'")));
  // mmhc keeps to the skeleton of its own PC options.
  const auto mmhc = learn_structure(data, make_structure_learner("mmhc[test=g2,alpha=0.05,max_conditioning=2]"));
  const auto skeleton = pc_skeleton(columns_of(data), edge_constraints(data.size()), options);
  for (const auto& e : mmhc.edges) {
    EXPECT_TRUE(skeleton.graph.adjacent(skeleton.graph.id(e.from), skeleton.graph.id(e.to))) << e.from << e.to;
  }
}

TEST(structure_learner_test, a_search_starts_from_a_network_or_from_another_learner) {
  const auto data = sample(asia(), 3000, 5);
  const auto pc = learn_structure(data, make_structure_learner("pc[alpha=0.05]"));
  const auto from_pc = learn_structure(data, make_structure_learner("hc[start=pc[alpha=0.05]]"));
  const auto given = learn_structure(data, make_structure_learner("hc"), {.start = pc.edges});
  EXPECT_EQ(from_pc.edges, given.edges);
  EXPECT_EQ(make_structure_learner("hc[start=pc]").options().component("start"), "pc");
  EXPECT_THAT(
      [&] { static_cast<void>(learn_structure(data, make_structure_learner("hc[start=pc]"), {.start = pc.edges})); },
      ThrowsMessage<model_error>(HasSubstr("two starts")));
  EXPECT_THAT([&] { static_cast<void>(learn_structure(data, make_structure_learner("pc"), {.start = pc.edges})); },
              ThrowsMessage<model_error>(HasSubstr("PC-stable takes no start network")));
  EXPECT_THAT([&] { static_cast<void>(learn_structure(data, make_structure_learner("pc"), {.favoured = pc.edges})); },
              ThrowsMessage<model_error>(HasSubstr("PC-stable takes no structure prior")));
}

TEST(structure_learner_test, the_empty_graph_keeps_the_required_edges) {
  const auto data = sample(asia(), 200, 6);
  structure_context context;
  context.knowledge.required = {{"smoke", "lung"}};
  const auto learned = learn_structure(data, make_structure_learner("empty"), context);
  EXPECT_EQ(learned.edges, context.knowledge.required);
  context.knowledge.required = {{"smoke", "lungs"}};
  EXPECT_THAT([&] { static_cast<void>(learn_structure(data, make_structure_learner("empty"), context)); },
              ThrowsMessage<model_error>(HasSubstr("lungs")));
}

TEST(structure_learner_test, settings_given_apart_go_to_the_learner_and_to_its_start) {
  const auto learner = [](const char* text, std::vector<component_setting> settings) {
    return make_structure_learner(text, settings).text();
  };
  EXPECT_EQ(learner("mmhc", {{"--alpha", "alpha", "0.05"}, {"--restarts", "restarts", std::nullopt}}),
            make_structure_learner("mmhc[alpha=0.05]").text());
  // --start pc --alpha: PC's alpha, not hc's (which has none).
  EXPECT_EQ(learner("hc", {{"--start", "start", "pc"}, {"--alpha", "alpha", "0.05"}}),
            make_structure_learner("hc[start=pc[alpha=0.05]]").text());
  // mmhc from pc: the alpha of both.
  EXPECT_EQ(learner("mmhc", {{"--start", "start", "pc"}, {"--alpha", "alpha", "0.05"}}),
            make_structure_learner("mmhc[start=pc[alpha=0.05],alpha=0.05]").text());
  EXPECT_THAT(
      [&] {
        static_cast<void>(learner("hc", {{"--alpha", "alpha", "0.05"}}));
      },
      ThrowsMessage<model_error>(HasSubstr("--alpha: sets the option alpha, which the structure learner hc has not")));
  EXPECT_THAT(
      [&] {
        static_cast<void>(learner("pc", {{"--start", "start", "pc"}}));
      },
      ThrowsMessage<model_error>(HasSubstr("--start: sets the option start, which the structure learner pc has not")));
  EXPECT_THAT(
      [&] {
        static_cast<void>(learner("hc", {{"--start", "start", "pcc"}}));
      },
      ThrowsMessage<model_error>(HasSubstr("--start: unknown structure learner 'pcc'")));
  EXPECT_THAT(
      [&] {
        static_cast<void>(learner("pc[alpha=0.1]", {{"--alpha", "alpha", "0.05"}}));
      },
      ThrowsMessage<model_error>(HasSubstr("--alpha: sets alpha, which 'pc[alpha=0.1]' sets already")));
}

}  // namespace
}  // namespace pgm::structure_learner_tests
