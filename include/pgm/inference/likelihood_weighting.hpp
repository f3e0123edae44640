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
  explicit sampler_tables(const bayesian_network& network) : order_(network.graph().topological_order()) {
    const auto n = network.size();
    cumulative_.resize(n);
    parents_.resize(n);
    strides_.resize(n);
    cards_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto& table = network.tables()[i];
      const auto j = table.child_cardinality();
      cards_[i] = j;
      parents_[i] = network.graph().parents(variable_id(static_cast<variable_id::rep>(i)));
      strides_[i] = table.parent_radix().strides();
      cumulative_[i] = cumulative_columns(table, true);
    }
  }

  [[nodiscard]] const std::vector<variable_id>& order() const noexcept { return order_; }
  [[nodiscard]] std::size_t cardinality(std::size_t node) const noexcept { return cards_[node]; }
  [[nodiscard]] std::size_t size() const noexcept { return cards_.size(); }

  /// The configuration of node's parents in `state`.
  [[nodiscard]] std::size_t configuration(std::size_t node, std::span<const std::uint32_t> state) const noexcept {
    std::size_t u = 0;
    const auto& ps = parents_[node];
    for (std::size_t p = 0; p < ps.size(); ++p) u += state[ps[p].value()] * strides_[node][p];
    return u;
  }
  /// P(node = x | configuration u), from the normalized column.
  [[nodiscard]] double probability(std::size_t node, std::size_t u, std::size_t x) const noexcept {
    const double* c = cumulative_[node].column(u);
    return c[x] - (x == 0 ? 0.0 : c[x - 1]);
  }
  /// A state drawn from column u given a uniform draw in [0, 1).
  [[nodiscard]] std::uint32_t draw(std::size_t node, std::size_t u, double uniform) const noexcept {
    const auto j = cards_[node];
    const double* c = cumulative_[node].column(u);
    std::size_t x = 0;
    while (x + 1 < j && uniform >= c[x]) ++x;
    return static_cast<std::uint32_t>(x);
  }
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
/// intervention fixed it (then its table is out of the model: no weight), and the likelihood.
struct sampler_evidence {
  std::vector<std::int64_t> fixed;
  std::vector<char> intervened;
  std::vector<std::vector<double>> likelihood;

  sampler_evidence(std::size_t n, const evidence_set& observed) : fixed(n, -1), intervened(n, 0), likelihood(n) {
    for (const auto& o : observed.hard) fixed[o.variable.value()] = o.state.value();
    for (const auto& o : observed.intervened) {
      fixed[o.variable.value()] = o.state.value();
      intervened[o.variable.value()] = 1;
    }
    for (const auto& l : observed.soft) likelihood[l.variable.value()] = l.weights;
  }
};

/// One forward sample into `state` with the evidence fixed; returns its weight, the probability
/// of the observed states times the likelihoods of soft evidence (0 as soon as it is 0).
inline double draw_weighted(const sampler_tables& tables, std::vector<std::uint32_t>& state,
                            const sampler_evidence& observed, sample_stream& stream) {
  double w = 1.0;
  for (const auto node : tables.order()) {
    const auto i = node.value();
    const auto u = tables.configuration(i, state);
    if (observed.fixed[i] >= 0) {
      state[i] = static_cast<std::uint32_t>(observed.fixed[i]);
      if (!observed.intervened[i]) w *= tables.probability(i, u, state[i]);
    } else {
      state[i] = tables.draw(i, u, stream.uniform());
    }
    if (!observed.likelihood[i].empty()) w *= observed.likelihood[i][state[i]];
    if (w == 0.0) return 0.0;
  }
  return w;
}

/// Weighted tallies of some outputs (one cell index per output, per sample), summed in order.
struct weighted_tally {
  double weight = 0.0;
  double weight_squared = 0.0;
  std::vector<double> weighted;          ///< per cell, Σ w·1[cell]
  std::vector<double> squared_weighted;  ///< per cell, Σ w²·1[cell]

  explicit weighted_tally(std::size_t cells = 0) : weighted(cells, 0.0), squared_weighted(cells, 0.0) {}
  weighted_tally& operator+=(const weighted_tally& other) {
    weight += other.weight;
    weight_squared += other.weight_squared;
    for (std::size_t c = 0; c < weighted.size(); ++c) {
      weighted[c] += other.weighted[c];
      squared_weighted[c] += other.squared_weighted[c];
    }
    return *this;
  }
};

/// How a sample becomes output cells: groups of variables, each a joint table of its own.
struct tally_layout {
  std::vector<std::vector<variable_id>> groups;
  std::vector<std::size_t> offsets;  ///< first cell of each group
  std::size_t cells = 0;

  tally_layout(std::vector<std::vector<variable_id>> of, const bayesian_network& network) : groups(std::move(of)) {
    for (const auto& g : groups) {
      offsets.push_back(cells);
      std::size_t size = 1;
      for (auto v : g) size *= network.variables()[v.value()].cardinality();
      cells += size;
    }
  }
};

/// A posterior over `group` from its cells of a tally.
[[nodiscard]] inline posterior tallied_posterior(const bayesian_network& network, std::span<const variable_id> group,
                                                 const weighted_tally& tally, std::size_t offset, std::size_t samples,
                                                 std::string engine) {
  posterior result;
  result.engine = std::move(engine);
  std::vector<std::size_t> cards;
  std::size_t size = 1;
  for (auto v : group) {
    result.variables.push_back(network.variables()[v.value()]);
    cards.push_back(result.variables.back().cardinality());
    size *= cards.back();
  }
  std::vector<double> values(size);
  result.standard_errors.resize(size);
  for (std::size_t c = 0; c < size; ++c) {
    const double p = tally.weighted[offset + c] / tally.weight;
    values[c] = p;
    const double variance = (tally.squared_weighted[offset + c] * (1.0 - 2.0 * p) + p * p * tally.weight_squared) /
                            (tally.weight * tally.weight);
    result.standard_errors[c] = std::sqrt(std::max(0.0, variance));
  }
  result.table = factor(std::vector<variable_id>(group.begin(), group.end()), std::move(cards), std::move(values));
  const double n = static_cast<double>(samples);
  result.evidence_probability = tally.weight / n;
  result.log_evidence_probability = std::log(result.evidence_probability);
  return result;
}

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
  [[nodiscard]] posterior joint(std::span<const variable_id> query) {
    const detail::tally_layout layout({std::vector<variable_id>(query.begin(), query.end())}, *network_);
    const auto tally = run(layout);
    return detail::tallied_posterior(*network_, query, tally, 0, options_.samples, std::string(name()));
  }

  /// Every one of `nodes`' marginals from one run of samples.
  [[nodiscard]] std::vector<posterior> marginals(std::span<const variable_id> nodes) {
    std::vector<std::vector<variable_id>> groups;
    for (auto v : nodes) groups.push_back({v});
    const detail::tally_layout layout(std::move(groups), *network_);
    const auto tally = run(layout);
    std::vector<posterior> result;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      result.push_back(detail::tallied_posterior(*network_, layout.groups[i], tally, layout.offsets[i],
                                                 options_.samples, std::string(name())));
    }
    return result;
  }

  /// ln of the estimated P(evidence), the mean weight; −∞ when no sample has any weight.
  [[nodiscard]] double log_probability_of_evidence() {
    const detail::tally_layout layout({}, *network_);
    return std::log(run(layout, true).weight / static_cast<double>(options_.samples));
  }

 private:
  /// The tallies of every sample; refuses evidence no sample is consistent with unless
  /// `allow_nothing` (P(evidence) is then estimated as 0).
  [[nodiscard]] detail::weighted_tally run(const detail::tally_layout& layout, bool allow_nothing = false) const {
    const detail::sampler_evidence observed(network_->size(), evidence_);
    const std::size_t blocks = (options_.samples + detail::sampling_block - 1) / detail::sampling_block;
    std::vector<detail::weighted_tally> per_block(blocks, detail::weighted_tally(layout.cells));
    detail::parallel_options parallel;
    parallel.threads = options_.threads;
    detail::parallel_for(blocks, parallel, [&](detail::item_range range) {
      std::vector<std::uint32_t> state(network_->size());
      for (std::size_t b = range.begin; b < range.end; ++b) {
        detail::sample_stream stream(detail::mix_seed(options_.seed, b));
        const std::size_t first = b * detail::sampling_block;
        const std::size_t last = std::min(options_.samples, first + detail::sampling_block);
        auto& tally = per_block[b];
        for (std::size_t s = first; s < last; ++s) {
          const double w = detail::draw_weighted(tables_, state, observed, stream);
          if (w == 0.0) continue;
          tally.weight += w;
          tally.weight_squared += w * w;
          for (std::size_t g = 0; g < layout.groups.size(); ++g) {
            std::size_t cell = 0;
            for (auto v : layout.groups[g]) cell = cell * tables_.cardinality(v.value()) + state[v.value()];
            tally.weighted[layout.offsets[g] + cell] += w;
            tally.squared_weighted[layout.offsets[g] + cell] += w * w;
          }
        }
      }
    });
    detail::weighted_tally total(layout.cells);
    for (const auto& t : per_block) total += t;
    if (!(total.weight > 0.0) && !allow_nothing) {
      throw impossible_evidence("none of " + std::to_string(options_.samples) +
                                " samples of likelihood weighting is consistent with the evidence " +
                                detail::describe(*network_, evidence_) +
                                ": it is impossible or too unlikely to sample; use an exact engine (jt, ve) or "
                                "more samples");
    }
    return total;
  }

  const bayesian_network* network_;
  detail::sampler_tables tables_;
  sampling_options options_;
  evidence_set evidence_;
};

}  // namespace pgm
