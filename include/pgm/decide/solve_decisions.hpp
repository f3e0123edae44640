#pragma once
/// \file
/// The best policy of an influence diagram (pgm/core/influence_diagram.hpp) and what it is
/// worth: the maximum expected utility (MEU), an optimal action for every decision given what it
/// observes, the expected utility of a given policy, and the value of observing a chance
/// variable before a decision.
///
/// Two readings of what a decision knows:
/// - **perfect recall** (the default): a decision knows what every earlier decision knew and
///   chose. Exact, by variable elimination over pairs of probability and utility potentials
///   (Jensen, Jensen & Dittmer 1994): the variables nobody observes are summed first, then the
///   last decision is maximized, then what it observed is summed, and so on back to the first.
/// - **limited memory** (a LIMID, Lauritzen & Nilsson 2001): a decision knows its parents only.
///   Single policy updating, from uniform policies, replaces one decision's policy at a time by
///   its best answer to the others until none improves: the expected utility never falls, and
///   the result is a local optimum (the global one on a diagram with perfect recall).
///
/// Evidence is what is observed before the first decision: the MEU is then E[U | evidence].

#include <cstddef>
#include <string_view>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/influence_diagram.hpp"
#include "pgm/inference/query.hpp"

namespace pgm {

struct decision_options {
  /// Each decision knows its parents only; solved by single policy updating.
  bool limited_memory = false;
};

struct decision_solution {
  /// The expected utility of the policies (the maximum, unless `local_optimum`).
  double meu = 0;
  /// One per decision, in the order they are taken. With perfect recall a policy lists the
  /// decision's parents and every earlier observation or choice its best action depends on.
  /// Observed evidence is in no policy.
  std::vector<decision_policy> policies;
  /// Single policy updating stopped where no one decision improves: it may not be the maximum.
  bool local_optimum = false;
  /// Single policy updating: the expected utility of the uniform policies it started from, and
  /// the rounds over every decision it took.
  double start_expected_utility = 0;
  std::size_t rounds = 0;
};

/// The optimal policies and their expected utility given `observed` (chance variables that no
/// decision influences, by state label). Throws model_error for an evidence variable that is a
/// decision or that a decision influences, or evidence of probability 0.
[[nodiscard]] PGM_DECL decision_solution solve_decisions(const influence_diagram& diagram,
                                                         const evidence& observed = {},
                                                         const decision_options& options = {});

/// The expected utility, given `observed`, of acting by `policies` (one per decision).
[[nodiscard]] PGM_DECL double expected_utility(const influence_diagram& diagram,
                                               const std::vector<decision_policy>& policies,
                                               const evidence& observed = {});

/// The diagram in which `chance` is also known when `decision` is taken. Throws model_error
/// when `chance` depends on `decision` (it cannot be known before it).
[[nodiscard]] PGM_DECL influence_diagram observing(const influence_diagram& diagram, variable_id chance,
                                                   variable_id decision);

/// The value of perfect information of `chance` at `decision`: the MEU when it is known there
/// (and, with perfect recall, at every later decision) less the MEU without. Never negative with
/// perfect recall; under limited memory both are local optima, so it may be.
[[nodiscard]] PGM_DECL double value_of_information(const influence_diagram& diagram, std::string_view chance,
                                                   std::string_view decision, const evidence& observed = {},
                                                   const decision_options& options = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/decide/impl/solve_decisions.ipp"
#endif
