#pragma once
/// \file
/// Gibbs sampling on any `GraphicalModel` ("gibbs" for `pgm solve` and `pgm.MarkovNetwork`): one
/// chain sweeping the unobserved variables in id order, each drawn from its distribution given
/// the others, P(x_v | rest) ∝ Π over the factors that hold v. The marginals are the
/// Rao–Blackwellized estimates, the average of those conditional distributions over the sweeps
/// after the burn-in, which have less variance than counts of the states drawn.
///
/// The same seed gives the same numbers on any machine: the chain draws from pgm's own SplitMix64
/// stream (pgm/detail/splitmix.hpp), not a standard library's distributions. A chain mixes only
/// where it can move: with zeros in the factors, some states may be out of its reach from the
/// state it starts in (each variable's first state allowed by the factors it is in, one by one);
/// the result says when a variable's conditional was all zeros, where it drew uniformly.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "pgm/core/graphical_model.hpp"
#include "pgm/detail/splitmix.hpp"
#include "pgm/inference/exact.hpp"
#include "pgm/inference/factor.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/inference/semiring.hpp"

namespace pgm {

struct factor_gibbs_options {
  std::size_t sweeps = 10'000;
  std::size_t burn_in = 1'000;
  std::uint64_t seed = 1;
  /// Seconds of wall-clock time after which the chain stops with the sweeps it has kept.
  double time_limit_seconds = std::numeric_limits<double>::infinity();
};

struct factor_gibbs_result {
  /// Every variable's estimated marginal, in id order; a point mass on an observed one.
  std::vector<std::vector<double>> marginals;
  /// The draws whose conditional had no positive state (drawn uniformly instead).
  std::size_t stuck_draws = 0;
  /// The sweeps kept: options.sweeps unless the time limit stopped the chain first.
  std::size_t sweeps = 0;
  bool timed_out = false;
};

/// Gibbs sampling on `model` with hard and soft evidence (interventions are refused).
template <GraphicalModel M>
[[nodiscard]] factor_gibbs_result factor_gibbs(const M& model, const evidence_set& observed,
                                               const factor_gibbs_options& options = {}) {
  if (!observed.intervened.empty())
    throw model_error("Gibbs sampling does not answer interventions (do); use jt or ve");
  const auto n = model.size();
  std::vector<std::ptrdiff_t> fixed(n, -1);
  for (const auto& o : observed.hard) fixed[o.variable.value()] = static_cast<std::ptrdiff_t>(o.state.value());
  // The factors in probabilities, each soft evidence one more, and which hold each variable.
  std::vector<factor> factors;
  for (std::size_t f = 0; f < model.factor_count(); ++f) {
    factors.push_back(detail::model_factor<sum_product<double>>(model, f));
  }
  for (const auto& l : observed.soft)
    factors.emplace_back(std::vector<variable_id>{l.variable}, std::vector<std::size_t>{l.weights.size()}, l.weights);
  std::vector<std::vector<std::size_t>> holding(n);
  for (std::size_t f = 0; f < factors.size(); ++f) {
    for (auto v : factors[f].scope()) holding[v.value()].push_back(f);
  }
  std::vector<std::size_t> state(n, 0);
  for (std::size_t v = 0; v < n; ++v) {
    if (fixed[v] >= 0) state[v] = static_cast<std::size_t>(fixed[v]);
  }
  auto value_at = [&](const factor& f) {
    std::size_t index = 0;
    for (std::size_t k = 0; k < f.scope().size(); ++k)
      index = index * f.cardinalities()[k] + state[f.scope()[k].value()];
    return f.values()[index];
  };
  factor_gibbs_result result;
  result.marginals.resize(n);
  for (std::size_t v = 0; v < n; ++v) result.marginals[v].assign(model.variables()[v].cardinality(), 0.0);
  std::vector<double> conditional;
  std::uint64_t draws = 0;
  auto sweep = [&](bool keep, bool starting) {
    for (std::size_t v = 0; v < n; ++v) {
      if (fixed[v] >= 0) continue;
      const auto card = model.variables()[v].cardinality();
      conditional.assign(card, 1.0);
      double total = 0.0;
      for (std::size_t x = 0; x < card; ++x) {
        state[v] = x;
        for (const auto f : holding[v]) conditional[x] *= value_at(factors[f]);
        total += conditional[x];
      }
      const double u = static_cast<double>(detail::mix_seed(options.seed, draws++) >> 11) * 0x1p-53;
      std::size_t chosen = card - 1;
      if (!(total > 0.0) || !std::isfinite(total)) {
        if (!starting) ++result.stuck_draws;
        chosen = std::min(card - 1, static_cast<std::size_t>(u * static_cast<double>(card)));
        conditional.assign(card, 1.0 / static_cast<double>(card));
      } else {
        for (auto& p : conditional) p /= total;
        double running = 0.0;
        for (std::size_t x = 0; x < card; ++x) {
          running += conditional[x];
          if (u < running) {
            chosen = x;
            break;
          }
        }
      }
      if (starting) {  // the first state the factors allow, given the states set so far
        chosen = static_cast<std::size_t>(
            std::find_if(conditional.begin(), conditional.end(), [](double p) { return p > 0.0; }) -
            conditional.begin());
      }
      state[v] = chosen;
      if (keep) {
        for (std::size_t x = 0; x < card; ++x) result.marginals[v][x] += conditional[x];
      }
    }
  };
  const auto started = std::chrono::steady_clock::now();
  const auto past_time_limit = [&] {
    const std::chrono::duration<double> spent = std::chrono::steady_clock::now() - started;
    return spent.count() > options.time_limit_seconds;
  };
  sweep(false, true);
  for (std::size_t s = 0; s < options.burn_in && !result.timed_out; ++s) {
    sweep(false, false);
    result.timed_out = past_time_limit();
  }
  while (result.sweeps < options.sweeps && !result.timed_out) {
    sweep(true, false);
    ++result.sweeps;
    result.timed_out = past_time_limit();
  }
  for (std::size_t v = 0; v < n; ++v) {
    if (fixed[v] >= 0) {
      result.marginals[v][static_cast<std::size_t>(fixed[v])] = 1.0;
      continue;
    }
    if (result.sweeps == 0) {  // stopped before the first kept sweep: the state it reached
      result.marginals[v][state[v]] = 1.0;
      continue;
    }
    for (auto& p : result.marginals[v]) p /= static_cast<double>(result.sweeps);
  }
  return result;
}

}  // namespace pgm
