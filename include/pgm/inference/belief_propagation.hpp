#pragma once
/// \file
/// Loopy belief propagation ("bp") on any `GraphicalModel`: sum-product messages between factors
/// and variables on the factor graph, exact on a model whose factor graph is a tree and an
/// approximation on others, for models whose junction tree does not fit in memory (the
/// competition's linkage and large grid problems).
///
/// Messages are kept as natural logarithms, normalized to sum to one, so no product over-
/// or underflows, and zeros (hard constraints) stay exact as −∞. Observed variables are entered
/// by reducing the factors that hold them. Two schedules, as libDAI's BP offers:
///   - `parallel`: every message from the previous iteration's (synchronous, "flooding");
///   - `residual`: the factor whose outgoing messages would change most is updated next (Elidan,
///     McGraw and Koller 2006), which converges in fewer updates and more often.
/// Damping d mixes each new factor-to-variable message with the old one as old^d · new^(1−d).
/// Converged means no message would change by more than `tolerance` (largest absolute change in
/// probability); the result says whether it converged and after how many iterations (for the
/// residual schedule, updates divided by the number of factors).
///
/// log Z is the Bethe estimate −F_Bethe = Σ_f Σ b_f (ln φ_f − ln b_f) + Σ_v (d_v − 1) Σ b_v ln b_v,
/// exact on trees.

#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/graphical_model.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/inference/exact.hpp"
#include "pgm/inference/factor.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/inference/semiring.hpp"

namespace pgm {

enum class bp_schedule { residual, parallel };

inline constexpr std::array all_bp_schedules{bp_schedule::residual, bp_schedule::parallel};

[[nodiscard]] constexpr std::string_view to_string(bp_schedule schedule) noexcept {
  return schedule == bp_schedule::residual ? "residual" : "parallel";
}

[[nodiscard]] inline bp_schedule parse_bp_schedule(std::string_view text) {
  return parse_choice("belief propagation schedule", text, all_bp_schedules);
}

[[nodiscard]] inline std::vector<std::string> known_bp_schedules() { return names_of(all_bp_schedules); }

struct bp_options {
  bp_schedule schedule = bp_schedule::residual;
  /// 0 takes each new message as it is; 0.5 averages it with the old one (in logarithms).
  double damping = 0.0;
  double tolerance = 1e-9;
  std::size_t max_iterations = 1000;
  /// Seconds of wall-clock time after which it stops with the beliefs it has (not converged).
  double time_limit_seconds = std::numeric_limits<double>::infinity();
};

struct bp_result {
  /// Every variable's belief, in id order; a point mass on an observed one.
  std::vector<std::vector<double>> marginals;
  /// The Bethe estimate of ln Z(e).
  double log_partition = 0.0;
  bool converged = false;
  std::size_t iterations = 0;
  /// The largest message change of the last iteration.
  double residual = 0.0;
  /// Whether it stopped at options.time_limit_seconds.
  bool timed_out = false;
};

namespace detail {

/// Belief propagation over factors given as natural logarithms (−∞ for 0), the evidence already
/// entered. `cardinalities` has one entry per variable; a variable in no factor is uniform.
[[nodiscard]] PGM_DECL bp_result run_belief_propagation(const std::vector<std::size_t>& cardinalities,
                                                        const std::vector<factor_of<log_sum_product<double>>>& factors,
                                                        const bp_options& options);

}  // namespace detail

/// Loopy belief propagation on `model` with hard and soft evidence (interventions are refused:
/// they need a DAG). Throws impossible_evidence when the evidence contradicts a factor outright
/// (every state of some factor is 0 after reduction).
template <GraphicalModel M>
[[nodiscard]] bp_result belief_propagation(const M& model, const evidence_set& observed,
                                           const bp_options& options = {}) {
  using log_space = log_sum_product<double>;
  if (!observed.intervened.empty()) {
    throw model_error("belief propagation does not answer interventions (do); use jt or ve");
  }
  std::vector<std::ptrdiff_t> fixed(model.size(), -1);
  for (const auto& o : observed.hard) fixed[o.variable.value()] = static_cast<std::ptrdiff_t>(o.state.value());
  std::vector<factor_of<log_space>> factors;
  factors.reserve(model.factor_count() + observed.soft.size());
  for (std::size_t f = 0; f < model.factor_count(); ++f) {
    auto table = detail::model_factor<log_space>(model, f);
    const auto scope = table.scope();
    for (auto id : scope) {
      if (fixed[id.value()] >= 0) table = table.reduce(id, static_cast<std::size_t>(fixed[id.value()]));
    }
    factors.push_back(std::move(table));
  }
  for (const auto& l : observed.soft) {
    std::vector<double> weights;
    for (double w : l.weights) weights.push_back(log_space::from_probability(w));
    factors.emplace_back(std::vector<variable_id>{l.variable}, std::vector<std::size_t>{l.weights.size()},
                         std::move(weights));
  }
  std::vector<std::size_t> cards;
  for (std::size_t i = 0; i < model.size(); ++i) {
    // An observed variable is in no factor any more: one state, so that it adds nothing to Z.
    cards.push_back(fixed[i] >= 0 ? 1 : model.variables()[i].cardinality());
  }
  auto result = detail::run_belief_propagation(cards, factors, options);
  if (result.log_partition == log_space::zero()) detail::throw_impossible(model, observed);
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (fixed[i] < 0) continue;
    result.marginals[i].assign(model.variables()[i].cardinality(), 0.0);
    result.marginals[i][static_cast<std::size_t>(fixed[i])] = 1.0;
  }
  return result;
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/inference/impl/belief_propagation.ipp"
#endif
