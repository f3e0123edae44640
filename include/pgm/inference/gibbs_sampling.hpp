#pragma once
/// \file
/// Gibbs sampling ("gibbs"): independent Markov chains over the unobserved variables, each step
/// redrawing one variable from its distribution given its Markov blanket,
/// P(x | mb) ∝ P(x | pa)·Π_children P(child | its parents)·λ(x) for soft evidence λ. A sweep
/// redraws every unobserved variable once, in topological order; each chain discards
/// `burn_in` sweeps, then counts one sample per sweep.
///
/// Each chain starts from a forward sample consistent with the evidence (found by likelihood
/// weighting's draws, up to 10,000 tries). Tables with zeros can split the states into parts a
/// chain cannot leave; the chains' spread then shows in the standard errors, which come from
/// batch means: each chain's samples cut into 10 batches, se = sd(batch means)/√batches.
/// P(evidence) is not what Gibbs sampling estimates: posteriors carry likelihood weighting's
/// estimate, from as many samples.
///
/// Repeatable: chain c draws from the stream of (seed, c); chains run in parallel and are
/// combined in chain order.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/detail/parallel_for.hpp"
#include "pgm/detail/splitmix.hpp"
#include "pgm/inference/likelihood_weighting.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/inference/sampling_options.hpp"

namespace pgm {

class gibbs_sampling {
 public:
  /// `network` must outlive the engine.
  PGM_DECL explicit gibbs_sampling(const bayesian_network& network, sampling_options options = {});

  static constexpr bool handles_interventions = true;
  [[nodiscard]] std::string_view name() const noexcept { return "gibbs"; }
  [[nodiscard]] const bayesian_network& network() const noexcept { return *network_; }
  [[nodiscard]] const evidence_set& evidence() const noexcept { return evidence_; }
  PGM_DECL void set_evidence(evidence_set observed);

  [[nodiscard]] posterior joint(std::span<const variable_id> query) {
    const detail::tally_layout layout({std::vector<variable_id>(query.begin(), query.end())}, *network_);
    return estimates(layout).front();
  }

  [[nodiscard]] PGM_DECL std::vector<posterior> marginals(std::span<const variable_id> nodes);

  /// Likelihood weighting's estimate (see the file comment).
  [[nodiscard]] double log_probability_of_evidence() {
    if (!log_evidence_) log_evidence_ = weighting_.log_probability_of_evidence();
    return *log_evidence_;
  }

 private:
  static constexpr std::size_t batches_per_chain = 10;
  static constexpr std::size_t start_attempts = 10'000;

  struct child_link {
    std::size_t node;
    std::size_t stride;  ///< of the parent in the child's configuration numbering
  };

  [[nodiscard]] PGM_DECL std::vector<posterior> estimates(const detail::tally_layout& layout);

  PGM_DECL void run_chain(std::size_t chain, const detail::sampler_evidence& observed,
                          const detail::tally_layout& layout, std::size_t per_batch,
                          std::vector<std::vector<double>>& counts) const;

  /// A forward sample with the evidence clamped and nonzero weight.
  PGM_DECL bool start(std::vector<std::uint32_t>& state, const detail::sampler_evidence& observed,
                      detail::sample_stream& stream) const;

  /// One sweep: every free variable redrawn from its distribution given its Markov blanket.
  PGM_DECL void step(std::vector<std::uint32_t>& state, std::span<const std::size_t> free,
                     const detail::sampler_evidence& observed, detail::sample_stream& stream,
                     std::vector<double>& weights) const;

  const bayesian_network* network_;
  detail::sampler_tables tables_;
  likelihood_weighting weighting_;
  sampling_options options_;
  evidence_set evidence_;
  std::vector<std::vector<child_link>> children_;
  std::optional<double> log_evidence_;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/inference/impl/gibbs_sampling.ipp"
#endif
