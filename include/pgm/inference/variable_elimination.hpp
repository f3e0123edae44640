#pragma once
/// \file
/// Exact inference by variable elimination, over any semiring: P(query | evidence) for any set
/// of query variables, P(evidence), the most probable explanation (max-product) and the most
/// probable state of a subset with the rest summed out (sums first, then maxima: marginal MAP).
///
/// Only the ancestors of the query and evidence variables take part (the others are barren: they
/// sum to one), the hard evidence is applied to each table before any product, soft evidence
/// enters as one factor per variable, and the remaining variables are eliminated greedily in
/// min-fill (default), min-degree or min-weight order (triangulation.hpp). Each query starts
/// afresh; for many queries on one network the junction tree engine keeps its work.
///
/// `variable_elimination` is the engine ("ve"); `query` and `joint_with_evidence` are the
/// one-call forms.

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <mutex>
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
#include "pgm/core/error.hpp"
#include "pgm/inference/exact.hpp"
#include "pgm/inference/factor.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/inference/semiring.hpp"
#include "pgm/inference/triangulation.hpp"

namespace pgm {

namespace detail {

/// Whether each node is an ancestor of (or one of) `targets`, in the network with the edges into
/// the intervened variables of `observed` cut.
[[nodiscard]] PGM_DECL std::vector<bool> ancestral_set(const bayesian_network& network,
                                                       std::span<const variable_id> targets,
                                                       const evidence_set& observed = {});

/// The ancestral set of `query` and every variable the evidence names.
[[nodiscard]] PGM_DECL std::vector<bool> relevant_set(const bayesian_network& network,
                                                      std::span<const variable_id> query, const evidence_set& observed);

/// A factor shared rather than copied: a network's tables stay where they are kept until the
/// evidence or an elimination makes a new one.
template <Semiring S>
using shared_factor = std::shared_ptr<const factor_of<S>>;

/// The factors of `model` that bear on `keep` and the evidence, in semiring S: each with the hard
/// evidence and interventions applied, and a factor per soft evidence. In a Bayesian network
/// only the ancestral set of `keep` and the evidence (the rest is barren), an intervened
/// variable's own table left out (the truncated factorisation); in another model every factor,
/// and a factor of ones over each variable in none (so that summing it out counts its states).
/// `eliminate` receives the variables taking part that are neither kept nor fixed.
/// `table_of(f)` gives factor f as a shared factor (made by model_factor<S>, or kept).
template <Semiring S, GraphicalModel M, class TableOf>
[[nodiscard]] std::vector<shared_factor<S>> evidence_factors(const M& model, std::span<const variable_id> keep,
                                                             const evidence_set& observed,
                                                             std::vector<variable_id>& eliminate, TableOf&& table_of) {
  std::vector<bool> relevant;
  if constexpr (DirectedModel<M>) {
    relevant = relevant_set(model, keep, observed);
  } else {
    relevant.assign(model.size(), true);
  }
  std::vector<std::ptrdiff_t> fixed(model.size(), -1);
  for (const auto& o : observed.hard) fixed[o.variable.value()] = static_cast<std::ptrdiff_t>(o.state.value());
  for (const auto& o : observed.intervened) fixed[o.variable.value()] = static_cast<std::ptrdiff_t>(o.state.value());

  std::vector<shared_factor<S>> factors;
  std::vector<bool> covered(model.size(), DirectedModel<M>);
  for (std::size_t f = 0; f < model.factor_count(); ++f) {
    if constexpr (DirectedModel<M>) {
      const variable_id node = index_at<variable_id>(f);
      if (!relevant[f] || observed.intervenes(node)) continue;
    }
    if constexpr (DirectedModel<M>) {
      if (model.tables()[f].is_sparse()) {
        // Reduced as it is read: a sparse family past the dense limit is never made whole.
        const variable_id node = index_at<variable_id>(f);
        auto reduced = reduced_table_factor<S>(model, node, fixed);
        for (auto id : model.factor_scope(f)) covered[id.value()] = true;
        factors.push_back(std::make_shared<const factor_of<S>>(std::move(reduced)));
        continue;
      }
    }
    shared_factor<S> table = table_of(f);
    const auto scope = table->scope();  // a copy: reducing replaces the table
    for (auto id : scope) {
      covered[id.value()] = true;
      if (fixed[id.value()] >= 0) {
        table = std::make_shared<const factor_of<S>>(table->reduce(id, static_cast<std::size_t>(fixed[id.value()])));
      }
    }
    factors.push_back(std::move(table));
  }
  eliminate.clear();
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (!relevant[i] || fixed[i] >= 0) continue;
    const variable_id node = index_at<variable_id>(i);
    if (!covered[i]) {
      const auto card = model.variables()[i].cardinality();
      factors.push_back(std::make_shared<const factor_of<S>>(std::vector<variable_id>{node},
                                                             std::vector<std::size_t>{card},
                                                             std::vector<typename S::value_type>(card, S::one())));
    }
    if (std::find(keep.begin(), keep.end(), node) == keep.end()) eliminate.push_back(node);
  }
  for (const auto& l : observed.soft) {
    std::vector<typename S::value_type> weights;
    for (double w : l.weights) weights.push_back(S::from_probability(w));
    factors.push_back(std::make_shared<const factor_of<S>>(
        std::vector<variable_id>{l.variable}, std::vector<std::size_t>{l.weights.size()}, std::move(weights)));
  }
  return factors;
}

/// Eliminates `variable` from `factors` with S's ⊕; returns the product it eliminated from.
template <Semiring S>
shared_factor<S> eliminate_one(std::vector<shared_factor<S>>& factors, variable_id variable) {
  std::vector<shared_factor<S>> with;
  std::vector<shared_factor<S>> rest;
  rest.reserve(factors.size());
  for (auto& f : factors) (f->contains(variable) ? with : rest).push_back(std::move(f));
  shared_factor<S> product = with.empty() ? std::make_shared<const factor_of<S>>(unit<S>()) : with.front();
  for (std::size_t k = 1; k < with.size(); ++k) {
    product = std::make_shared<const factor_of<S>>(combine<S>(*product, *with[k]));
  }
  rest.push_back(std::make_shared<const factor_of<S>>(eliminate<S>(*product, variable)));
  factors = std::move(rest);
  return product;
}

/// The product of `factors` as one factor over `scope` (with these cardinalities), in that order:
/// starting from the one-valued factor over `scope` puts the result in its order.
template <Semiring S>
[[nodiscard]] factor_of<S> product_over(const std::vector<shared_factor<S>>& factors,
                                        std::span<const variable_id> scope, std::span<const std::size_t> cards) {
  std::size_t cells = 1;
  for (auto c : cards) cells *= c;
  auto result = factor_of<S>(std::vector<variable_id>(scope.begin(), scope.end()),
                             std::vector<std::size_t>(cards.begin(), cards.end()),
                             std::vector<typename S::value_type>(cells, S::one()));
  for (const auto& f : factors) result = combine<S>(result, *f);
  return result;
}

/// The product of `factors` over `scope`, the cardinalities from `network`.
template <Semiring S, GraphicalModel M>
[[nodiscard]] factor_of<S> product_over(const std::vector<shared_factor<S>>& factors,
                                        std::span<const variable_id> scope, const M& network) {
  std::vector<std::size_t> cards;
  for (auto id : scope) cards.push_back(network.variables()[id.value()].cardinality());
  return product_over<S>(factors, scope, cards);
}

}  // namespace detail

namespace detail {

template <std::floating_point T>
const basic_factor<T>& factor_at(const basic_factor<T>& f) {
  return f;
}
template <std::floating_point T>
const basic_factor<T>& factor_at(const std::shared_ptr<const basic_factor<T>>& f) {
  return *f;
}

}  // namespace detail

/// A greedy elimination order of `eliminate` for the interaction graph of `factors` (factors or
/// shared factors).
template <class Factor>
[[nodiscard]] std::vector<variable_id> elimination_order(
    const std::vector<Factor>& factors, std::vector<variable_id> eliminate,
    elimination_heuristic heuristic = elimination_heuristic::min_fill) {
  std::vector<variable_id> nodes;
  for (const auto& f : factors) {
    const auto& scope = detail::factor_at(f).scope();
    nodes.insert(nodes.end(), scope.begin(), scope.end());
  }
  nodes.insert(nodes.end(), eliminate.begin(), eliminate.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  auto local = [&](variable_id id) {
    return static_cast<std::size_t>(std::lower_bound(nodes.begin(), nodes.end(), id) - nodes.begin());
  };
  interaction_graph graph(nodes.size());
  std::vector<std::size_t> cards(nodes.size(), 1);
  for (const auto& held : factors) {
    const auto& f = detail::factor_at(held);
    for (std::size_t a = 0; a < f.scope().size(); ++a) {
      cards[local(f.scope()[a])] = f.cardinalities()[a];
      for (std::size_t b = a + 1; b < f.scope().size(); ++b) {
        const auto u = local(f.scope()[a]);
        const auto w = local(f.scope()[b]);
        if (!boost::edge(u, w, graph).second) boost::add_edge(u, w, graph);
      }
    }
  }
  std::unique_ptr<bool[]> flags(new bool[nodes.size()]());
  for (auto id : eliminate) flags[local(id)] = true;
  const auto order =
      greedy_elimination(graph, cards, heuristic, std::span<const bool>(flags.get(), nodes.size())).order;
  std::vector<variable_id> result;
  result.reserve(order.size());
  for (auto v : order) result.push_back(nodes[v]);
  return result;
}

/// The unnormalized joint of `query` (in that order) with the evidence, in semiring S; its
/// ⊕-total is P(evidence) for sum-product. Query and evidence variables must be distinct.
template <Semiring S, GraphicalModel M, class TableOf>
[[nodiscard]] factor_of<S> joint_in(const M& network, std::span<const variable_id> query, const evidence_set& observed,
                                    elimination_heuristic heuristic, TableOf&& table_of) {
  std::vector<variable_id> eliminate;
  auto factors = detail::evidence_factors<S>(network, query, observed, eliminate, table_of);
  for (auto variable : elimination_order(factors, std::move(eliminate), heuristic)) {
    static_cast<void>(detail::eliminate_one<S>(factors, variable));
  }
  return detail::product_over<S>(factors, query, network);
}

template <Semiring S, GraphicalModel M>
[[nodiscard]] factor_of<S> joint_in(const M& network, std::span<const variable_id> query, const evidence_set& observed,
                                    elimination_heuristic heuristic = elimination_heuristic::min_fill) {
  return joint_in<S>(network, query, observed, heuristic, [&](std::size_t f) {
    return std::make_shared<const factor_of<S>>(detail::model_factor<S>(network, f));
  });
}

/// The unnormalized P(query, evidence) over `query` in the order given; its sum is P(evidence).
/// Query and evidence variables must be distinct network ids (checked by the named overload).
[[nodiscard]] PGM_DECL factor joint_with_evidence(const bayesian_network& network, std::span<const variable_id> query,
                                                  std::span<const observation> observed,
                                                  elimination_heuristic heuristic = elimination_heuristic::min_fill);

/// The most probable joint state of `variables` with the rest summed out (marginal MAP; the
/// most probable explanation when `variables` are all the unobserved ones), in the max
/// semiring Max, with Max's sum counterpart for the summing. Returns the states and the value
/// max P(variables, evidence). Ties: the lowest state of each variable, settled from the last
/// eliminated back.
template <Semiring Max, GraphicalModel M, class TableOf>
requires(Max::idempotent) [[nodiscard]] std::pair<std::vector<std::size_t>, typename Max::value_type> maximum_in(
    const M& network, std::span<const variable_id> variables, const evidence_set& observed,
    elimination_heuristic heuristic, TableOf&& table_of) {
  // The sums run in the same representation as the maxima: probabilities or logarithms.
  using Sum = std::conditional_t<stores_logarithms<Max>, log_sum_product<typename Max::value_type>,
                                 sum_product<typename Max::value_type>>;
  std::vector<variable_id> summed;
  auto factors = detail::evidence_factors<Max>(network, variables, observed, summed, table_of);
  for (auto variable : elimination_order(factors, std::move(summed), heuristic)) {
    static_cast<void>(detail::eliminate_one<Sum>(factors, variable));
  }
  const std::vector<variable_id> maximized(variables.begin(), variables.end());
  const auto order = elimination_order(factors, maximized, heuristic);
  std::vector<detail::shared_factor<Max>> buckets;
  buckets.reserve(order.size());
  for (auto variable : order) buckets.push_back(detail::eliminate_one<Max>(factors, variable));
  auto value = Max::one();
  for (const auto& f : factors) value = Max::times(value, total_of<Max>(*f));

  std::vector<std::size_t> state_of(network.size(), 0);
  for (std::size_t k = order.size(); k-- > 0;) {
    auto bucket = *buckets[k];
    const auto scope = bucket.scope();
    for (auto id : scope) {
      if (id != order[k]) bucket = bucket.reduce(id, state_of[id.value()]);
    }
    const auto values = bucket.values();
    state_of[order[k].value()] =
        static_cast<std::size_t>(std::max_element(values.begin(), values.end()) - values.begin());
  }
  std::vector<std::size_t> states;
  states.reserve(variables.size());
  for (auto id : variables) states.push_back(state_of[id.value()]);
  return {std::move(states), value};
}

template <Semiring Max, GraphicalModel M>
requires(Max::idempotent) [[nodiscard]] std::pair<std::vector<std::size_t>, typename Max::value_type> maximum_in(
    const M& network, std::span<const variable_id> variables, const evidence_set& observed,
    elimination_heuristic heuristic = elimination_heuristic::min_fill) {
  return maximum_in<Max>(network, variables, observed, heuristic, [&](std::size_t f) {
    return std::make_shared<const factor_of<Max>>(detail::model_factor<Max>(network, f));
  });
}

struct variable_elimination_options {
  elimination_heuristic heuristic = elimination_heuristic::min_fill;
};

/// The variable elimination engine over any model: holds the model and the evidence; every
/// query eliminates afresh. It owns or shares the model: built from a model it keeps a copy,
/// from a shared_ptr it shares it (pgm::borrowed lends one without a copy). Its const members
/// (joint, mpe, P(evidence)) may be called from several threads at once; set_evidence may not
/// run beside them.
///
/// In a Markov network P(evidence) is Z(e)/Z and a joint probability is Π φ / Z: the engine
/// computes ln Z once, on first need. Interventions need a DAG: only a directed model takes them.
template <GraphicalModel M = bayesian_network>
class variable_elimination {
 public:
  using model_type = M;

  explicit variable_elimination(M model, variable_elimination_options options = {})
      : variable_elimination(std::make_shared<const M>(std::move(model)), options) {}
  explicit variable_elimination(std::shared_ptr<const M> model, variable_elimination_options options = {})
      : model_(std::move(model)), options_(options) {
    if (!model_) throw model_error("variable elimination was given no model");
  }

  static constexpr bool handles_interventions = DirectedModel<M>;
  [[nodiscard]] std::string_view name() const noexcept { return "ve"; }
  [[nodiscard]] const M& model() const noexcept { return *model_; }
  [[nodiscard]] const M& network() const noexcept requires DirectedModel<M> { return *model_; }
  [[nodiscard]] const evidence_set& evidence() const noexcept { return evidence_; }
  void set_evidence(evidence_set observed) {
    detail::check_interventions_allowed<M>(observed, name());
    evidence_ = std::move(observed);
  }

  /// P(query | evidence), `query` in the order wanted.
  [[nodiscard]] posterior joint(std::span<const variable_id> query) const {
    auto result = detail::exact_posterior(*model_, query, evidence_, std::string(name()), [&]<Semiring S>() {
      return joint_in<S>(*model_, query, evidence_, options_.heuristic, tables<S>());
    });
    if constexpr (!DirectedModel<M>) detail::divide_by_partition(result, log_partition());
    return result;
  }

  [[nodiscard]] double log_probability_of_evidence() const {
    if constexpr (DirectedModel<M>) {
      return log_total(evidence_);
    } else {
      return log_total(evidence_) - log_partition();
    }
  }

  /// The most probable joint state of `variables` (every unobserved variable when empty) given
  /// the evidence, the others summed out.
  [[nodiscard]] mpe_result mpe(std::span<const variable_id> variables = {}) const {
    const auto chosen = variables.empty() ? detail::unobserved(*model_, evidence_)
                                          : std::vector<variable_id>(variables.begin(), variables.end());
    auto result = detail::exact_mpe(
        *model_, chosen, evidence_, log_total(evidence_), std::string(name()),
        [&]<Semiring S>() { return maximum_in<S>(*model_, chosen, evidence_, options_.heuristic, tables<S>()); });
    if constexpr (!DirectedModel<M>) detail::divide_by_partition(result, log_partition());
    return result;
  }

  /// ln Z, the logarithm of the model's partition function without evidence (0 for a Bayesian
  /// network), computed once.
  [[nodiscard]] double log_partition() const {
    if constexpr (DirectedModel<M>) {
      return 0.0;
    } else {
      {
        const std::lock_guard lock(*tables_mutex_);
        if (*log_partition_) return **log_partition_;
      }
      const double value = log_total({});
      const std::lock_guard lock(*tables_mutex_);
      *log_partition_ = value;
      return value;
    }
  }

 private:
  /// ln of the ⊕-total of the model's factors with `observed` entered: ln P(e) in a Bayesian
  /// network, ln Z(e) in another model.
  [[nodiscard]] double log_total(const evidence_set& observed) const {
    return detail::exact_log_evidence(
        [&]<Semiring S>() { return total_of<S>(joint_in<S>(*model_, {}, observed, options_.heuristic, tables<S>())); });
  }

  /// Every factor in S, made once per semiring on first use, under a lock: two threads may
  /// query one engine through its const members. A sparse table is not kept: each query reads
  /// it reduced by its evidence (detail::evidence_factors).
  template <Semiring S>
  [[nodiscard]] auto tables() const {
    const std::lock_guard lock(*tables_mutex_);
    auto& kept = std::get<kept_tables<S>>(*tables_).factors;
    if (kept.empty()) {
      kept.resize(model_->factor_count());
      for (std::size_t f = 0; f < kept.size(); ++f) {
        if constexpr (DirectedModel<M>) {
          if (model_->tables()[f].is_sparse()) continue;  // read reduced by each query's evidence
        }
        kept[f] = std::make_shared<const factor_of<S>>(detail::model_factor<S>(*model_, f));
      }
    }
    return [&kept](std::size_t f) { return kept[f]; };
  }

  // S is a Semiring; left unconstrained, as clang 14 crashes checking a constrained member
  // template of a class template named in the class's own body.
  template <class S>
  struct kept_tables {
    std::vector<detail::shared_factor<S>> factors;
  };
  using all_tables = std::tuple<kept_tables<sum_product<double>>, kept_tables<log_sum_product<double>>,
                                kept_tables<max_product<double>>, kept_tables<log_max_product<double>>>;

  std::shared_ptr<const M> model_;
  variable_elimination_options options_;
  evidence_set evidence_;
  /// Shared by copies, as the model is: they hold the same factors and the same ln Z.
  std::shared_ptr<all_tables> tables_ = std::make_shared<all_tables>();
  std::shared_ptr<std::optional<double>> log_partition_ = std::make_shared<std::optional<double>>();
  std::shared_ptr<std::mutex> tables_mutex_ = std::make_shared<std::mutex>();
};

template <class M>
variable_elimination(std::shared_ptr<M>, variable_elimination_options = {})
    -> variable_elimination<std::remove_const_t<M>>;

#if defined(PGM_SEPARATE_COMPILATION)
extern template class variable_elimination<bayesian_network>;
extern template class variable_elimination<markov_network>;
#endif

/// P(query | evidence) by name. Throws model_error for an unknown variable or state, a
/// variable asked twice or both asked and observed; impossible_evidence when P(evidence) = 0.
[[nodiscard]] PGM_DECL posterior query(const bayesian_network& network, std::span<const std::string> variables,
                                       const evidence& observed = {},
                                       elimination_heuristic heuristic = elimination_heuristic::min_fill);

[[nodiscard]] PGM_DECL posterior query(const bayesian_network& network, std::initializer_list<std::string> variables,
                                       const evidence& observed = {},
                                       elimination_heuristic heuristic = elimination_heuristic::min_fill);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/inference/impl/variable_elimination.ipp"
#endif
