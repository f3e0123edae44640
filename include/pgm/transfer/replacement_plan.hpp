#pragma once
/// \file
/// The building block of every replacement strategy: a `replacement_plan` says, for each
/// parent of the prior node X′, where its state comes from — a target parent (through a state
/// mapping) or a fixed distribution (a pinned value, or the prior's marginal) — and
/// `evaluate_plan` turns the plan into the prior table f(θ′_{·|u′(u)}) for every target u.
/// Direct- and Cross-Replacement differ only in how they build the plan.

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/transfer/state_map.hpp"
#include "pgm/transfer/transfer_problem.hpp"

namespace pgm {

/// Where one prior parent's state comes from.
struct parent_source {
  /// The target parent that supplies it, with how its states map; or none.
  std::optional<std::size_t> target_parent;
  state_mapping mapping;
  /// Without a target parent: a fixed distribution over the prior parent's states.
  std::vector<weighted_state> fixed;
};

struct replacement_plan {
  std::vector<parent_source> parents;    ///< one per parent of the prior node, in its order
  std::vector<std::size_t> child_state;  ///< prior child state of each target child state
};

namespace detail {

/// The prior's distribution of a root variable: what marginalizing it means.
[[nodiscard]] inline std::vector<weighted_state> prior_marginal(const transfer_problem& problem, const variable& v) {
  const auto* network = problem.prior_network();
  if (!network) {
    throw model_error("marginalizing the prior's '" + v.name() + "' needs the prior network, not only its table");
  }
  const auto& table = network->table(v.name());
  if (!table.parents().empty()) {
    throw model_error("the prior's '" + v.name() +
                      "' has parents, so its marginal would need inference; pin it to a value instead");
  }
  std::vector<weighted_state> shares;
  for (std::size_t s = 0; s < v.cardinality(); ++s) {
    const double p = table.column(config_index(0))[s];
    if (p > 0) shares.push_back({s, p});
  }
  return shares;
}

[[nodiscard]] inline std::vector<std::size_t> match_child(const transfer_problem& problem) {
  const auto& target = problem.target_child();
  const auto& prior = problem.prior_table().child();
  const auto mapping = map_states(target, prior);
  std::vector<std::size_t> child(mapping.size());
  std::vector<bool> used(prior.cardinality(), false);
  for (std::size_t s = 0; s < mapping.size(); ++s) {
    child[s] = mapping[s].front().state;
    if (used[child[s]]) break;
    used[child[s]] = true;
  }
  if (target.cardinality() != prior.cardinality() || std::find(used.begin(), used.end(), false) != used.end()) {
    throw model_error("the states of '" + target.name() + "' {" + list_for_message(target.states()) +
                      "} and of the prior's '" + prior.name() + "' {" + list_for_message(prior.states()) +
                      "} do not correspond one to one");
  }
  return child;
}

}  // namespace detail

/// A plan assigning each prior parent from the target parent that `counterpart` names (the
/// prior variable a target variable stands for, if any); `strategy` names the strategy in
/// errors. Unassigned prior parents take their pin from the map, or it is an error.
template <class Counterpart>
[[nodiscard]] replacement_plan make_plan(const transfer_problem& problem, Counterpart counterpart,
                                         const std::string& strategy) {
  const auto& prior = problem.prior_table();
  replacement_plan plan;
  plan.child_state = detail::match_child(problem);
  std::size_t assigned = 0;
  for (const auto& prior_parent : prior.parents()) {
    parent_source source;
    for (std::size_t t = 0; t < problem.target_parents().size(); ++t) {
      const auto& target_parent = problem.target_parents()[t];
      if (counterpart(target_parent.name()) != std::optional<std::string>(prior_parent.name())) continue;
      if (source.target_parent) {
        throw model_error(strategy + ": both '" + problem.target_parents()[*source.target_parent].name() + "' and '" +
                          target_parent.name() + "' stand for the prior's '" + prior_parent.name() + "'");
      }
      source.target_parent = t;
      source.mapping = map_states(target_parent, prior_parent, problem.options().matching);
    }
    if (source.target_parent) {
      ++assigned;
    } else if (const auto pin = problem.map().pinned.find(prior_parent.name()); pin != problem.map().pinned.end()) {
      source.fixed = pin->second.marginalize()
                         ? detail::prior_marginal(problem, prior_parent)
                         : std::vector<weighted_state>{{pinned_state(prior_parent, pin->second.value), 1.0}};
    } else {
      throw model_error(strategy + " leaves the prior's parent '" + prior_parent.name() + "' of '" +
                        prior.child().name() + "' unassigned: no parent of '" + problem.target_child().name() +
                        "' corresponds to it; pin it with '" + prior_parent.name() +
                        "@<value>' or marginalize it with '" + prior_parent.name() + "@*'");
    }
    plan.parents.push_back(std::move(source));
  }
  if (!prior.parents().empty() && assigned == 0) {
    throw model_error(strategy + ": no parent of '" + problem.target_child().name() +
                      "' corresponds to a parent of the prior's '" + prior.child().name() + "'");
  }
  return plan;
}

/// Direct-Replacement's plan: u′ = u restricted to Pa_X′ ∩ Pa_X (identical variables).
[[nodiscard]] inline replacement_plan direct_plan(const transfer_problem& problem) {
  const auto& map = problem.map();
  return make_plan(
      problem, [&](const std::string& target) { return std::optional(map.identical_to(target)); },
      "Direct-Replacement");
}

/// Cross-Replacement's plan: u′ = u restricted to the related variables, read as their prior
/// counterparts.
[[nodiscard]] inline replacement_plan cross_plan(const transfer_problem& problem) {
  const auto& map = problem.map();
  return make_plan(
      problem, [&](const std::string& target) { return map.related_to(target); }, "Cross-Replacement");
}

/// The prior configurations u′ behind every target configuration u under `plan`, each with
/// its weight: `counts[u]` terms per u, one after the other.
struct plan_terms {
  std::vector<prior_term> terms;
  std::vector<std::uint32_t> counts;
};

[[nodiscard]] inline plan_terms expand_plan(const replacement_plan& plan, const transfer_problem& problem) {
  const auto& prior_strides = problem.prior_table().parent_radix().strides();
  const auto& targets = problem.target_parents();
  std::vector<std::size_t> target_cards;
  for (const auto& t : targets) target_cards.push_back(t.cardinality());
  const mixed_radix target_radix(std::move(target_cards));
  const std::size_t k = plan.parents.size();
  plan_terms out;
  out.counts.resize(target_radix.size());
  std::vector<std::size_t> digits(targets.size(), 0);

  const bool single = std::all_of(plan.parents.begin(), plan.parents.end(), [](const parent_source& s) {
    if (!s.target_parent) return s.fixed.size() == 1;
    return std::all_of(s.mapping.begin(), s.mapping.end(), [](const auto& m) { return m.size() == 1; });
  });
  if (single) {
    // One u′ per u: u′'s index is a fixed part plus one offset per target parent digit, so
    // walking u in order only adjusts the sum by the digits that change.
    std::size_t fixed = 0;
    std::vector<std::size_t> first_offset(targets.size() + 1, 0);
    for (std::size_t t = 0; t < targets.size(); ++t) first_offset[t + 1] = first_offset[t] + targets[t].cardinality();
    std::vector<std::size_t> offset(first_offset.back(), 0);
    for (std::size_t p = 0; p < k; ++p) {
      const auto& source = plan.parents[p];
      if (!source.target_parent) {
        fixed += source.fixed.front().state * prior_strides[p];
        continue;
      }
      for (std::size_t s = 0; s < source.mapping.size(); ++s) {
        offset[first_offset[*source.target_parent] + s] += source.mapping[s].front().state * prior_strides[p];
      }
    }
    out.terms.resize(target_radix.size());
    std::fill(out.counts.begin(), out.counts.end(), 1U);
    std::size_t configuration = fixed;
    for (std::size_t t = 0; t < targets.size(); ++t) configuration += offset[first_offset[t]];
    for (std::size_t u = 0; u < target_radix.size(); ++u) {
      out.terms[u] = {static_cast<std::uint32_t>(configuration), 1.0};
      for (std::size_t d = digits.size(); d > 0; --d) {
        const std::size_t t = d - 1;
        configuration -= offset[first_offset[t] + digits[t]];
        if (++digits[t] == target_radix.radix(t)) digits[t] = 0;
        configuration += offset[first_offset[t] + digits[t]];
        if (digits[t] != 0) break;
      }
    }
    return out;
  }

  std::vector<const std::vector<weighted_state>*> choices(k);
  std::vector<std::size_t> pick(k);
  for (std::size_t u = 0; u < target_radix.size(); ++u) {
    for (std::size_t p = 0; p < k; ++p) {
      const auto& source = plan.parents[p];
      choices[p] = source.target_parent ? &source.mapping[digits[*source.target_parent]] : &source.fixed;
    }
    // Odometer over the combinations of weighted prior states.
    std::fill(pick.begin(), pick.end(), 0);
    std::uint32_t count = 0;
    while (true) {
      std::size_t configuration = 0;
      double weight = 1.0;
      for (std::size_t p = 0; p < k; ++p) {
        const auto& chosen = (*choices[p])[pick[p]];
        configuration += chosen.state * prior_strides[p];
        weight *= chosen.weight;
      }
      out.terms.push_back({static_cast<std::uint32_t>(configuration), weight});
      ++count;
      std::size_t p = k;
      while (p > 0 && ++pick[p - 1] == choices[p - 1]->size()) pick[--p] = 0;
      if (p == 0) break;
    }
    out.counts[u] = count;
    for (std::size_t d = digits.size(); d > 0 && ++digits[d - 1] == target_radix.radix(d - 1);) digits[--d] = 0;
  }
  return out;
}

/// The target table whose column u mixes the prior columns of u's terms by their weights,
/// with the child's states in the target's order.
[[nodiscard]] inline std::vector<double> mix_prior_columns(const plan_terms& expanded, const replacement_plan& plan,
                                                           const cpt<double>& prior) {
  const std::size_t j = plan.child_state.size();
  std::vector<double> values(expanded.counts.size() * j, 0.0);
  // A sparse prior table (fitted from few rows) is read column by column, as it is stored.
  const double* dense = prior.is_sparse() ? nullptr : prior.values().data();
  std::size_t next = 0;
  for (std::size_t u = 0; u < expanded.counts.size(); ++u) {
    for (std::uint32_t n = 0; n < expanded.counts[u]; ++n, ++next) {
      const auto& term = expanded.terms[next];
      const double* column =
          dense ? dense + std::size_t{term.configuration} * j : prior.column(config_index(term.configuration)).data();
      for (std::size_t x = 0; x < j; ++x) values[u * j + x] += term.weight * column[plan.child_state[x]];
    }
  }
  return values;
}

/// f(θ′_{·|u′(u)}) for every target configuration u under `plan`: the prior column of u′, or
/// the weighted mixture of columns where states were overlap-matched or parents marginalized.
[[nodiscard]] inline transferred_prior evaluate_plan(const replacement_plan& plan, const transfer_problem& problem,
                                                     replacement via) {
  auto expanded = expand_plan(plan, problem);
  auto values = mix_prior_columns(expanded, plan, problem.prior_table());
  const auto configurations = expanded.counts.size();
  return transferred_prior(cpt<double>(problem.target_child(), problem.target_parents(), std::move(values)),
                           problem.prior_table().parents(), std::move(expanded.terms), std::move(expanded.counts),
                           std::vector<replacement>(configurations, via));
}

}  // namespace pgm
