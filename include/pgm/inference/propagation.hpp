#pragma once
/// \file
/// `propagation<S>`: Shafer–Shenoy message passing over a compiled `junction_tree`, in any
/// semiring S (sums for marginals, maxima for the most probable explanation, their logarithms
/// where probabilities underflow).
///
/// Why Shafer–Shenoy rather than Hugin: it never divides, so every semiring works unchanged
/// (Hugin's division has no counterpart for max in log space without care for −∞ − −∞), and its
/// messages are separate values that can be kept and reused. Each message is computed on demand
/// and cached:
///   - a message whose source side holds no evidence is the same under any evidence: it is
///     computed once, the first time some query needs it, and kept for the life of the object
///     (this is where barren parts of the network cost nothing, as lazy propagation prunes them);
///   - a message with evidence on its source side is kept until evidence there changes.
/// So a query computes only the messages toward its clique that changed, one `marginals()` call
/// is the two-pass propagation, and entering or retracting evidence recompiles nothing.

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include "pgm/core/assert.hpp"
#include "pgm/core/bayesian_network.hpp"
#include "pgm/inference/exact.hpp"
#include "pgm/inference/factor.hpp"
#include "pgm/inference/junction_tree.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/inference/semiring.hpp"
#include "pgm/inference/table_walk.hpp"
#include "pgm/inference/triangulation.hpp"
#include "pgm/inference/variable_elimination.hpp"

namespace pgm {

template <Semiring S>
class propagation {
 public:
  using value_type = typename S::value_type;

  /// Propagation over `tree`, compiled from `model`, whose factors it keeps (in S).
  template <GraphicalModel M>
  propagation(std::shared_ptr<const junction_tree> tree, const M& model)
      : propagation(std::move(tree), factors_in(model)) {}

  /// Propagation over `tree` of these factors, factor f in the tree's factor_clique(f). An
  /// intervention do(X = x) takes out factor X (a Bayesian network's numbering: node i's table
  /// is factor i).
  propagation(std::shared_ptr<const junction_tree> tree, std::vector<factor_of<S>> factors)
      : tree_(std::move(tree)), factors_(std::move(factors)) {
    PGM_ASSERT(factors_.size() == tree_->factor_count(), "one factor per factor the tree was compiled for");
    const auto& cliques = tree_->cliques();
    base_.resize(cliques.size());
    families_.resize(cliques.size());
    for (std::size_t f = 0; f < factors_.size(); ++f) families_[tree_->factor_clique(f)].push_back(f);
    for (std::size_t c = 0; c < cliques.size(); ++c) {
      base_[c].assign(cliques[c].cells, S::one());
      multiply_families(c, [](std::size_t) { return false; });
    }
    prior_.resize(2 * tree_->edges().size());
    working_.resize(2 * tree_->edges().size());
    potential_version_.assign(cliques.size(), 0);
    group_folds_.resize(cliques.size());
    group_of_.resize(cliques.size());
    for (std::size_t c = 0; c < cliques.size(); ++c) {
      group_folds_[c].resize(cliques[c].groups.size());
      group_of_[c].resize(cliques[c].edges.size());
      for (std::size_t g = 0; g < cliques[c].groups.size(); ++g) {
        for (auto k : cliques[c].groups[g]) group_of_[c][k] = g;
      }
    }
    evidence_at_.resize(cliques.size());
    cut_at_.resize(cliques.size());
    with_evidence_.resize(cliques.size());
  }

  [[nodiscard]] const junction_tree& tree() const noexcept { return *tree_; }

  /// Replaces the evidence and interventions; only the cliques whose evidence changed lose their
  /// messages. do(X = x) takes X's table out of its family's clique and fixes X there at x, in
  /// that clique's base potential: the kept prior messages then hold for the interventions, so
  /// queries under one set of interventions cost what they cost on the mutilated network.
  void set_evidence(const evidence_set& observed) {
    bool changed = false;
    if (!observed.intervened.empty() || intervened_) set_interventions(observed.intervened, changed);
    // Only the cliques that hold evidence now or held it before are compared: a query on pigs
    // (441 cliques) sets evidence on one to three of them.
    std::vector<std::pair<std::size_t, local_evidence>> next;
    for (const auto& o : observed.hard) {
      std::vector<value_type> weights(tree_->cardinality(o.variable), S::zero());
      weights[o.state.value()] = S::one();
      next.push_back({tree_->home(o.variable), {o.variable, std::move(weights)}});
    }
    for (const auto& l : observed.soft) {
      std::vector<value_type> weights;
      for (double w : l.weights) weights.push_back(S::from_probability(w));
      next.push_back({tree_->home(l.variable), {l.variable, std::move(weights)}});
    }
    std::sort(next.begin(), next.end(), [](const auto& a, const auto& b) {
      return std::tie(a.first, a.second.variable) < std::tie(b.first, b.second.variable);
    });
    std::vector<std::size_t> touched = evidence_cliques_;
    for (const auto& [c, l] : next) touched.push_back(c);
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    evidence_cliques_.clear();
    auto from = next.begin();
    for (auto c : touched) {
      std::vector<local_evidence> here;
      for (; from != next.end() && from->first == c; ++from) here.push_back(std::move(from->second));
      if (here != evidence_at_[c]) {
        changed = true;
        evidence_at_[c] = std::move(here);
        refresh_potential(c);
        invalidate_from(c);
      }
      if (!evidence_at_[c].empty()) evidence_cliques_.push_back(c);
    }
    if (changed) drop_messages_for_this_evidence();
  }

  /// Replaces factor f's values (its scope stays): its clique's potential is made again and every
  /// message from that clique's side is dropped, those kept without evidence too. A filter over
  /// time moves its prior over the last slice's interface this way, one step after another.
  void set_factor(std::size_t f, std::vector<value_type> values) {
    PGM_ASSERT(f < factors_.size() && values.size() == factors_[f].values().size(), "the factor's own cells");
    factors_[f] = factor_of<S>(factors_[f].scope(), factors_[f].cardinalities(), std::move(values));
    const auto c = tree_->factor_clique(f);
    rebuild_base(c);
    refresh_potential(c);
    invalidate_from(c);
    for (std::size_t e = 0; e < tree_->edges().size(); ++e) prior_[toward(e, tree_->below(c, e))].valid = false;
    drop_messages_for_this_evidence();
  }

  /// ψ_c with its evidence, ⊗ every message into c.
  [[nodiscard]] std::vector<value_type> belief(std::size_t c) {
    ensure_incoming(c, tree_->cliques()[c].edges.size());
    return product_at(c, tree_->cliques()[c].edges.size());
  }

  /// What the beliefs of `targets` would cost now, in cells visited: their own products and
  /// every message into them that is not kept, with the messages those need, each counted once.
  [[nodiscard]] std::size_t cost_of_beliefs(std::span<const std::size_t> targets) {
    const auto& cliques = tree_->cliques();
    const auto work = [&](std::size_t q) { return cliques[q].cells * (cliques[q].groups.size() + 2); };
    auto& counted = counted_;
    counted.assign(2 * tree_->edges().size(), 0);
    std::size_t cost = 0;
    stack_.clear();
    for (auto c : targets) {
      cost = detail::saturating_add(cost, work(c));
      for (auto e : cliques[c].edges) stack_.push_back(message_into(c, e));
    }
    while (!stack_.empty()) {
      const auto d = stack_.back();
      stack_.pop_back();
      if (counted[d] || stored(d).valid) continue;
      counted[d] = 1;
      const auto from = source_of(d);
      cost = detail::saturating_add(cost, work(from));
      for (auto e : cliques[from].edges) {
        if (e != d / 2) stack_.push_back(message_into(from, e));
      }
    }
    return cost;
  }

  /// What the beliefs of every clique would cost by `beliefs_down`, in cells visited, with
  /// nothing kept: a product and a fold per clique on the way up, and on the way down a product,
  /// a fold per child and the folds onto its variables.
  [[nodiscard]] std::size_t cost_of_all_beliefs() const {
    std::size_t cost = 0;
    for (const auto& q : tree_->cliques()) {
      cost = detail::saturating_add(cost, detail::saturating_multiply(q.cells, 2 * q.groups.size() + 3));
    }
    return cost;
  }

  /// The smallest clique holding every variable of `scope`, or cliques().size() if none does.
  [[nodiscard]] std::size_t smallest_holding(std::span<const variable_id> scope) const {
    const auto& cliques = tree_->cliques();
    if (scope.size() == 1) return tree_->home(scope.front());
    std::size_t best = cliques.size();
    for (std::size_t c = 0; c < cliques.size(); ++c) {
      const bool holds = std::all_of(scope.begin(), scope.end(), [&](variable_id v) {
        return tree_->position(c, v) < cliques[c].variables.size();
      });
      if (holds && (best == cliques.size() || cliques[c].cells < cliques[best].cells)) best = c;
    }
    return best;
  }

  /// The unnormalized marginal of `node` (its sum is P(evidence) for sum-product).
  [[nodiscard]] std::vector<value_type> marginal(variable_id node) {
    const auto c = tree_->home(node);
    const variable_id scope[] = {node};
    return fold(belief(c), c, scope);
  }

  /// The unnormalized marginals of `nodes`, each clique's belief computed once for the
  /// variables at home there. Where their homes are several cliques and S divides, the beliefs
  /// come from one walk down the tree as Hugin's propagation makes it (see `beliefs_down`).
  [[nodiscard]] std::vector<std::vector<value_type>> marginals(std::span<const variable_id> nodes) {
    std::vector<std::vector<std::size_t>> at(tree_->cliques().size());  // node indices by home
    std::size_t homes = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      auto& here = at[tree_->home(nodes[i])];
      homes += here.empty() ? 1 : 0;
      here.push_back(i);
    }
    std::vector<std::vector<value_type>> result(nodes.size());
    std::vector<std::size_t> positions;
    const auto fold_homes = [&](std::size_t c) {
      positions.clear();
      for (auto i : at[c]) positions.push_back(tree_->position(c, nodes[i]));
      auto folds = fold_each(belief_buffer_, tree_->cliques()[c].cardinalities, positions);
      for (std::size_t k = 0; k < at[c].size(); ++k) result[at[c][k]] = std::move(folds[k]);
    };
    if constexpr (divides) {
      if (homes > 1) {
        std::vector<char> wanted(at.size());
        for (std::size_t c = 0; c < at.size(); ++c) wanted[c] = at[c].empty() ? 0 : 1;
        beliefs_down(wanted, fold_homes);
        return result;
      }
    }
    for (std::size_t c = 0; c < at.size(); ++c) {
      if (at[c].empty()) continue;
      ensure_incoming(c, tree_->cliques()[c].edges.size());
      product_into(belief_buffer_, c, tree_->cliques()[c].edges.size());
      fold_homes(c);
    }
    return result;
  }

  /// The unnormalized joints of `scopes` (ids in the order wanted, the last fastest), each
  /// within one clique (a family of a Bayesian network is), each clique's belief computed once
  /// for the scopes it holds; empty for a scope no clique holds.
  [[nodiscard]] std::vector<std::vector<value_type>> joints_within_cliques(
      std::span<const std::vector<variable_id>> scopes) {
    std::vector<std::vector<std::size_t>> at(tree_->cliques().size());  // scope indices by clique
    for (std::size_t i = 0; i < scopes.size(); ++i) {
      if (const auto c = smallest_holding(scopes[i]); c < at.size()) at[c].push_back(i);
    }
    std::vector<std::vector<value_type>> result(scopes.size());
    for (std::size_t c = 0; c < at.size(); ++c) {
      if (at[c].empty()) continue;
      ensure_incoming(c, tree_->cliques()[c].edges.size());
      product_into(belief_buffer_, c, tree_->cliques()[c].edges.size());
      for (auto i : at[c]) result[i] = fold(belief_buffer_, c, scopes[i]);
    }
    return result;
  }

  /// The unnormalized joint of `query` (ids in the order wanted) with the evidence.
  [[nodiscard]] factor_of<S> joint(std::span<const variable_id> query) {
    std::vector<std::size_t> cards;
    for (auto v : query) cards.push_back(tree_->cardinality(v));
    std::vector<variable_id> scope(query.begin(), query.end());
    if (const auto c = smallest_holding(query); c < tree_->cliques().size()) {
      return factor_of<S>(std::move(scope), std::move(cards), fold(belief(c), c, query));
    }
    return joint_across_cliques(query, std::move(scope), std::move(cards));
  }

  /// ⊕ over every joint state with the evidence: P(evidence) for sum-product, the largest
  /// joint probability for max-product.
  [[nodiscard]] value_type total() {
    const auto c = smallest_clique();
    value_type result = S::zero();
    for (const auto v : belief(c)) result = S::plus(result, v);
    return result;
  }

  /// For an idempotent S: a joint state of every variable whose value is the maximum (the first
  /// such state in clique order, so ties are settled the same way every time), with that value.
  /// Observed variables keep their observed state.
  struct maximum {
    std::vector<std::size_t> states;  ///< one per network variable
    value_type value;
  };
  [[nodiscard]] maximum maximize() requires(S::idempotent) {
    const auto& cliques = tree_->cliques();
    maximum result{std::vector<std::size_t>(tree_->variable_count(), unassigned), S::zero()};
    const auto& order = tree_->preorder();
    // Toward the root, every clique's product of its potential and its children's messages.
    ensure_incoming(order.front(), cliques[order.front()].edges.size());
    for (const auto c : order) {
      const auto parent_slot = slot_of(c, tree_->parent_edge(c));
      auto table = product_at(c, parent_slot);
      const auto& vars = cliques[c].variables;
      const auto& cards = cliques[c].cardinalities;
      std::vector<std::size_t> digit(vars.size(), 0);
      std::size_t best = table.size();
      for (std::size_t i = 0; i < table.size(); ++i) {
        bool consistent = true;
        for (std::size_t k = 0; k < vars.size() && consistent; ++k) {
          const auto fixed = result.states[vars[k].value()];
          consistent = fixed == unassigned || fixed == digit[k];
        }
        if (consistent && (best == table.size() || table[i] > table[best])) best = i;
        for (std::size_t k = vars.size(); k-- > 0;) {
          if (++digit[k] < cards[k]) break;
          digit[k] = 0;
        }
      }
      PGM_ASSERT(best < table.size(), "some state is consistent with the separator");
      if (c == order.front()) result.value = table[best];
      for (std::size_t k = vars.size(); k-- > 0;) {
        result.states[vars[k].value()] = best % cards[k];
        best /= cards[k];
      }
    }
    return result;
  }

 private:
  static constexpr std::size_t unassigned = static_cast<std::size_t>(-1);

  struct local_evidence {
    variable_id variable;
    std::vector<value_type> weights;
    friend bool operator==(const local_evidence&, const local_evidence&) = default;
  };
  struct message {
    std::vector<value_type> values;
    bool valid = false;
    std::uint64_t version = 0;  ///< unique to the values computed, so a fold can tell its inputs changed
    /// Made by Hugin's division where the message divided by was zero: the 0 put there holds
    /// only while the evidence on the other side stays, so any change of evidence discards it.
    bool for_this_evidence = false;
  };
  /// ψ_c with the messages of every group but one, folded onto that group's separator: what
  /// every message out of c through that group starts from (the group's own messages are
  /// functions of the separator, so they multiply after the fold).
  struct group_fold {
    std::vector<value_type> values;
    std::vector<std::uint64_t> inputs;  ///< the versions of ψ_c and of the messages it used
    bool valid = false;
    bool divided_by_zero = false;  ///< made by divide_out where the group's messages were zero
  };

  // A directed message on edge e: 2e goes child → parent, 2e + 1 parent → child.
  [[nodiscard]] static std::size_t toward(std::size_t e, bool to_parent) noexcept {
    return 2 * e + (to_parent ? 0 : 1);
  }
  [[nodiscard]] std::size_t source_of(std::size_t d) const noexcept {
    const auto& e = tree_->edges()[d / 2];
    return d % 2 == 0 ? e.child : e.parent;
  }
  [[nodiscard]] std::size_t message_into(std::size_t c, std::size_t e) const noexcept {
    return toward(e, tree_->edges()[e].parent == c);
  }
  /// Whether evidence lies on the source side of message d.
  [[nodiscard]] bool depends_on_evidence(std::size_t d) const noexcept {
    const auto e = d / 2;
    const bool upward = d % 2 == 0;
    return std::any_of(evidence_cliques_.begin(), evidence_cliques_.end(),
                       [&](std::size_t c) { return tree_->below(c, e) == upward; });
  }
  [[nodiscard]] message& stored(std::size_t d) { return depends_on_evidence(d) ? working_[d] : prior_[d]; }

  [[nodiscard]] std::size_t slot_of(std::size_t c, std::size_t e) const noexcept {
    const auto& edges = tree_->cliques()[c].edges;
    return static_cast<std::size_t>(std::find(edges.begin(), edges.end(), e) - edges.begin());
  }

  /// ψ_c with its evidence, made when first needed after the evidence changed (a query that
  /// is answered otherwise never pays for it).
  [[nodiscard]] const std::vector<value_type>& potential(std::size_t c) {
    if (evidence_at_[c].empty()) return base_[c];
    if (with_evidence_[c].empty()) apply_evidence(c);
    return with_evidence_[c];
  }

  void drop_messages_for_this_evidence() {
    if (!any_for_this_evidence_) return;
    for (auto* kept : {&prior_, &working_}) {
      for (auto& m : *kept) m.valid = m.valid && !m.for_this_evidence;
    }
    any_for_this_evidence_ = false;
  }

  /// The interventions' part of set_evidence.
  void set_interventions(const std::vector<observation>& intervened, bool& changed) {
    intervened_ = !intervened.empty();
    std::vector<std::vector<observation>> cut(tree_->cliques().size());
    for (const auto& o : intervened) cut[tree_->factor_clique(o.variable.value())].push_back(o);
    for (std::size_t c = 0; c < cut.size(); ++c) {
      std::sort(cut[c].begin(), cut[c].end(),
                [](const observation& a, const observation& b) { return a.variable < b.variable; });
      if (cut[c] != cut_at_[c]) {
        changed = true;
        cut_at_[c] = std::move(cut[c]);
        rebuild_base(c);
        refresh_potential(c);
        invalidate_from(c);
        for (std::size_t e = 0; e < tree_->edges().size(); ++e) prior_[toward(e, tree_->below(c, e))].valid = false;
      }
    }
  }

  void refresh_potential(std::size_t c) {
    potential_version_[c] = ++versions_;
    with_evidence_[c].clear();
    if (evidence_at_[c].empty()) with_evidence_[c].shrink_to_fit();
  }

  /// ψ_c without evidence: the clique's tables but the intervened ones (a product, since
  /// Shafer–Shenoy never divides), each intervened variable fixed at its state.
  void rebuild_base(std::size_t c) {
    const auto& clique = tree_->cliques()[c];
    base_[c].assign(clique.cells, S::one());
    const auto is_cut = [&](std::size_t f) {
      return std::any_of(cut_at_[c].begin(), cut_at_[c].end(),
                         [&](const observation& o) { return o.variable.value() == f; });
    };
    multiply_families(c, is_cut);
    for (const auto& o : cut_at_[c]) {
      std::vector<value_type> point(tree_->cardinality(o.variable), S::zero());
      point[o.state.value()] = S::one();
      const variable_id scope[] = {o.variable};
      detail::multiply_into<S, value_type>(base_[c], clique.cardinalities, tree_->strides_into(c, scope),
                                           std::span<const value_type>(point));
    }
  }

  void apply_evidence(std::size_t c) {
    with_evidence_[c] = base_[c];
    for (const auto& l : evidence_at_[c]) {
      const variable_id scope[] = {l.variable};
      detail::multiply_into<S, value_type>(with_evidence_[c], tree_->cliques()[c].cardinalities,
                                           tree_->strides_into(c, scope), std::span<const value_type>(l.weights));
    }
  }

  /// Every factor of `model` in S.
  template <GraphicalModel M>
  [[nodiscard]] static std::vector<factor_of<S>> factors_in(const M& model) {
    std::vector<factor_of<S>> factors;
    factors.reserve(model.factor_count());
    for (std::size_t f = 0; f < model.factor_count(); ++f) factors.push_back(detail::model_factor<S>(model, f));
    return factors;
  }

  /// base_[c] ⊗= every factor of clique c's families but those `left_out` names.
  template <class LeftOut>
  void multiply_families(std::size_t c, const LeftOut& left_out) {
    std::vector<std::vector<std::size_t>> strides;
    std::vector<std::size_t> kept;
    for (auto f : families_[c]) {
      if (left_out(f)) continue;
      kept.push_back(f);
      strides.push_back(tree_->strides_into(c, factors_[f].scope()));
    }
    std::vector<detail::strided_table<value_type>> tables;
    for (std::size_t k = 0; k < kept.size(); ++k) tables.push_back({strides[k], factors_[kept[k]].values()});
    detail::multiply_all_into<S, value_type>(std::span<value_type>(base_[c]), tree_->cliques()[c].cardinalities,
                                             std::span<const detail::strided_table<value_type>>(tables));
  }

  /// Every message with clique c on its source side is stale.
  void invalidate_from(std::size_t c) {
    for (std::size_t e = 0; e < tree_->edges().size(); ++e) working_[toward(e, tree_->below(c, e))].valid = false;
  }

  /// Computes the messages into c over every edge but its `skip`-th (none when skip is past the
  /// end), and those they need, that are not kept already.
  void ensure_incoming(std::size_t c, std::size_t skip) {
    const auto& edges = tree_->cliques()[c].edges;
    stack_.clear();
    for (std::size_t k = 0; k < edges.size(); ++k) {
      if (k != skip) stack_.push_back(message_into(c, edges[k]));
    }
    ensure_stacked();
  }

  /// Computes the messages on stack_ and those they need: a walk away from their targets that
  /// stops at kept messages, then the messages in reverse order of discovery, sources first.
  void ensure_stacked() {
    const auto& cliques = tree_->cliques();
    pending_.clear();
    while (!stack_.empty()) {
      const auto d = stack_.back();
      stack_.pop_back();
      if (stored(d).valid) continue;
      pending_.push_back(d);
      const auto from = source_of(d);
      for (auto e : cliques[from].edges) {
        if (e != d / 2) stack_.push_back(message_into(from, e));
      }
    }
    for (auto it = pending_.rbegin(); it != pending_.rend(); ++it) compute(*it);
  }

  /// ψ_c with evidence ⊗ the messages into c over every edge but its `skip`-th and every group
  /// but `skip_group`. Messages over one separator are multiplied in its table first, then into
  /// the clique's once.
  [[nodiscard]] std::vector<value_type> product_at(std::size_t c, std::size_t skip,
                                                   std::size_t skip_group = static_cast<std::size_t>(-1)) {
    std::vector<value_type> table;
    product_into(table, c, skip, skip_group);
    return table;
  }

  /// product_at into `table`, whose storage is reused (a clique's table of 16 MiB is not
  /// allocated and faulted in afresh for every belief).
  void product_into(std::vector<value_type>& table, std::size_t c, std::size_t skip,
                    std::size_t skip_group = static_cast<std::size_t>(-1)) {
    const auto& q = tree_->cliques()[c];
    const auto& psi = potential(c);
    table.assign(psi.begin(), psi.end());
    std::vector<detail::strided_table<value_type>> products;
    std::size_t merged = 0;
    for (std::size_t g = 0; g < q.groups.size(); ++g) {
      if (g == skip_group) continue;
      const auto& group = q.groups[g];
      const std::vector<value_type>* single = nullptr;
      std::size_t count = 0;
      for (auto k : group) {
        if (k == skip) continue;
        const auto& in = stored(message_into(c, q.edges[k]));
        PGM_ASSERT(in.valid, "messages are computed before use");
        if (count++ == 0) {
          single = &in.values;
          continue;
        }
        if (count == 2) {
          if (merged == group_scratch_.size()) group_scratch_.emplace_back();
          group_scratch_[merged] = *single;
        }
        auto& product = group_scratch_[merged];
        for (std::size_t i = 0; i < product.size(); ++i) product[i] = S::times(product[i], in.values[i]);
      }
      if (count == 0) continue;
      const auto& product = count == 1 ? *single : group_scratch_[merged++];
      const auto k = group.front() == skip ? group[1] : group.front();
      products.push_back({q.strides[k], product});
    }
    detail::multiply_all_into<S, value_type>(std::span<value_type>(table), q.cardinalities,
                                             std::span<const detail::strided_table<value_type>>(products));
  }

  /// The fold of ψ_c and every group of messages but g onto g's separator, kept while its inputs
  /// stay: a clique with many neighbours over one separator (pathfinder's disease node) sends
  /// them all its messages from one pass over its table.
  const std::vector<value_type>& fold_for_group(std::size_t c, std::size_t g) {
    const auto& q = tree_->cliques()[c];
    // Folds made all at once may divide by g's own messages (fold_all_groups): they depend on
    // every message into c, and are kept while none changes.
    const bool all_at_once = q.groups.size() >= fold_all_from && all_messages_in(c);
    inputs_of(c, all_at_once ? q.groups.size() : g, inputs_);
    auto& kept = group_folds_[c][g];
    if (kept.valid && kept.inputs == inputs_) return kept.values;
    if (all_at_once) {
      fold_all_groups(c);
      return kept.values;
    }
    product_into(belief_buffer_, c, q.edges.size(), g);
    const auto k = q.groups[g].front();
    kept.values.assign(tree_->edges()[q.edges[k]].cells, S::zero());
    detail::fold_onto<S, value_type>(std::span<const value_type>(belief_buffer_), q.cardinalities, q.strides[k],
                                     std::span<value_type>(kept.values));
    kept.inputs = inputs_;
    kept.valid = true;
    kept.divided_by_zero = false;
    return kept.values;
  }

  static constexpr bool divides =
      std::same_as<S, log_sum_product<value_type>> || std::same_as<S, sum_product<value_type>>;

  /// A clique with this many groups or more sends all its messages at once when every message
  /// into it is known (fold_all_groups): G messages from one product and G folds, or G·log G
  /// products, instead of G·G (a clique many cliques hang from, as a relational model's, sends
  /// hundreds).
  static constexpr std::size_t fold_all_from = 4;

  [[nodiscard]] bool all_messages_in(std::size_t c) {
    const auto& q = tree_->cliques()[c];
    return std::all_of(q.edges.begin(), q.edges.end(), [&](std::size_t e) { return stored(message_into(c, e)).valid; });
  }

  /// The product of group g's messages into c, over its separator.
  [[nodiscard]] std::vector<value_type> group_product(std::size_t c, std::size_t g) {
    const auto& q = tree_->cliques()[c];
    const auto& group = q.groups[g];
    std::vector<value_type> product = stored(message_into(c, q.edges[group.front()])).values;
    for (std::size_t i = 1; i < group.size(); ++i) {
      const auto& in = stored(message_into(c, q.edges[group[i]])).values;
      for (std::size_t j = 0; j < product.size(); ++j) product[j] = S::times(product[j], in[j]);
    }
    return product;
  }

  /// The versions of ψ_c and of the messages into c of every group but `skip` (none skipped
  /// when it is past the last group).
  void inputs_of(std::size_t c, std::size_t skip, std::vector<std::uint64_t>& inputs) {
    const auto& q = tree_->cliques()[c];
    inputs.assign(1, potential_version_[c]);
    for (std::size_t h = 0; h < q.groups.size(); ++h) {
      if (h == skip) continue;
      for (auto k : q.groups[h]) inputs.push_back(stored(message_into(c, q.edges[k])).version);
    }
  }

  /// Every group fold of clique c at once (fold_for_group), every message into c known: for sums
  /// of probabilities or of their logarithms as Hugin does, the belief folded onto each separator
  /// with the group's own messages divided out again (one product and G folds); in other semirings,
  /// which may not divide, by divide and conquer.
  void fold_all_groups(std::size_t c) {
    const auto& q = tree_->cliques()[c];
    std::vector<std::vector<value_type>> products(q.groups.size());
    for (std::size_t g = 0; g < q.groups.size(); ++g) products[g] = group_product(c, g);
    if constexpr (divides) {
      divide_out(c, products);
    } else {
      std::vector<value_type> table = potential(c);
      fold_range(c, 0, q.groups.size(), table, products);
    }
    for (std::size_t g = 0; g < q.groups.size(); ++g) {
      auto& kept = group_folds_[c][g];
      inputs_of(c, q.groups.size(), kept.inputs);
      kept.valid = true;
    }
  }

  /// `table` (clique c's) folded onto each variable at `positions`. In logarithms, through
  /// plain sums of the table's exps when no digit is lost that way (shifted_exp).
  [[nodiscard]] std::vector<std::vector<value_type>> fold_each(const std::vector<value_type>& table,
                                                               std::span<const std::size_t> cards,
                                                               std::span<const std::size_t> positions) {
    if constexpr (std::same_as<S, log_sum_product<value_type>>) {
      if (positions.size() > 1) {
        if (const auto top = detail::shifted_exp<value_type>(table, plain_buffer_)) {
          auto folds = detail::fold_onto_each<sum_product<value_type>, value_type>(plain_buffer_, cards, positions);
          for (auto& f : folds) detail::unshift_log<value_type>(f, *top);
          return folds;
        }
      }
    }
    return detail::fold_onto_each<S, value_type>(table, cards, positions);
  }

  /// Hugin's division: each group's fold is the belief's fold onto its separator over the group's
  /// messages; where they are zero, so is the fold (0/0 = 0: the group's side gives those states
  /// weight 0, whatever comes back to it). In logarithms it loses nothing; in probabilities it
  /// loses nothing where no product underflows, which solve's choice of semiring ensures
  /// (detail::in_fitting_semiring). In logarithms the folds are plain sums of the belief's exps when no
  /// digit is lost that way (one exp per cell for all of them: Alchemy_11's clique of 2²⁰ cells
  /// has hundreds of groups).
  void divide_out(std::size_t c, const std::vector<std::vector<value_type>>& products) {
    constexpr bool in_logs = std::same_as<S, log_sum_product<value_type>>;
    const auto& q = tree_->cliques()[c];
    product_into(belief_buffer_, c, q.edges.size());
    const auto& belief = belief_buffer_;
    std::optional<value_type> top;
    if constexpr (in_logs) top = detail::shifted_exp<value_type>(belief, plain_buffer_);
    for (std::size_t g = 0; g < q.groups.size(); ++g) {
      const auto k = q.groups[g].front();
      auto& values = group_folds_[c][g].values;
      if (top) {
        values.assign(tree_->edges()[q.edges[k]].cells, value_type{0});
        detail::fold_onto<sum_product<value_type>, value_type>(
            std::span<const value_type>(plain_buffer_), q.cardinalities, q.strides[k], std::span<value_type>(values));
        detail::unshift_log<value_type>(values, *top);
      } else {
        values.assign(tree_->edges()[q.edges[k]].cells, S::zero());
        detail::fold_onto<S, value_type>(std::span<const value_type>(belief), q.cardinalities, q.strides[k],
                                         std::span<value_type>(values));
      }
      group_folds_[c][g].divided_by_zero = false;
      for (std::size_t s = 0; s < values.size(); ++s) {
        const auto by = products[g][s];
        if (by == S::zero()) {
          values[s] = S::zero();
          group_folds_[c][g].divided_by_zero = true;
        } else {
          values[s] = in_logs ? values[s] - by : values[s] / by;
        }
      }
    }
  }

  /// Calls `use(c)` with clique c's belief in belief_buffer_ for every c `wanted` marks, walking
  /// down from the root after every message toward it is known: a clique's belief, folded onto a
  /// child's separator and divided by the child's message (Hugin's division, 0/0 = 0 as in
  /// divide_out), is its message to the child. One product per clique on the way, not one per
  /// message sent and another for the belief. A quotient is off only where the belief's fold has
  /// fallen below a double's normal range, by at most 2⁻¹⁰⁷⁴ a cell: against a total the caller
  /// has checked is normal, a marginal moves by less than 2.2e-16 per cell of the clique.
  template <class Use>
  void beliefs_down(std::span<const char> wanted, Use&& use) {
    const auto& cliques = tree_->cliques();
    const auto& order = tree_->preorder();
    std::vector<char> on_way(wanted.begin(), wanted.end());  // c or a clique below it is wanted
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
      const auto up = tree_->parent_edge(*it);
      if (on_way[*it] && up < tree_->edges().size()) on_way[tree_->edges()[up].parent] = 1;
    }
    ensure_incoming(order.front(), cliques[order.front()].edges.size());
    std::vector<value_type> fold;
    for (auto c : order) {
      if (!on_way[c]) continue;
      const auto& q = cliques[c];
      std::vector<std::size_t> to_send;  // edge positions of children whose message is stale
      for (std::size_t k = 0; k < q.edges.size(); ++k) {
        const auto& e = tree_->edges()[q.edges[k]];
        if (e.parent == c && on_way[e.child] && !stored(toward(q.edges[k], false)).valid) to_send.push_back(k);
      }
      if (!wanted[c] && to_send.empty()) continue;
      std::stable_sort(to_send.begin(), to_send.end(),
                       [&](std::size_t a, std::size_t b) { return group_of_[c][a] < group_of_[c][b]; });
      product_into(belief_buffer_, c, q.edges.size());
      // In logarithms, the folds are plain sums of the belief's exps where no digit is lost that
      // way, as in divide_out: one exp per cell for all of them, not one per cell and fold.
      std::optional<value_type> top;
      if constexpr (std::same_as<S, log_sum_product<value_type>>) {
        if (!to_send.empty()) top = detail::shifted_exp<value_type>(belief_buffer_, plain_buffer_);
      }
      for (std::size_t first = 0; first < to_send.size(); ++first) {
        const auto g = group_of_[c][to_send[first]];
        if (first > 0 && g == group_of_[c][to_send[first - 1]]) continue;
        const auto& strides = q.strides[to_send[first]];
        const auto cells = tree_->edges()[q.edges[to_send[first]]].cells;
        if (top) {
          fold.assign(cells, value_type{0});
          detail::fold_onto<sum_product<value_type>, value_type>(std::span<const value_type>(plain_buffer_),
                                                                 q.cardinalities, strides, std::span<value_type>(fold));
          detail::unshift_log<value_type>(fold, *top);
        } else {
          fold.assign(cells, S::zero());
          detail::fold_onto<S, value_type>(std::span<const value_type>(belief_buffer_), q.cardinalities, strides,
                                           std::span<value_type>(fold));
        }
        for (auto k = first; k < to_send.size() && group_of_[c][to_send[k]] == g; ++k) {
          send_by_division(c, to_send[k], fold);
        }
      }
      if (wanted[c]) use(c);
    }
  }

  /// Clique c's message through its k-th edge, downward: `fold` (c's belief on the separator)
  /// over the message that came up that edge.
  void send_by_division(std::size_t c, std::size_t k, const std::vector<value_type>& fold) {
    constexpr bool in_logs = std::same_as<S, log_sum_product<value_type>>;
    const auto edge = tree_->cliques()[c].edges[k];
    const auto& up = stored(toward(edge, true)).values;
    std::vector<value_type> values(fold.size());
    bool by_zero = false;
    for (std::size_t s = 0; s < values.size(); ++s) {
      const auto by = up[s];
      if (by == S::zero()) {
        values[s] = S::zero();
        by_zero = true;
      } else {
        values[s] = in_logs ? fold[s] - by : fold[s] / by;
      }
    }
    auto& out = stored(toward(edge, false));
    out.values = std::move(values);
    out.valid = true;
    out.version = ++versions_;
    out.for_this_evidence = by_zero;
    any_for_this_evidence_ = any_for_this_evidence_ || by_zero;
  }

  /// `table` is ψ_c ⊗ the products of every group outside [lo, hi): folds it, with the products
  /// of all of [lo, hi) but one, onto each group of [lo, hi). Consumes `table`.
  void fold_range(std::size_t c, std::size_t lo, std::size_t hi, std::vector<value_type>& table,
                  const std::vector<std::vector<value_type>>& products) {
    const auto& q = tree_->cliques()[c];
    const auto strides_of = [&](std::size_t g) -> const std::vector<std::size_t>& {
      return q.strides[q.groups[g].front()];
    };
    if (hi - lo == 1) {
      auto& values = group_folds_[c][lo].values;
      values.assign(tree_->edges()[q.edges[q.groups[lo].front()]].cells, S::zero());
      detail::fold_onto<S, value_type>(std::span<const value_type>(table), q.cardinalities, strides_of(lo),
                                       std::span<value_type>(values));
      return;
    }
    const auto mid = lo + (hi - lo) / 2;
    auto left = table;
    for (auto g = mid; g < hi; ++g) {
      detail::multiply_into<S, value_type>(left, q.cardinalities, strides_of(g),
                                           std::span<const value_type>(products[g]));
    }
    fold_range(c, lo, mid, left, products);
    left = {};
    for (auto g = lo; g < mid; ++g) {
      detail::multiply_into<S, value_type>(table, q.cardinalities, strides_of(g),
                                           std::span<const value_type>(products[g]));
    }
    fold_range(c, mid, hi, table, products);
  }

  void compute(std::size_t d) {
    const auto e = d / 2;
    const auto from = source_of(d);
    const auto slot = slot_of(from, e);
    const auto g = group_of_[from][slot];
    const auto& q = tree_->cliques()[from];
    auto values = fold_for_group(from, g);
    const bool for_this_evidence = group_folds_[from][g].divided_by_zero;
    for (auto k : q.groups[g]) {
      if (k == slot) continue;
      const auto& in = stored(message_into(from, q.edges[k]));
      for (std::size_t i = 0; i < values.size(); ++i) values[i] = S::times(values[i], in.values[i]);
    }
    auto& out = stored(d);
    out.values = std::move(values);
    out.valid = true;
    out.version = ++versions_;
    out.for_this_evidence = for_this_evidence;
    any_for_this_evidence_ = any_for_this_evidence_ || for_this_evidence;
  }

  /// A table of clique c folded onto `scope` (in that order).
  [[nodiscard]] std::vector<value_type> fold(const std::vector<value_type>& table, std::size_t c,
                                             std::span<const variable_id> scope) const {
    std::size_t cells = 1;
    for (auto v : scope) cells *= tree_->cardinality(v);
    std::vector<value_type> out(cells, S::zero());
    detail::fold_onto<S, value_type>(std::span<const value_type>(table), tree_->cliques()[c].cardinalities,
                                     tree_->strides_into(c, scope), std::span<value_type>(out));
    return out;
  }

  [[nodiscard]] std::size_t smallest_clique() const {
    const auto& cliques = tree_->cliques();
    std::size_t best = 0;
    for (std::size_t c = 1; c < cliques.size(); ++c) {
      if (cliques[c].cells < cliques[best].cells) best = c;
    }
    return best;
  }

  /// Variables in different cliques: the smallest subtree joining their homes, each of its
  /// cliques with the messages from outside it, eliminated down to the query.
  [[nodiscard]] factor_of<S> joint_across_cliques(std::span<const variable_id> query, std::vector<variable_id> scope,
                                                  std::vector<std::size_t> cards) {
    const auto& cliques = tree_->cliques();
    std::vector<char> keep(cliques.size(), 1);
    std::vector<char> terminal(cliques.size(), 0);
    for (auto v : query) terminal[tree_->home(v)] = 1;
    // Prune non-terminal leaves until none is left: what remains joins the terminals.
    std::vector<std::size_t> degree(cliques.size());
    std::vector<std::size_t> leaves;
    for (std::size_t c = 0; c < cliques.size(); ++c) {
      degree[c] = cliques[c].edges.size();
      if (degree[c] <= 1 && !terminal[c]) leaves.push_back(c);
    }
    while (!leaves.empty()) {
      const auto c = leaves.back();
      leaves.pop_back();
      if (!keep[c]) continue;
      keep[c] = 0;
      for (auto e : cliques[c].edges) {
        const auto other = tree_->across(e, c);
        if (keep[other] && --degree[other] <= 1 && !terminal[other]) leaves.push_back(other);
      }
    }
    // Each kept clique's potential with the messages from its pruned neighbours.
    std::vector<detail::shared_factor<S>> factors;
    for (std::size_t c = 0; c < cliques.size(); ++c) {
      if (!keep[c]) continue;
      const auto& q = cliques[c];
      stack_.clear();
      for (auto e : q.edges) {
        if (!keep[tree_->across(e, c)]) stack_.push_back(message_into(c, e));
      }
      ensure_stacked();
      auto table = potential(c);
      for (std::size_t k = 0; k < q.edges.size(); ++k) {
        if (keep[tree_->across(q.edges[k], c)]) continue;
        const auto& in = stored(message_into(c, q.edges[k]));
        detail::multiply_into<S, value_type>(table, q.cardinalities, q.strides[k],
                                             std::span<const value_type>(in.values));
      }
      factors.push_back(std::make_shared<const factor_of<S>>(q.variables, q.cardinalities, std::move(table)));
    }
    return eliminate_to(std::move(factors), scope, cards);
  }

  /// Eliminates every variable outside `scope` from the product of `factors` (min-fill order),
  /// and returns the result over `scope` in that order.
  [[nodiscard]] factor_of<S> eliminate_to(std::vector<detail::shared_factor<S>> factors,
                                          const std::vector<variable_id>& scope,
                                          const std::vector<std::size_t>& cards) const {
    std::vector<variable_id> others;
    for (const auto& f : factors) {
      for (auto v : f->scope()) {
        if (std::find(scope.begin(), scope.end(), v) == scope.end()) others.push_back(v);
      }
    }
    std::sort(others.begin(), others.end());
    others.erase(std::unique(others.begin(), others.end()), others.end());
    for (auto v : elimination_order(factors, std::move(others))) {
      static_cast<void>(detail::eliminate_one<S>(factors, v));
    }
    return detail::product_over<S>(factors, scope, cards);
  }

  std::shared_ptr<const junction_tree> tree_;
  std::vector<factor_of<S>> factors_;
  std::vector<std::vector<value_type>> base_;
  std::vector<std::vector<local_evidence>> evidence_at_;
  std::vector<std::vector<std::size_t>> families_;  ///< the factors each clique holds
  std::vector<std::vector<observation>> cut_at_;    ///< the interventions on them, by variable
  std::vector<std::vector<value_type>> with_evidence_;
  std::vector<std::size_t> evidence_cliques_;  ///< ascending
  bool intervened_ = false;                    ///< whether any clique has an intervention
  bool any_for_this_evidence_ = false;         ///< whether a kept message may be for_this_evidence
  std::vector<message> prior_;
  std::vector<message> working_;
  std::vector<std::size_t> pending_;
  std::vector<std::size_t> stack_;
  std::vector<char> counted_;                           ///< cost_of_beliefs's marks, reused
  std::vector<std::vector<value_type>> group_scratch_;  ///< products of a group's messages
  std::vector<value_type> belief_buffer_;               ///< a clique's product, reused
  std::vector<value_type> plain_buffer_;                ///< its exps, in logarithms
  std::vector<std::uint64_t> potential_version_;
  std::vector<std::vector<group_fold>> group_folds_;
  std::vector<std::vector<std::size_t>> group_of_;  ///< [clique][edge position] → its group
  std::vector<std::uint64_t> inputs_;
  std::uint64_t versions_ = 0;
};

}  // namespace pgm
