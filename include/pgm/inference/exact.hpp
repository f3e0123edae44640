#pragma once
/// \file
/// What the exact engines share: turning an unnormalized joint into a `posterior`, in
/// probabilities when P(evidence) is a normal double and in logarithms when it underflows, and
/// the same for the most probable explanation. Each engine supplies one computation generic
/// over the semiring; these run it in the semiring that fits.

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/graphical_model.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/inference/factor.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/inference/semiring.hpp"

namespace pgm::detail {

/// A column of a table whose sum is off 1 by more than this is read as the distribution it
/// rounds: divided by its sum. Published files print 4 to 6 digits, so their columns miss 1 by
/// up to 1e-6; inference assumes they sum to 1 (a barren node is left out because it sums to
/// 1), and reading each column as its distribution makes every engine, and leaving barren
/// nodes out, exact. Tables that sum to 1 within rounding of the last bits are used as they are.
inline constexpr double column_sum_slack = 1e-12;

/// The table of `node` as a factor over (its parents…, node) in semiring S, each column read as
/// a distribution (see column_sum_slack).
template <Semiring S>
[[nodiscard]] factor_of<S> table_factor(const bayesian_network& network, variable_id node) {
  const auto& stored = network.table(node);
  const auto densified = stored.is_sparse() ? std::optional(dense_for_factor(stored)) : std::nullopt;
  const auto& table = densified ? *densified : stored;
  const auto j = table.child_cardinality();
  std::vector<double> probabilities(table.values().begin(), table.values().end());
  for (std::size_t u = 0; u * j < probabilities.size(); ++u) {
    double sum = 0.0;
    for (std::size_t x = 0; x < j; ++x) sum += probabilities[u * j + x];
    if (std::abs(sum - 1.0) > column_sum_slack && sum > 0.0) {
      for (std::size_t x = 0; x < j; ++x) probabilities[u * j + x] /= sum;
    }
  }
  std::vector<typename S::value_type> values;
  values.reserve(probabilities.size());
  for (double p : probabilities) values.push_back(S::from_probability(p));
  auto scope = network.graph().parents(node);
  scope.push_back(node);
  std::vector<std::size_t> cards = table.parent_radix().radices();
  cards.push_back(j);
  return factor_of<S>(std::move(scope), std::move(cards), std::move(values));
}

/// The table of `node` as a factor in semiring S with the variables `fixed` gives a state (its
/// entry for a variable, −1 for one not fixed) reduced away, read column by column: a sparse table
/// is never made dense, so a family past pgm's dense limit answers once its evidence leaves few
/// cells (P(Y | 24 observed parents) is one column). Each column is read as table_factor reads
/// it. Throws table_too_large when the reduced factor itself is past the limit.
template <Semiring S>
[[nodiscard]] factor_of<S> reduced_table_factor(const bayesian_network& network, variable_id node,
                                                std::span<const std::ptrdiff_t> fixed) {
  const auto& table = network.table(node);
  const auto parents = network.graph().parents(node);
  const auto& radix = table.parent_radix();
  const auto j = table.child_cardinality();
  std::vector<variable_id> scope;
  std::vector<std::size_t> cards;
  std::vector<std::size_t> free_parents;  // positions among the parents
  std::vector<std::size_t> codes(parents.size(), 0);
  std::size_t cells = 1;
  for (std::size_t k = 0; k < parents.size(); ++k) {
    const auto state = fixed[parents[k].value()];
    if (state >= 0) {
      codes[k] = static_cast<std::size_t>(state);
      continue;
    }
    free_parents.push_back(k);
    scope.push_back(parents[k]);
    cards.push_back(radix.radix(k));
    cells = saturating_multiply(cells, radix.radix(k));
  }
  const auto child_state = fixed[node.value()];
  if (child_state < 0) {
    scope.push_back(node);
    cards.push_back(j);
    cells = saturating_multiply(cells, j);
  }
  if (cells > max_table_cells) {
    throw table_too_large("the table of '" + table.child().name() + "' with the evidence entered still has " +
                          std::to_string(cells) + " cells, more than pgm's limit of " +
                          std::to_string(max_table_cells) +
                          " (docs/limits.md): observe more of its parents, or use the sampling engines (lw, gibbs)");
  }
  std::vector<typename S::value_type> values;
  values.reserve(cells);
  std::vector<double> column(j);
  const auto configurations = cells / (child_state < 0 ? j : 1);
  for (std::size_t c = 0; c < configurations; ++c) {
    const auto stored = table.column(config_index(radix.encode(codes)));
    double sum = 0.0;
    for (std::size_t x = 0; x < j; ++x) sum += (column[x] = static_cast<double>(stored[x]));
    if (std::abs(sum - 1.0) > column_sum_slack && sum > 0.0) {
      for (auto& p : column) p /= sum;
    }
    if (child_state < 0) {
      for (const double p : column) values.push_back(S::from_probability(p));
    } else {
      values.push_back(S::from_probability(column[static_cast<std::size_t>(child_state)]));
    }
    for (std::size_t k = free_parents.size(); k-- > 0;) {  // the next configuration, the last fastest
      const auto at = free_parents[k];
      if (++codes[at] < radix.radix(at)) break;
      codes[at] = 0;
    }
  }
  return factor_of<S>(std::move(scope), std::move(cards), std::move(values));
}

/// Factor f of `model` in semiring S: a Bayesian network's table read as table_factor does, any
/// other model's factor with each value converted by S::from_probability.
template <Semiring S, GraphicalModel M>
[[nodiscard]] factor_of<S> model_factor(const M& model, std::size_t f) {
  if constexpr (std::same_as<M, bayesian_network>) {
    return table_factor<S>(model, index_at<variable_id>(f));
  } else {
    const auto& table = model.factor(f);
    std::vector<typename S::value_type> values;
    values.reserve(table.values().size());
    for (const double v : table.values()) values.push_back(S::from_probability(v));
    return factor_of<S>(std::vector<variable_id>(table.scope().begin(), table.scope().end()),
                        std::vector<std::size_t>(table.cardinalities().begin(), table.cardinalities().end()),
                        std::move(values));
  }
}

/// Whether a probability (or a Markov network's partition function) computed in doubles can be
/// trusted as it is: positive, finite and not subnormal (a subnormal total has lost digits, so
/// its ratios would be rough; an infinite one has lost them all).
[[nodiscard]] inline bool well_represented(double p) noexcept {
  return p >= std::numeric_limits<double>::min() && p <= std::numeric_limits<double>::max();
}

/// The variables `observed` does not fix, in id order.
template <GraphicalModel M>
[[nodiscard]] std::vector<variable_id> unobserved(const M& model, const evidence_set& observed) {
  std::vector<variable_id> ids;
  for (std::size_t i = 0; i < model.size(); ++i) {
    const variable_id id = index_at<variable_id>(i);
    if (!observed.fixes(id)) ids.push_back(id);
  }
  return ids;
}

/// Interventions are graph surgery on a DAG: refused for any other model.
template <GraphicalModel M>
void check_interventions_allowed(const evidence_set& observed, std::string_view engine) {
  if constexpr (!DirectedModel<M>) {
    if (!observed.intervened.empty()) {
      throw model_error("the engine '" + std::string(engine) + "' cannot intervene (do) on a " +
                        std::string(model_kind<M>()) + ": interventions cut a variable from its parents in a DAG");
    }
  }
}

/// A Markov network's answers computed from Π φ, divided by its partition function Z (given as
/// ln Z): P(evidence) = Z(e)/Z, P(x, e) = Π φ(x, e)/Z.
inline void divide_by_partition(posterior& result, double log_partition) {
  result.log_evidence_probability -= log_partition;
  result.evidence_probability = std::exp(result.log_evidence_probability);
}

inline void divide_by_partition(mpe_result& result, double log_partition) {
  result.log_joint_probability -= log_partition;
  result.joint_probability = std::exp(result.log_joint_probability);
}

/// P(query | evidence) from `joint_in<S>()`, an unnormalized joint over `query` computed in
/// semiring S: first with sum_product, then, when its total underflows, with log_sum_product.
/// Throws impossible_evidence when the evidence has probability 0.
template <GraphicalModel M, class JointIn>
[[nodiscard]] posterior exact_posterior(const M& network, std::span<const variable_id> query,
                                        const evidence_set& observed, std::string engine, JointIn&& joint_in) {
  posterior result;
  result.engine = std::move(engine);
  for (auto id : query) result.variables.push_back(network.variables()[id.value()]);
  auto joint = joint_in.template operator()<sum_product<double>>();
  const double total = joint.sum();
  if (well_represented(total)) {
    joint.normalize();
    result.table = std::move(joint);
    result.evidence_probability = total;
    result.log_evidence_probability = std::log(total);
    return result;
  }
  using log_space = log_sum_product<double>;
  auto logs = joint_in.template operator()<log_space>();
  const double log_total = total_of<log_space>(logs);
  if (log_total == log_space::zero()) throw_impossible(network, observed);
  std::vector<double> values;
  values.reserve(logs.size());
  for (double v : logs.values()) values.push_back(std::exp(v - log_total));
  result.table = factor(logs.scope(), logs.cardinalities(), std::move(values));
  result.evidence_probability = std::exp(log_total);
  result.log_evidence_probability = log_total;
  return result;
}

/// ln P(evidence) from `total_in<S>()`, the evidence's probability in semiring S; −∞ for
/// impossible evidence (a probability, not a condition, so 0 is an answer).
template <class TotalIn>
[[nodiscard]] double exact_log_evidence(TotalIn&& total_in) {
  const double total = total_in.template operator()<sum_product<double>>();
  if (well_represented(total)) return std::log(total);
  return total_in.template operator()<log_sum_product<double>>();
}

/// The most probable explanation from `maximum_in<S>()`, which returns (states of `variables`,
/// the largest value of the joint with the evidence) in a max semiring S; in probabilities
/// first, in logarithms when the maximum underflows. `log_evidence` is ln P(evidence); throws
/// impossible_evidence when it is −∞.
template <GraphicalModel M, class MaximumIn>
[[nodiscard]] mpe_result exact_mpe(const M& network, std::span<const variable_id> variables,
                                   const evidence_set& observed, double log_evidence, std::string engine,
                                   MaximumIn&& maximum_in) {
  if (log_evidence == -std::numeric_limits<double>::infinity()) throw_impossible(network, observed);
  mpe_result result;
  result.engine = std::move(engine);
  for (auto id : variables) result.variables.push_back(network.variables()[id.value()]);
  auto [states, value] = maximum_in.template operator()<max_product<double>>();
  double log_joint = 0.0;
  if (well_represented(value)) {
    log_joint = std::log(value);
  } else {
    auto logs = maximum_in.template operator()<log_max_product<double>>();
    states = std::move(logs.first);
    log_joint = logs.second;
  }
  for (auto s : states) result.states.push_back(index_at<state_index>(s));
  result.log_joint_probability = log_joint;
  result.joint_probability = std::exp(log_joint);
  result.log_probability = log_joint - log_evidence;
  result.probability = std::exp(result.log_probability);
  return result;
}

}  // namespace pgm::detail
