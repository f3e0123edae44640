#pragma once
/// \file
/// Likelihood weighting ("lw"), for networks whose junction tree is too large: each sample draws
/// the unobserved variables forward from their tables and takes the observed ones as observed,
/// weighted by the probability of what was observed (and by the likelihood of soft evidence).
/// P(x | e) is the weighted share of x, P(e) the mean weight.
///
/// Standard errors: for the ratio estimate p = Σ w·1[x] / Σ w, the delta method gives
/// se² = Σ w²·(1[x] − p)² / (Σ w)²; for P(e), the standard error of a mean of weights.
///
/// Repeatable: blocks of detail::sampling_block samples, each from the stream of (seed, block),
/// run in parallel through the one parallel-for and summed in block order.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/detail/cumulative_columns.hpp"
#include "pgm/detail/parallel_for.hpp"
#include "pgm/detail/splitmix.hpp"
#include "pgm/inference/factor.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/inference/sampling_options.hpp"

namespace pgm {

namespace detail {

/// A network prepared for drawing samples: normalized cumulative columns, parent strides, and
/// the topological order.
class sampler_tables {
 public:
  PGM_DECL explicit sampler_tables(const bayesian_network& network);

  [[nodiscard]] const std::vector<variable_id>& order() const noexcept { return order_; }
  [[nodiscard]] std::size_t cardinality(std::size_t node) const noexcept { return cards_[node]; }
  [[nodiscard]] std::size_t size() const noexcept { return cards_.size(); }

  /// The configuration of node's parents in `state`.
  [[nodiscard]] PGM_DECL std::size_t configuration(std::size_t node,
                                                   std::span<const std::uint32_t> state) const noexcept;
  /// P(node = x | configuration u), from the normalized column.
  [[nodiscard]] double probability(std::size_t node, std::size_t u, std::size_t x) const noexcept {
    const double* c = cumulative_[node].column(u);
    return c[x] - (x == 0 ? 0.0 : c[x - 1]);
  }
  /// A state drawn from column u given a uniform draw in [0, 1).
  [[nodiscard]] PGM_DECL std::uint32_t draw(std::size_t node, std::size_t u, double uniform) const noexcept;
  [[nodiscard]] std::span<const variable_id> parents(std::size_t node) const noexcept { return parents_[node]; }
  [[nodiscard]] std::span<const std::size_t> strides(std::size_t node) const noexcept { return strides_[node]; }

 private:
  std::vector<variable_id> order_;
  std::vector<cumulative_columns> cumulative_;
  std::vector<std::vector<variable_id>> parents_;
  std::vector<std::vector<std::size_t>> strides_;
  std::vector<std::size_t> cards_;
};

/// The evidence as the samplers use it: per node, the fixed state (or none), whether an
/// intervention fixed it (then its table is out of the model: no weight), and the likelihood,
/// divided by its largest weight so that a sample's weight stays within a double whatever the
/// scale the user gave (10³⁰⁸ or 10⁻³²⁰: only ratios matter to a posterior); the logarithms of
/// those largest weights, summed, put P(evidence) back on the user's scale.
struct sampler_evidence {
  std::vector<std::int64_t> fixed;
  std::vector<char> intervened;
  std::vector<std::vector<double>> likelihood;
  double log_likelihood_scale = 0.0;

  PGM_DECL sampler_evidence(std::size_t n, const evidence_set& observed);
};

/// One forward sample into `state` with the evidence fixed; returns its weight, the probability
/// of the observed states times the likelihoods of soft evidence (0 as soon as it is 0).
PGM_DECL double draw_weighted(const sampler_tables& tables, std::vector<std::uint32_t>& state,
                              const sampler_evidence& observed, sample_stream& stream);

/// Weighted tallies of some outputs (one cell index per output, per sample), summed in order.
struct weighted_tally {
  /// sampler_evidence::log_likelihood_scale of the evidence the weights were drawn under.
  double log_likelihood_scale = 0.0;
  double weight = 0.0;
  double weight_squared = 0.0;
  std::vector<double> weighted;          ///< per cell, Σ w·1[cell]
  std::vector<double> squared_weighted;  ///< per cell, Σ w²·1[cell]

  explicit weighted_tally(std::size_t cells = 0) : weighted(cells, 0.0), squared_weighted(cells, 0.0) {}
  PGM_DECL weighted_tally& operator+=(const weighted_tally& other);
};

/// How a sample becomes output cells: groups of variables, each a joint table of its own.
struct tally_layout {
  std::vector<std::vector<variable_id>> groups;
  std::vector<std::size_t> offsets;  ///< first cell of each group
  std::size_t cells = 0;

  PGM_DECL tally_layout(std::vector<std::vector<variable_id>> of, const bayesian_network& network);
};

/// A posterior over `group` from its cells of a tally.
[[nodiscard]] PGM_DECL posterior tallied_posterior(const bayesian_network& network, std::span<const variable_id> group,
                                                   const weighted_tally& tally, std::size_t offset, std::size_t samples,
                                                   std::string engine);

}  // namespace detail

class likelihood_weighting {
 public:
  /// `network` must outlive the engine.
  explicit likelihood_weighting(const bayesian_network& network, sampling_options options = {})
      : network_(&network), tables_(network), options_(options) {
    if (options_.samples == 0) throw model_error("likelihood weighting needs at least one sample");
  }

  static constexpr bool handles_interventions = true;
  [[nodiscard]] std::string_view name() const noexcept { return "lw"; }
  [[nodiscard]] const bayesian_network& network() const noexcept { return *network_; }
  [[nodiscard]] const evidence_set& evidence() const noexcept { return evidence_; }
  [[nodiscard]] const sampling_options& options() const noexcept { return options_; }
  void set_evidence(evidence_set observed) { evidence_ = std::move(observed); }

  /// The estimated P(query | evidence), with a standard error per value.
  [[nodiscard]] PGM_DECL posterior joint(std::span<const variable_id> query);

  /// Every one of `nodes`' marginals from one run of samples.
  [[nodiscard]] PGM_DECL std::vector<posterior> marginals(std::span<const variable_id> nodes);

  /// ln of the estimated P(evidence), the mean weight; −∞ when no sample has any weight.
  [[nodiscard]] double log_probability_of_evidence() {
    const detail::tally_layout layout({}, *network_);
    const auto tally = run(layout, true);
    return std::log(tally.weight / static_cast<double>(options_.samples)) + tally.log_likelihood_scale;
  }

 private:
  /// The tallies of every sample; refuses evidence no sample is consistent with unless
  /// `allow_nothing` (P(evidence) is then estimated as 0).
  [[nodiscard]] PGM_DECL detail::weighted_tally run(const detail::tally_layout& layout,
                                                    bool allow_nothing = false) const;

  const bayesian_network* network_;
  detail::sampler_tables tables_;
  sampling_options options_;
  evidence_set evidence_;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/inference/impl/likelihood_weighting.ipp"
#endif
