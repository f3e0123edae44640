#pragma once
/// \file
/// The junction tree engine ("jt"): the network compiled once into a `junction_tree`, then
/// Shafer–Shenoy propagation (propagation.hpp) answering every query from kept messages.
/// Marginals run in sum-product, falling back to log space when P(evidence) underflows; the
/// most probable explanation runs in max-product on the same tree (log-max when it underflows);
/// the most probable state of a subset, which needs its sums before its maxima, is handed to
/// variable elimination.
///
/// One propagation per semiring, each made on first use and told the evidence lazily, so an
/// engine that only ever answers marginals holds one set of tables.
///
/// Pruning where it pays: a query whose kept messages do not cover it would recompute the
/// messages from the evidence to its clique through every clique on the way, whole, even where
/// the network's tables there are barren for this query or d-separated from it. When the query's
/// relevant part (the ancestors of query and evidence: what is left after removing barren nodes,
/// in which the evidence separates the d-separated parts) has fewer cells than that work by a
/// wide margin, the engine eliminates that part instead, as variable elimination does, and keeps
/// its messages for later. A second query under the same evidence counts the work as shared, so
/// repeated queries propagate.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/inference/exact.hpp"
#include "pgm/inference/junction_tree.hpp"
#include "pgm/inference/propagation.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/inference/semiring.hpp"
#include "pgm/inference/variable_elimination.hpp"

namespace pgm {

class junction_tree_engine {
 public:
  /// Compiles `network` (which must outlive the engine). Throws table_too_large when the tree
  /// exceeds options.max_cells.
  explicit junction_tree_engine(const bayesian_network& network, const junction_tree_options& options = {})
      : network_(&network), tree_(std::make_shared<const junction_tree>(network, options)), options_(options) {}

  static constexpr bool handles_interventions = true;
  [[nodiscard]] std::string_view name() const noexcept { return "jt"; }
  [[nodiscard]] const bayesian_network& network() const noexcept { return *network_; }
  [[nodiscard]] const junction_tree& tree() const noexcept { return *tree_; }
  [[nodiscard]] const evidence_set& evidence() const noexcept { return evidence_; }

  /// Replaces the evidence: hard and soft, entered or retracted, nothing recompiled.
  PGM_DECL void set_evidence(evidence_set observed);

  [[nodiscard]] PGM_DECL posterior joint(std::span<const variable_id> query);

  /// The marginal of each of `nodes`: after the first, each costs a fold of a kept belief.
  [[nodiscard]] PGM_DECL std::vector<posterior> marginals(std::span<const variable_id> nodes);

  [[nodiscard]] double log_probability_of_evidence() {
    return detail::exact_log_evidence([&]<Semiring S>() { return in<S>().total(); });
  }

  /// The most probable joint state of `variables` (every unobserved variable when empty).
  [[nodiscard]] PGM_DECL mpe_result mpe(std::span<const variable_id> variables = {});

 private:
  /// Variable elimination costs more per cell than propagation (it builds its tables afresh,
  /// and its product tables outgrow the network's): 24 puts the choice where the single-query
  /// benchmark of bench/inference_bench.cpp is fastest on every published network it runs
  /// (alarm and hailfinder propagate, insurance and pathfinder eliminate).
  static constexpr std::size_t elimination_cell_cost = 24;

  /// The cells of the tables in the relevant part of a query: the ancestors of the query and
  /// evidence variables (the rest is barren).
  [[nodiscard]] PGM_DECL std::size_t relevant_cells(std::span<const variable_id> query) const;

  /// Whether eliminating the query's relevant part is cheaper than the messages it needs.
  [[nodiscard]] PGM_DECL bool eliminating_pays(std::span<const variable_id> query);

  /// Whether eliminating each node's relevant part in turn is cheaper than the propagation to
  /// all their homes.
  [[nodiscard]] PGM_DECL bool eliminating_each_pays(std::span<const variable_id> nodes);

  PGM_DECL variable_elimination& elimination();

  template <Semiring S>
  struct slot {
    std::unique_ptr<propagation<S>> engine;
    std::size_t version = 0;
  };

  /// The propagation in S, made on first use, with the current evidence.
  template <Semiring S>
  propagation<S>& in() {
    auto& s = std::get<slot<S>>(propagations_);
    if (!s.engine) s.engine = std::make_unique<propagation<S>>(tree_, *network_);
    if (s.version != version_) {
      s.engine->set_evidence(evidence_);
      s.version = version_;
    }
    return *s.engine;
  }

  const bayesian_network* network_;
  std::shared_ptr<const junction_tree> tree_;
  junction_tree_options options_;
  evidence_set evidence_;
  std::size_t version_ = 1;
  std::size_t queries_since_evidence_ = 0;
  std::unique_ptr<variable_elimination> elimination_;
  std::size_t elimination_version_ = 0;
  std::tuple<slot<sum_product<double>>, slot<log_sum_product<double>>, slot<max_product<double>>,
             slot<log_max_product<double>>>
      propagations_;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/inference/impl/junction_tree_engine.ipp"
#endif
