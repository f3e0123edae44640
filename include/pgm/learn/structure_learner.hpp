#pragma once
/// \file
/// The seam of structure learning, as `InferenceEngine` is inference's: a `StructureLearner`
/// learns a DAG from a `structure_problem` (the data's discrete columns and what is known about
/// them) and fills a `structure_result`, which every learner shares. `structure_learner` holds
/// any of them with the choice that made it ("hc[score=bdeu[iss=10]]"); the built-in learners
/// are in pgm/learn/structure_learners.hpp, their registry in
/// pgm/learn/structure_learner_registry.hpp.

#include <concepts>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/component_registry.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/learn/background_knowledge.hpp"
#include "pgm/learn/cpdag.hpp"
#include "pgm/learn/hill_climbing.hpp"
#include "pgm/learn/pc.hpp"

namespace pgm {

/// What a learner is given besides its own options.
struct structure_context {
  /// Tiers, forbidden and required edges, which every learner keeps.
  background_knowledge knowledge;
  /// A network a score search starts from instead of the empty graph.
  std::vector<named_edge> start;
  /// A structure prior: a score search adds `favour_weight` for each of these edges present
  /// (pgm/learn/structure_prior.hpp maps a related task's network to them).
  std::vector<named_edge> favoured;
  double favour_weight = 0.0;
  /// Worker threads; 0 uses every hardware thread. A learner's result is the same for any number.
  unsigned threads = 0;
};

struct structure_problem : structure_context {
  /// The variables, all discrete, in the order the result lists them.
  std::vector<const discrete_column*> columns;
  std::vector<std::string> names;
};

/// What every learner returns.
struct structure_result {
  /// The learner's registered name ("pc", "hc", a user's), set by learn_structure.
  std::string learner;
  /// The learned DAG (for PC, one DAG of its CPDAG's class).
  std::vector<named_edge> edges;
  /// PC's CPDAG; for the score searches, the CPDAG of the learned DAG's class.
  cpdag graph;
  /// PC: the nodes given new v-structures to extend its CPDAG to a DAG.
  std::size_t relaxed = 0;
  /// The details of PC-stable's tests and of a score search, when the learner ran one.
  std::optional<pc_result> pc;
  std::optional<search_result> search;
};

template <class L>
concept StructureLearner = std::copy_constructible<L> && requires(const L& learner, const structure_problem& problem) {
  { learner.learn(problem) } -> std::same_as<structure_result>;
};

/// Any structure learner, with the name and options it was chosen by.
class structure_learner : public chosen_function<structure_result(const structure_problem&)> {
 public:
  template <StructureLearner L>
  requires(!std::same_as<L, structure_learner>) structure_learner(L learner, component_choice choice)
      : chosen_function(
            [learner = std::move(learner)](const structure_problem& problem) { return learner.learn(problem); },
            std::move(choice)) {}

  [[nodiscard]] structure_result learn(const structure_problem& problem) const { return (*this)(problem); }
};

static_assert(StructureLearner<structure_learner>);

/// The DAG `edges` over `names` with its class's CPDAG, as a learner that finds a DAG reports it.
[[nodiscard]] PGM_DECL structure_result dag_result(const std::vector<std::string>& names,
                                                   std::vector<named_edge> edges);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/structure_learner.ipp"
#endif
