#pragma once
// The definitions of pgm/learn/structure_learners.hpp: inline in a header-only build, compiled
// once into libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/core/error.hpp"
#include "pgm/learn/independence_test_registry.hpp"
#include "pgm/learn/orientation.hpp"
#include "pgm/learn/score_registry.hpp"
#include "pgm/learn/structure_learner_registry.hpp"
#include "pgm/learn/structure_learners.hpp"

namespace pgm {
namespace detail {

/// PC's options, read into `settings`.
inline pc_options read_pc_options(const option_values& options) {
  pc_options settings;
  settings.test = make_independence_test(options.component("test"));
  settings.alpha = options.number("alpha");
  settings.max_conditioning = options.count("max_conditioning");
  return settings;
}

/// Hill climbing's options, read into `settings`.
inline search_options read_search_options(const option_values& options) {
  search_options settings;
  settings.score = make_score(options.component("score"));
  settings.max_parents = options.count("max_parents");
  settings.restarts = options.count("restarts");
  settings.perturb = options.count("perturb");
  settings.seed = options.count("seed");
  settings.max_iterations = options.count("max_iterations");
  return settings;
}

/// The start learner `options` name, if any other than the empty graph.
inline std::optional<structure_learner> read_start(const option_values& options) {
  auto start = make_structure_learner(options.component("start"));
  if (start.name() == "empty") return std::nullopt;
  return start;
}

}  // namespace detail

PGM_DECL std::vector<option_declaration> pc_learner::options() {
  const pc_options defaults;
  return {
      component_option("test", &independence_tests, defaults.test.name(), "the independence test"),
      number_option("alpha", defaults.alpha, "significance level: an edge goes when a test has p > alpha")
          .greater_than(0.0)
          .less_than(1.0),
      count_option("max_conditioning", defaults.max_conditioning, "the largest conditioning set tried").at_most(64),
  };
}

PGM_DECL pc_learner::pc_learner(const option_values& options) : settings_(detail::read_pc_options(options)) {}

PGM_DECL structure_result pc_learner::learn(const structure_problem& problem) const {
  if (!problem.start.empty()) throw model_error("PC-stable takes no start network; hc, tabu and mmhc do");
  if (!problem.favoured.empty() || problem.favour_weight != 0.0)
    throw model_error("PC-stable takes no structure prior; hc, tabu and mmhc do");
  auto settings = settings_;
  settings.knowledge = problem.knowledge;
  settings.threads = problem.threads;
  auto learned = pc_stable(problem.columns, settings);
  structure_result result;
  result.graph = learned.graph;
  result.edges = extend_to_dag(learned.graph, true, &result.relaxed);
  result.pc = std::move(learned);
  return result;
}

PGM_DECL std::vector<option_declaration> hill_climbing_learner::options() {
  const search_options defaults;
  return {
      component_option("score", &scores, defaults.score.name(), "the decomposable score"),
      count_option("max_parents", defaults.max_parents, "the most parents a node may get"),
      count_option("restarts", defaults.restarts, "random restarts after the search converges").at_most(100000),
      count_option("perturb", defaults.perturb, "random moves that perturb the network at each restart")
          .at_least(1)
          .at_most(100000),
      count_option("seed", defaults.seed, "seed of the restarts' perturbations"),
      count_option("max_iterations", defaults.max_iterations, "the most moves of one search"),
      component_option("start", &structure_learners, "empty", "the learner whose network the search starts from"),
  };
}

PGM_DECL hill_climbing_learner::hill_climbing_learner(search_options settings, std::optional<structure_learner> start)
    : settings_(std::move(settings)), start_(std::move(start)) {}

PGM_DECL hill_climbing_learner::hill_climbing_learner(const option_values& options)
    : settings_(detail::read_search_options(options)), start_(detail::read_start(options)) {}

PGM_DECL structure_result hill_climbing_learner::search(const structure_problem& problem,
                                                        std::vector<unsigned char> candidates) const {
  auto settings = settings_;
  settings.knowledge = problem.knowledge;
  settings.threads = problem.threads;
  settings.favoured = problem.favoured;
  settings.favour_weight = problem.favour_weight;
  settings.candidates = std::move(candidates);
  if (!problem.start.empty()) settings.start = problem.start;
  if (start_) {
    if (!problem.start.empty()) {
      throw model_error("the search has two starts: a start network and the learner " + start_->text());
    }
    structure_problem first = problem;
    first.favoured.clear();
    first.favour_weight = 0.0;
    settings.start = start_->learn(first).edges;
  }
  auto learned = hill_climb(problem.columns, settings);
  auto result = dag_result(problem.names, learned.edges);
  result.search = std::move(learned);
  return result;
}

PGM_DECL structure_result hill_climbing_learner::learn(const structure_problem& problem) const {
  return search(problem, {});
}

PGM_DECL std::vector<option_declaration> tabu_search_learner::options() {
  auto declared = hill_climbing_learner::options();
  const search_options defaults;
  declared.insert(declared.begin() + 1,
                  {count_option("tabu", 10, "length of the tabu list (bnlearn's default)").at_least(1).at_most(100000),
                   count_option("max_tabu", defaults.max_tabu,
                                "moves in a row without improving on the best network before the search stops")
                       .at_most(100000)});
  return declared;
}

PGM_DECL tabu_search_learner::tabu_search_learner() : tabu_search_learner(option_values(options())) {}

PGM_DECL tabu_search_learner::tabu_search_learner(const option_values& options) : hill_climbing_learner(options) {
  settings_.tabu = options.count("tabu");
  settings_.max_tabu = options.count("max_tabu");
}

PGM_DECL std::vector<option_declaration> hybrid_learner::options() {
  auto declared = pc_learner::options();
  for (auto& option : hill_climbing_learner::options()) declared.push_back(std::move(option));
  return declared;
}

PGM_DECL hybrid_learner::hybrid_learner(const option_values& options)
    : hill_climbing_learner(options), restrict_(detail::read_pc_options(options)) {}

PGM_DECL structure_result hybrid_learner::learn(const structure_problem& problem) const {
  // The restrict phase: PC-stable's skeleton; the maximize phase: hill climbing within it.
  auto restrict = restrict_;
  restrict.knowledge = problem.knowledge;
  restrict.threads = problem.threads;
  const edge_constraints constraints(restrict.knowledge, problem.names);
  const auto skeleton = pc_skeleton(problem.columns, constraints, restrict);
  const std::size_t n = problem.columns.size();
  std::vector<unsigned char> candidates(n * n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (i != j && skeleton.graph.adjacent(detail::node(i), detail::node(j))) candidates[i * n + j] = 1;
    }
  }
  return search(problem, std::move(candidates));
}

PGM_DECL structure_result empty_learner::learn(const structure_problem& problem) const {
  static_cast<void>(edge_constraints(problem.knowledge, problem.names));  // refuses what contradicts itself
  return dag_result(problem.names, problem.knowledge.required);
}

}  // namespace pgm
