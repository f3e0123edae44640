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
  void set_evidence(evidence_set observed) {
    evidence_ = std::move(observed);
    ++version_;
    queries_since_evidence_ = 0;
  }

  [[nodiscard]] posterior joint(std::span<const variable_id> query) {
    if (eliminating_pays(query)) {
      auto result = elimination().joint(query);
      result.engine = std::string(name());
      return result;
    }
    return detail::exact_posterior(*network_, query, evidence_, std::string(name()),
                                   [&]<Semiring S>() { return in<S>().joint(query); });
  }

  /// The marginal of each of `nodes`: after the first, each costs a fold of a kept belief.
  [[nodiscard]] std::vector<posterior> marginals(std::span<const variable_id> nodes) {
    std::vector<posterior> result;
    result.reserve(nodes.size());
    if (eliminating_each_pays(nodes)) {
      // Each variable's relevant part is small (pathfinder's findings hang from one node):
      // eliminating them one by one beats the propagation.
      for (auto node : nodes) {
        const variable_id one[] = {node};
        result.push_back(elimination().joint(one));
        result.back().engine = std::string(name());
      }
      return result;
    }
    const auto sums = in<sum_product<double>>().marginals(nodes);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      double total = 0.0;
      for (double v : sums[i]) total += v;
      if (!detail::well_represented(total)) {
        // Underflow somewhere: every marginal from log space, each on its own.
        result.clear();
        for (auto node : nodes) {
          const variable_id one[] = {node};
          result.push_back(joint(one));
        }
        return result;
      }
      posterior p;
      p.engine = std::string(name());
      p.variables.push_back(network_->variables()[nodes[i].value()]);
      p.table = factor({nodes[i]}, {sums[i].size()}, sums[i]);
      p.table.normalize();
      p.evidence_probability = total;
      p.log_evidence_probability = std::log(total);
      result.push_back(std::move(p));
    }
    return result;
  }

  [[nodiscard]] double log_probability_of_evidence() {
    return detail::exact_log_evidence([&]<Semiring S>() { return in<S>().total(); });
  }

  /// The most probable joint state of `variables` (every unobserved variable when empty).
  [[nodiscard]] mpe_result mpe(std::span<const variable_id> variables = {}) {
    std::vector<variable_id> unobserved;
    for (std::size_t i = 0; i < network_->size(); ++i) {
      const variable_id id(static_cast<variable_id::rep>(i));
      if (!evidence_.fixes(id)) unobserved.push_back(id);
    }
    const double log_evidence = log_probability_of_evidence();
    std::vector<variable_id> chosen(variables.begin(), variables.end());
    std::sort(chosen.begin(), chosen.end());
    if (!variables.empty() && chosen != unobserved) {
      auto result = elimination().mpe(variables);
      result.engine = std::string(name());
      return result;
    }
    return detail::exact_mpe(*network_, unobserved, evidence_, log_evidence, std::string(name()), [&]<Semiring S>() {
      auto best = in<S>().maximize();
      std::vector<std::size_t> states;
      for (auto id : unobserved) states.push_back(best.states[id.value()]);
      return std::pair{std::move(states), best.value};
    });
  }

 private:
  /// Variable elimination costs more per cell than propagation (it builds its tables afresh,
  /// and its product tables outgrow the network's): 24 puts the choice where the single-query
  /// benchmark of bench/inference_bench.cpp is fastest on every published network it runs
  /// (alarm and hailfinder propagate, insurance and pathfinder eliminate).
  static constexpr std::size_t elimination_cell_cost = 24;

  /// The cells of the tables in the relevant part of a query: the ancestors of the query and
  /// evidence variables (the rest is barren).
  [[nodiscard]] std::size_t relevant_cells(std::span<const variable_id> query) const {
    const auto relevant = detail::relevant_set(*network_, query, evidence_);
    std::size_t cells = 0;
    for (std::size_t i = 0; i < network_->size(); ++i) {
      if (relevant[i]) cells += network_->tables()[i].size();
    }
    return cells;
  }

  /// Whether eliminating the query's relevant part is cheaper than the messages it needs.
  [[nodiscard]] bool eliminating_pays(std::span<const variable_id> query) {
    const auto shared = ++queries_since_evidence_;
    if (!options_.prune) return false;
    auto& sums = in<sum_product<double>>();
    const std::size_t c[] = {sums.smallest_holding(query)};
    if (c[0] >= tree_->cliques().size()) return false;
    return detail::saturating_multiply(relevant_cells(query), elimination_cell_cost * shared) < sums.cost_of_beliefs(c);
  }

  /// Whether eliminating each node's relevant part in turn is cheaper than the propagation to
  /// all their homes.
  [[nodiscard]] bool eliminating_each_pays(std::span<const variable_id> nodes) {
    if (!options_.prune) return false;
    std::size_t eliminating = 0;
    std::vector<std::size_t> homes;
    for (auto node : nodes) {
      const variable_id one[] = {node};
      eliminating = detail::saturating_add(eliminating, relevant_cells(one));
      homes.push_back(tree_->home(node));
    }
    std::sort(homes.begin(), homes.end());
    homes.erase(std::unique(homes.begin(), homes.end()), homes.end());
    return detail::saturating_multiply(eliminating, elimination_cell_cost) <
           in<sum_product<double>>().cost_of_beliefs(homes);
  }

  variable_elimination& elimination() {
    if (!elimination_)
      elimination_ =
          std::make_unique<variable_elimination>(*network_, variable_elimination_options{options_.heuristic});
    if (elimination_version_ != version_) {
      elimination_->set_evidence(evidence_);
      elimination_version_ = version_;
    }
    return *elimination_;
  }

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
