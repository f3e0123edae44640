#pragma once
// Definitions for pgm/inference/dynamic_inference.hpp.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pgm/inference/dynamic_inference.hpp"
#include "pgm/inference/exact.hpp"

namespace pgm {

namespace detail {

/// The junction tree of these factors, over variables of these cardinalities.
inline std::shared_ptr<const junction_tree> tree_over(std::vector<std::size_t> cardinalities,
                                                      const std::vector<factor_of<sum_product<double>>>& factors,
                                                      const junction_tree_options& options) {
  std::vector<std::vector<variable_id>> scopes;
  for (const auto& f : factors) scopes.push_back(f.scope());
  return std::make_shared<const junction_tree>(std::move(cardinalities), scopes, options);
}

}  // namespace detail

PGM_DECL interface_filter::interface_filter(dynamic_network model, const junction_tree_options& options)
    : model_(std::move(model)) {
  using table = factor_of<sum_product<double>>;  // probabilities: the same values in max-product
  const std::size_t n = model_.size();
  // Two slices unrolled: slice 1's tables are the transition's, over slice 0 and slice 1.
  const auto two = model_.unroll(2);
  std::vector<std::size_t> slice_of(two.size());
  std::vector<std::size_t> template_of(two.size());
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t t = 0; t < 2; ++t) {
      const auto id = two.id(slice_name(model_.variables()[i].name(), static_cast<long>(t))).value();
      slice_of[id] = t;
      template_of[id] = i;
    }
  }
  std::vector<char> in_interface(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto node = two.id(slice_name(model_.variables()[i].name(), 1));
    for (auto p : two.graph().parents(node)) {
      if (slice_of[p.value()] == 0) in_interface[template_of[p.value()]] = 1;
    }
  }
  std::vector<std::size_t> cards;
  for (const auto& v : model_.variables()) cards.push_back(v.cardinality());
  std::vector<std::size_t> interface_cards;
  for (std::size_t i = 0; i < n; ++i) {
    if (!in_interface[i]) continue;
    interface_.push_back(index_at<variable_id>(i));
    previous_interface_.push_back(index_at<variable_id>(n + previous_interface_.size()));
    interface_cells_ = detail::saturating_multiply(interface_cells_, cards[i]);
    interface_cards.push_back(cards[i]);
  }
  const std::vector<double> ones(interface_cells_, 1.0);

  // The first slice: its tables as factors 0 … n−1 (factor i is variable i's, as interventions
  // need), then β over the interface.
  std::vector<table> first;
  for (std::size_t i = 0; i < n; ++i) {
    first.push_back(detail::table_factor<sum_product<double>>(model_.initial(), index_at<variable_id>(i)));
  }
  if (!interface_.empty()) first.emplace_back(interface_, interface_cards, ones);
  const auto first_tree = detail::tree_over(cards, first, options);
  first_max_ = std::make_unique<propagation<max_product<double>>>(first_tree, first);
  first_ = std::make_unique<propagation<sum_product<double>>>(first_tree, std::move(first));

  // The transition: this slice's variables keep their template ids, the previous slice's
  // interface follows them; its tables, then the prior over the previous interface, then β.
  std::vector<variable_id> renumbered(two.size());
  for (std::size_t id = 0; id < two.size(); ++id) {
    const auto i = template_of[id];
    if (slice_of[id] == 1) {
      renumbered[id] = index_at<variable_id>(i);
    } else if (in_interface[i]) {
      const auto at = std::lower_bound(interface_.begin(), interface_.end(), index_at<variable_id>(i));
      renumbered[id] = previous_interface_[static_cast<std::size_t>(at - interface_.begin())];
    }
  }
  std::vector<table> transition;
  for (std::size_t i = 0; i < n; ++i) {
    const auto node = two.id(slice_name(model_.variables()[i].name(), 1));
    const auto given = detail::table_factor<sum_product<double>>(two, node);
    std::vector<variable_id> scope;
    for (auto v : given.scope()) scope.push_back(renumbered[v.value()]);
    transition.emplace_back(std::move(scope), given.cardinalities(),
                            std::vector<double>(given.values().begin(), given.values().end()));
  }
  auto transition_cards = cards;
  if (!interface_.empty()) {
    transition.emplace_back(previous_interface_, interface_cards, ones);
    transition.emplace_back(interface_, interface_cards, ones);
    transition_cards.insert(transition_cards.end(), interface_cards.begin(), interface_cards.end());
  }
  const auto transition_tree = detail::tree_over(std::move(transition_cards), transition, options);
  transition_max_ = std::make_unique<propagation<max_product<double>>>(transition_tree, transition);
  transition_ = std::make_unique<propagation<sum_product<double>>>(transition_tree, std::move(transition));
  first_future_ = transition_prior_ = transition_future_ = max_prior_ = ones;
  for (std::size_t i = 0; i < n; ++i) every_.push_back(index_at<variable_id>(i));
}

PGM_DECL impossible_evidence interface_filter::impossible_at(std::size_t step, const evidence_set& observed) const {
  return impossible_evidence("the evidence at step " + std::to_string(step) + " (" +
                             detail::describe(model_.variables(), observed) +
                             ") has probability 0 given the steps before");
}

PGM_DECL interface_filter::step_answer interface_filter::step(bool first, const std::vector<double>& prior,
                                                              const std::vector<double>& future,
                                                              const evidence_set& observed, std::size_t step) {
  const std::size_t n = model_.size();
  auto& in = first ? *first_ : *transition_;
  if (!interface_.empty()) {
    if (first) {
      set_if_changed(in, n, future, first_future_);
    } else {
      set_if_changed(in, n, prior, transition_prior_);
      set_if_changed(in, n + 1, future, transition_future_);
    }
  }
  in.set_evidence(observed);
  step_answer answer;
  answer.marginals = in.marginals(every_);
  double total = 0.0;
  if (n > 0) {
    for (double p : answer.marginals.front()) total += p;
  }
  if (!(total > 0.0) || !std::isfinite(total)) throw impossible_at(step, observed);
  for (auto& m : answer.marginals) {
    for (auto& p : m) p /= total;
  }
  if (!interface_.empty()) {
    const auto joint = in.joint(interface_);
    answer.interface.assign(joint.values().begin(), joint.values().end());
    for (auto& p : answer.interface) p /= total;
  } else {
    answer.interface = {1.0};
  }
  answer.log_total = std::log(total);
  return answer;
}

PGM_DECL std::vector<double> interface_filter::backward(const std::vector<double>& future, const evidence_set& observed,
                                                        std::size_t step) {
  const std::size_t n = model_.size();
  set_if_changed(*transition_, n, std::vector<double>(interface_cells_, 1.0), transition_prior_);
  set_if_changed(*transition_, n + 1, future, transition_future_);
  transition_->set_evidence(observed);
  const auto joint = transition_->joint(previous_interface_);
  std::vector<double> beta(joint.values().begin(), joint.values().end());
  double total = 0.0;
  for (double b : beta) total += b;
  if (!(total > 0.0) || !std::isfinite(total)) {
    throw impossible_evidence("the evidence from step " + std::to_string(step) + " on has probability 0");
  }
  for (auto& b : beta) b /= total;
  return beta;
}

PGM_DECL dynamic_marginals interface_filter::filter(std::span<const evidence_set> steps, std::size_t predict) {
  dynamic_marginals result;
  const std::vector<double> ones(interface_cells_, 1.0);
  const evidence_set none;
  std::vector<double> prior;
  for (std::size_t t = 0; t < steps.size() + predict; ++t) {
    auto answer = step(t == 0, prior, ones, t < steps.size() ? steps[t] : none, t);
    if (t < steps.size()) result.log_evidence_probability += answer.log_total;
    result.steps.push_back(std::move(answer.marginals));
    prior = std::move(answer.interface);
  }
  return result;
}

PGM_DECL dynamic_marginals interface_filter::smooth(std::span<const evidence_set> steps) {
  // Nothing carries from one slice to the next: smoothing is filtering.
  if (interface_.empty()) return filter(steps);
  dynamic_marginals result;
  if (steps.empty()) return result;
  const std::vector<double> ones(interface_cells_, 1.0);
  // Forward: every step's filtered interface (the prior of the next).
  std::vector<std::vector<double>> alpha;
  for (std::size_t t = 0; t < steps.size(); ++t) {
    auto answer = step(t == 0, t == 0 ? ones : alpha.back(), ones, steps[t], t);
    result.log_evidence_probability += answer.log_total;
    alpha.push_back(std::move(answer.interface));
  }
  // Backward: β_t, the evidence after t given slice t's interface.
  std::vector<std::vector<double>> beta(steps.size());
  beta.back() = ones;
  for (std::size_t t = steps.size() - 1; t > 0; --t) beta[t - 1] = backward(beta[t], steps[t], t);
  for (std::size_t t = 0; t < steps.size(); ++t) {
    result.steps.push_back(step(t == 0, t == 0 ? ones : alpha[t - 1], beta[t], steps[t], t).marginals);
  }
  return result;
}

PGM_DECL most_probable_steps interface_filter::most_probable(std::span<const evidence_set> steps) {
  most_probable_steps result;
  const std::size_t n = model_.size();
  // Forward: δ_t, the largest joint with the evidence so far for each state of slice t's
  // interface, scaled so that its largest is 1 (the scales' logarithms add up to ln P(x*, e)).
  std::vector<std::vector<double>> delta;
  for (std::size_t t = 0; t < steps.size(); ++t) {
    auto& in = t == 0 ? *first_max_ : *transition_max_;
    if (t > 0 && !interface_.empty()) set_if_changed(in, n, delta.back(), max_prior_);
    in.set_evidence(steps[t]);
    std::vector<double> best;
    if (interface_.empty()) {
      best = {in.total()};
    } else {
      const auto joint = in.joint(interface_);
      best.assign(joint.values().begin(), joint.values().end());
    }
    const double top = *std::max_element(best.begin(), best.end());
    if (!(top > 0.0) || !std::isfinite(top)) throw impossible_at(t, steps[t]);
    for (auto& b : best) b /= top;
    result.log_probability += std::log(top);
    delta.push_back(std::move(best));
  }
  // Back: each step maximised with the step before's δ as its prior and its own interface held
  // where the step after it put it.
  result.states.resize(steps.size());
  std::vector<std::size_t> held;  // slice t's interface states, chosen at step t + 1
  for (std::size_t t = steps.size(); t-- > 0;) {
    auto& in = t == 0 ? *first_max_ : *transition_max_;
    if (t > 0 && !interface_.empty()) set_if_changed(in, n, delta[t - 1], max_prior_);
    auto observed = steps[t];
    for (std::size_t k = 0; k < held.size(); ++k) {
      if (!observed.fixes(interface_[k])) {
        observed.hard.push_back({interface_[k], index_at<state_index>(held[k])});
      }
    }
    in.set_evidence(observed);
    const auto best = in.maximize();
    result.states[t].assign(best.states.begin(), best.states.begin() + static_cast<std::ptrdiff_t>(n));
    held.clear();
    if (t > 0) {
      for (auto id : previous_interface_) held.push_back(best.states[id.value()]);
    }
  }
  return result;
}

}  // namespace pgm
