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
/// repeated queries propagate. A Markov network has no barren part: its queries propagate.
///
/// Any model: the engine owns or shares it, as variable_elimination does (pgm::borrowed lends
/// one). Unlike variable_elimination, it is not for two threads at once: its queries keep
/// messages.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
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

template <GraphicalModel M = bayesian_network>
class junction_tree_engine {
 public:
  using model_type = M;

  /// Compiles `model` (a copy). Throws table_too_large when the tree exceeds options.max_cells.
  explicit junction_tree_engine(M model, const junction_tree_options& options = {})
      : junction_tree_engine(std::make_shared<const M>(std::move(model)), options) {}
  explicit junction_tree_engine(std::shared_ptr<const M> model, const junction_tree_options& options = {})
      : model_(checked(std::move(model))),
        tree_(std::make_shared<const junction_tree>(*model_, options)),
        options_(options) {}

  /// An engine of the same model and compiled tree without evidence or kept messages: its
  /// answers have the bits a newly compiled engine's have. Kept messages make an answer's last
  /// bit depend on what was asked before (Hugin's division where a clique has many neighbours),
  /// so a worker whose results must not depend on its history starts from one of these.
  [[nodiscard]] junction_tree_engine fresh() const { return junction_tree_engine(model_, tree_, options_); }

  static constexpr bool handles_interventions = DirectedModel<M>;
  [[nodiscard]] std::string_view name() const noexcept { return "jt"; }
  [[nodiscard]] const M& model() const noexcept { return *model_; }
  [[nodiscard]] const M& network() const noexcept requires DirectedModel<M> { return *model_; }
  [[nodiscard]] const junction_tree& tree() const noexcept { return *tree_; }
  [[nodiscard]] const evidence_set& evidence() const noexcept { return evidence_; }

  /// Replaces the evidence: hard and soft, entered or retracted, nothing recompiled.
  void set_evidence(evidence_set observed) {
    detail::check_interventions_allowed<M>(observed, name());
    evidence_ = std::move(observed);
    ++version_;
    queries_since_evidence_ = 0;
  }

  [[nodiscard]] posterior joint(std::span<const variable_id> query);

  /// The marginal of each of `nodes`: after the first, each costs a fold of a kept belief.
  [[nodiscard]] std::vector<posterior> marginals(std::span<const variable_id> nodes);

  /// P(scope | evidence) of each of `scopes`, normalized, in the order of its ids (the last
  /// fastest): a scope within one clique (a family of a Bayesian network) costs a fold of a
  /// belief computed once for all of them, as EM's E-step asks; any other, a joint().
  [[nodiscard]] std::vector<std::vector<double>> joints(std::span<const std::vector<variable_id>> scopes);

  [[nodiscard]] double log_probability_of_evidence() { return log_total() - log_partition(); }

  /// ln Z, the logarithm of the model's partition function without evidence (0 for a Bayesian
  /// network), propagated once on first need.
  [[nodiscard]] double log_partition() {
    if constexpr (DirectedModel<M>) {
      return 0.0;
    } else {
      if (!log_partition_) {
        log_partition_ =
            detail::exact_log_evidence([&]<Semiring S>() { return propagation<S>(tree_, *model_).total(); });
      }
      return *log_partition_;
    }
  }

  /// The most probable joint state of `variables` (every unobserved variable when empty).
  [[nodiscard]] mpe_result mpe(std::span<const variable_id> variables = {});

 private:
  /// Variable elimination costs more per cell than propagation (it builds its tables afresh,
  /// and its product tables outgrow the network's): 24 puts the choice where the single-query
  /// benchmark of bench/inference_bench.cpp is fastest on every published network it runs
  /// (alarm and hailfinder propagate, insurance and pathfinder eliminate).
  static constexpr std::size_t elimination_cell_cost = 24;

  junction_tree_engine(std::shared_ptr<const M> model, std::shared_ptr<const junction_tree> tree,
                       const junction_tree_options& options)
      : model_(std::move(model)), tree_(std::move(tree)), options_(options) {}

  static std::shared_ptr<const M> checked(std::shared_ptr<const M> model) {
    if (!model) throw model_error("the junction tree engine was given no model");
    return model;
  }

  /// ln P(e) in a Bayesian network, ln Z(e) in another model.
  [[nodiscard]] double log_total() {
    return detail::exact_log_evidence([&]<Semiring S>() { return in<S>().total(); });
  }

  /// The cells of the tables in the relevant part of a query: the ancestors of the query and
  /// evidence variables (the rest is barren).
  [[nodiscard]] std::size_t relevant_cells(std::span<const variable_id> query) const;

  /// Whether eliminating the query's relevant part is cheaper than the messages it needs.
  [[nodiscard]] bool eliminating_pays(std::span<const variable_id> query);

  /// Whether eliminating each node's relevant part in turn is cheaper than the propagation to
  /// all their homes.
  [[nodiscard]] bool eliminating_each_pays(std::span<const variable_id> nodes);

  /// What eliminating one node's relevant part costs, in about the nanoseconds a propagation
  /// spends on a cell: a fixed cost per relevant variable (its elimination order and tables),
  /// and its cells, which are about the tree's cliques cut down to the relevant variables that
  /// are not observed (eliminating's tables outgrow the network's where the relevant part is
  /// wide, as in pigs, where most of the network is an ancestor of most variables). Fitted to
  /// the single variable elimination of every variable of the published networks under ten
  /// observations (alarm 25 relevant variables and 15 µs; pigs 55 and 62 µs; water 22 variables
  /// and 68,000 cells, 131 µs).
  [[nodiscard]] std::size_t elimination_work(variable_id node) const;
  static constexpr std::size_t elimination_variable_work = 550;
  static constexpr std::size_t elimination_cell_work = 4;

  variable_elimination<M>& elimination();

  // S is a Semiring; left unconstrained, as clang 14 crashes checking a constrained member
  // template of a class template named in the class's own body.
  template <class S>
  struct slot {
    std::unique_ptr<propagation<S>> engine;
    std::size_t version = 0;
  };

  /// The propagation in S, made on first use, with the current evidence.
  template <Semiring S>
  propagation<S>& in() {
    auto& s = std::get<slot<S>>(propagations_);
    if (!s.engine) s.engine = std::make_unique<propagation<S>>(tree_, *model_);
    if (s.version != version_) {
      s.engine->set_evidence(evidence_);
      s.version = version_;
    }
    return *s.engine;
  }

  std::shared_ptr<const M> model_;
  std::shared_ptr<const junction_tree> tree_;
  junction_tree_options options_;
  evidence_set evidence_;
  std::size_t version_ = 1;
  std::size_t queries_since_evidence_ = 0;
  std::unique_ptr<variable_elimination<M>> elimination_;
  std::size_t elimination_version_ = 0;
  std::optional<double> log_partition_;
  std::tuple<slot<sum_product<double>>, slot<log_sum_product<double>>, slot<max_product<double>>,
             slot<log_max_product<double>>>
      propagations_;
};

template <class M>
junction_tree_engine(std::shared_ptr<M>, const junction_tree_options& = {})
    -> junction_tree_engine<std::remove_const_t<M>>;

template <GraphicalModel M>
posterior junction_tree_engine<M>::joint(std::span<const variable_id> query) {
  if (eliminating_pays(query)) {
    auto result = elimination().joint(query);
    result.engine = std::string(name());
    return result;
  }
  auto result = detail::exact_posterior(*model_, query, evidence_, std::string(name()),
                                        [&]<Semiring S>() { return in<S>().joint(query); });
  if constexpr (!DirectedModel<M>) detail::divide_by_partition(result, log_partition());
  return result;
}

template <GraphicalModel M>
std::vector<std::vector<double>> junction_tree_engine<M>::joints(std::span<const std::vector<variable_id>> scopes) {
  auto tables = in<sum_product<double>>().joints_within_cliques(scopes);
  for (std::size_t i = 0; i < scopes.size(); ++i) {
    double total = 0.0;
    for (double v : tables[i]) total += v;
    if (tables[i].empty() || !detail::well_represented(total)) {
      // Across cliques, or underflow: this one from joint(), which answers in logarithms then.
      const auto answer = joint(scopes[i]);
      const auto values = answer.table.values();
      tables[i].assign(values.begin(), values.end());
      continue;
    }
    for (double& v : tables[i]) v /= total;
  }
  return tables;
}

template <GraphicalModel M>
std::vector<posterior> junction_tree_engine<M>::marginals(std::span<const variable_id> nodes) {
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
  const double ln_z = log_partition();
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
    p.variables.push_back(model_->variables()[nodes[i].value()]);
    p.table = factor({nodes[i]}, {sums[i].size()}, sums[i]);
    p.table.normalize();
    p.evidence_probability = total;
    p.log_evidence_probability = std::log(total);
    if constexpr (!DirectedModel<M>) detail::divide_by_partition(p, ln_z);
    result.push_back(std::move(p));
  }
  return result;
}

template <GraphicalModel M>
mpe_result junction_tree_engine<M>::mpe(std::span<const variable_id> variables) {
  const auto unobserved = detail::unobserved(*model_, evidence_);
  std::vector<variable_id> chosen(variables.begin(), variables.end());
  std::sort(chosen.begin(), chosen.end());
  if (!variables.empty() && chosen != unobserved) {
    auto result = elimination().mpe(variables);
    result.engine = std::string(name());
    return result;
  }
  auto result = detail::exact_mpe(*model_, unobserved, evidence_, log_total(), std::string(name()), [&]<Semiring S>() {
    auto best = in<S>().maximize();
    std::vector<std::size_t> states;
    for (auto id : unobserved) states.push_back(best.states[id.value()]);
    return std::pair{std::move(states), best.value};
  });
  if constexpr (!DirectedModel<M>) detail::divide_by_partition(result, log_partition());
  return result;
}

template <GraphicalModel M>
std::size_t junction_tree_engine<M>::relevant_cells(std::span<const variable_id> query) const {
  if constexpr (DirectedModel<M>) {
    const auto relevant = detail::relevant_set(*model_, query, evidence_);
    std::size_t cells = 0;
    for (std::size_t i = 0; i < model_->size(); ++i) {
      if (relevant[i]) cells += model_->tables()[i].size();
    }
    return cells;
  } else {
    return 0;  // never asked: a model without barren parts always propagates
  }
}

template <GraphicalModel M>
bool junction_tree_engine<M>::eliminating_pays(std::span<const variable_id> query) {
  const auto shared = ++queries_since_evidence_;
  if constexpr (!DirectedModel<M>) {
    return false;
  } else {
    if (!options_.prune) return false;
    auto& sums = in<sum_product<double>>();
    const std::size_t c[] = {sums.smallest_holding(query)};
    if (c[0] >= tree_->cliques().size()) return false;
    return detail::saturating_multiply(relevant_cells(query), elimination_cell_cost * shared) < sums.cost_of_beliefs(c);
  }
}

template <GraphicalModel M>
bool junction_tree_engine<M>::eliminating_each_pays(std::span<const variable_id> nodes) {
  if constexpr (!DirectedModel<M>) {
    return false;
  } else {
    if (!options_.prune) return false;
    std::vector<std::size_t> homes;
    for (auto node : nodes) homes.push_back(tree_->home(node));
    std::sort(homes.begin(), homes.end());
    homes.erase(std::unique(homes.begin(), homes.end()), homes.end());
    auto& sums = in<sum_product<double>>();
    const auto propagating = homes.size() > 1 ? sums.cost_of_all_beliefs() : sums.cost_of_beliefs(homes);
    // Estimated from at most 32 of the nodes, evenly spread, and only until it passes the
    // propagation: each estimate walks the network (about a microsecond on alarm), and pigs' 431
    // would cost a fifth of the propagation they decide against.
    const std::size_t stride = std::max<std::size_t>(1, nodes.size() / 32);
    const double each_counts_for = static_cast<double>(stride);
    double eliminating = 0.0;
    for (std::size_t i = 0; i < nodes.size(); i += stride) {
      eliminating += each_counts_for * static_cast<double>(elimination_work(nodes[i]));
      if (eliminating >= static_cast<double>(propagating)) return false;
    }
    return true;
  }
}

template <GraphicalModel M>
std::size_t junction_tree_engine<M>::elimination_work(variable_id node) const {
  if constexpr (DirectedModel<M>) {
    const variable_id one[] = {node};
    const auto relevant = detail::relevant_set(*model_, one, evidence_);
    std::size_t variables = 0;
    for (std::size_t i = 0; i < model_->size(); ++i) variables += relevant[i] ? 1 : 0;
    std::vector<char> eliminated(relevant.begin(), relevant.end());  // relevant and not observed
    for (const auto& o : evidence_.hard) eliminated[o.variable.value()] = 0;
    for (const auto& o : evidence_.intervened) eliminated[o.variable.value()] = 0;
    std::size_t cells = 0;
    for (const auto& clique : tree_->cliques()) {
      std::size_t cut = 1;
      bool any = false;
      for (auto v : clique.variables) {
        if (!eliminated[v.value()]) continue;
        any = true;
        cut = detail::saturating_multiply(cut, tree_->cardinality(v));
      }
      if (any) cells = detail::saturating_add(cells, cut);
    }
    return detail::saturating_add(variables * elimination_variable_work,
                                  detail::saturating_multiply(cells, elimination_cell_work));
  } else {
    return 0;  // never asked: a model without barren parts always propagates
  }
}

template <GraphicalModel M>
variable_elimination<M>& junction_tree_engine<M>::elimination() {
  if (!elimination_) {
    elimination_ = std::make_unique<variable_elimination<M>>(model_, variable_elimination_options{options_.heuristic});
  }
  if (elimination_version_ != version_) {
    elimination_->set_evidence(evidence_);
    elimination_version_ = version_;
  }
  return *elimination_;
}

#if defined(PGM_SEPARATE_COMPILATION)
extern template class junction_tree_engine<bayesian_network>;
extern template class junction_tree_engine<markov_network>;
#endif

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/inference/impl/junction_tree_engine.ipp"
#endif
