#pragma once
/// \file
/// Prevention during a task of several actions (a tower built one cube at a time): having seen
/// the first steps of an episode, the states of the controllable variables at the next step that
/// make it likeliest that every step from there on succeeds. Judged on the dynamic network
/// unrolled to the horizon, by a junction tree compiled once, each candidate as an intervention
/// P(success at steps k … T−1 | the episode, do(controllable at k)): the robot sets them.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/dynamic_network.hpp"
#include "pgm/core/success_event.hpp"
#include "pgm/inference/query.hpp"

namespace pgm {

/// What to decide: the episode so far and what may be set.
struct prevention_over_time_request {
  /// Each step's observations over the template variables' ids, t = 0, 1, …. The step decided is
  /// the first whose success variable is not observed (after the last, when all are); it may
  /// give the controllable variables' planned states, and what else is known then.
  std::vector<evidence_set> steps;
  /// Template variables set at the step decided.
  std::vector<variable_id> controllable;
  /// A template variable and its success state.
  success_event success;
  /// Slices in all, the step decided's included; 0 for just that step.
  std::size_t horizon = 0;
};

/// The answer: the step decided, the best states and the probabilities of success.
struct prevention_over_time {
  std::size_t step = 0;
  std::size_t horizon = 0;
  /// (variable, state) of each controllable variable at `step`, in the request's order.
  std::vector<std::pair<std::string, std::string>> best;
  /// P(success at every step from `step` to horizon − 1 | the episode), the controllable
  /// variables as planned (set to the plan) or, without a whole plan, left to the model.
  double before = 0.0;
  /// The same with the controllable variables set to `best`.
  double after = 0.0;
  /// Whether the step decided gave every controllable variable's state.
  bool planned = false;
};

/// Configurations of the controllable variables that prevent_over_time tries, at most.
inline constexpr std::size_t max_prevention_candidates = std::size_t{1} << 16;

/// Decides the next step (see the file comment). The plan, when whole, stays unless another
/// setting does better by more than 1e-12 relative. Throws model_error naming what is wrong: a
/// controllable success variable, observations past the step decided, a horizon before it, more
/// than max_prevention_candidates configurations; impossible_evidence for an episode the model
/// gives probability 0.
[[nodiscard]] PGM_DECL prevention_over_time prevent_over_time(const dynamic_network& model,
                                                              const prevention_over_time_request& request);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/decide/impl/prevent_over_time.ipp"
#endif
