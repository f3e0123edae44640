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

#include "pgm/core/compilation.hpp"
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
[[nodiscard]] PGM_DECL std::vector<weighted_state> prior_marginal(const transfer_problem& problem, const variable& v);

[[nodiscard]] PGM_DECL std::vector<std::size_t> match_child(const transfer_problem& problem);

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
[[nodiscard]] PGM_DECL replacement_plan direct_plan(const transfer_problem& problem);

/// Cross-Replacement's plan: u′ = u restricted to the related variables, read as their prior
/// counterparts.
[[nodiscard]] PGM_DECL replacement_plan cross_plan(const transfer_problem& problem);

/// The prior configurations u′ behind every target configuration u under `plan`, each with
/// its weight: `counts[u]` terms per u, one after the other.
struct plan_terms {
  std::vector<prior_term> terms;
  std::vector<std::uint32_t> counts;
};

[[nodiscard]] PGM_DECL plan_terms expand_plan(const replacement_plan& plan, const transfer_problem& problem);

/// The target table whose column u mixes the prior columns of u's terms by their weights,
/// with the child's states in the target's order.
[[nodiscard]] PGM_DECL std::vector<double> mix_prior_columns(const plan_terms& expanded, const replacement_plan& plan,
                                                             const cpt<double>& prior);

/// f(θ′_{·|u′(u)}) for every target configuration u under `plan`: the prior column of u′, or
/// the weighted mixture of columns where states were overlap-matched or parents marginalized.
[[nodiscard]] PGM_DECL transferred_prior evaluate_plan(const replacement_plan& plan, const transfer_problem& problem,
                                                       replacement via);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/transfer/impl/replacement_plan.ipp"
#endif
