#pragma once
/// \file
/// The paper's parameter metrics (Sec. IV-C) over the parameters it counts: the success
/// state's θ_{success|u} for every parent configuration u of the success node (625 for
/// 2-Stack's onTop2). Max-Difference is the largest |θ − θ*|, Mean-Difference their average, so
/// Mean ≤ Max always (docs/decisions.md: the formula read literally with both states of a binary
/// child would double the mean; the text counts 625 parameters, and we follow the text).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>

#include "pgm/core/compilation.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"

namespace pgm {

/// What the experiment measures of an estimate (the `metric` column of its tables).
enum class experiment_metric {
  max_difference,      ///< Max-Difference against θ*
  mean_difference,     ///< Mean-Difference against θ*
  failure_prevention,  ///< the share of failures prevented
  chosen_w,            ///< the weight an automatic line chose
  // With move costs (experiment_options::costs): the ε-rule's cost, and the rule of highest
  // expected utility's success and cost (pgm/decide/prevent_by_utility.hpp).
  prevention_cost,         ///< the mean cost of the ε-rule's moves
  utility_prevention,      ///< success after the moves of highest expected utility
  utility_prevention_cost  ///< the mean cost of those moves
};

inline constexpr std::array experiment_metrics{
    experiment_metric::max_difference,         experiment_metric::mean_difference,
    experiment_metric::failure_prevention,     experiment_metric::chosen_w,
    experiment_metric::prevention_cost,        experiment_metric::utility_prevention,
    experiment_metric::utility_prevention_cost};

[[nodiscard]] constexpr std::string_view to_string(experiment_metric metric) noexcept {
  switch (metric) {
    case experiment_metric::max_difference:
      return "max_difference";
    case experiment_metric::mean_difference:
      return "mean_difference";
    case experiment_metric::failure_prevention:
      return "failure_prevention";
    case experiment_metric::chosen_w:
      return "chosen_w";
    case experiment_metric::prevention_cost:
      return "prevention_cost";
    case experiment_metric::utility_prevention:
      return "utility_prevention";
    case experiment_metric::utility_prevention_cost:
      return "utility_prevention_cost";
  }
  return "?";
}

/// The metric named `text`; throws unknown_name otherwise.
[[nodiscard]] inline experiment_metric parse_experiment_metric(std::string_view text) {
  return parse_choice("metric", text, experiment_metrics);
}

struct parameter_difference {
  double max = 0;
  double mean = 0;
};

/// Max- and Mean-Difference of the success state's parameters between an estimate and the
/// ground truth of the same shape.
[[nodiscard]] PGM_DECL parameter_difference success_parameter_difference(const cpt<double>& estimate,
                                                                         const cpt<double>& truth,
                                                                         std::size_t success_state);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/eval/impl/metrics.ipp"
#endif
