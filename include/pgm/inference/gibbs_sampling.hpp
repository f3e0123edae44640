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
#include "pgm/detail/parallel_for.hpp"
#include "pgm/detail/splitmix.hpp"
#include "pgm/inference/likelihood_weighting.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/inference/sampling_options.hpp"

namespace pgm {

class gibbs_sampling {
 public:
  /// `network` must outlive the engine.
  explicit gibbs_sampling(const bayesian_network& network, sampling_options options = {})
      : network_(&network), tables_(network), weighting_(network, options), options_(options) {
    if (options_.chains == 0) throw model_error("Gibbs sampling needs at least one chain");
    if (options_.samples < options_.chains) {
      throw model_error("Gibbs sampling needs at least one sample per chain (" + std::to_string(options_.chains) +
                        " chains, " + std::to_string(options_.samples) + " samples)");
    }
    const auto n = network.size();
    children_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto parents = network.graph().parents(variable_id(static_cast<variable_id::rep>(i)));
      for (std::size_t p = 0; p < parents.size(); ++p) {
        children_[parents[p].value()].push_back({i, tables_.strides(i)[p]});
      }
    }
  }

  static constexpr bool handles_interventions = true;
  [[nodiscard]] std::string_view name() const noexcept { return "gibbs"; }
  [[nodiscard]] const bayesian_network& network() const noexcept { return *network_; }
  [[nodiscard]] const evidence_set& evidence() const noexcept { return evidence_; }
  void set_evidence(evidence_set observed) {
    evidence_ = observed;
    weighting_.set_evidence(std::move(observed));
    log_evidence_.reset();
  }

  [[nodiscard]] posterior joint(std::span<const variable_id> query) {
    const detail::tally_layout layout({std::vector<variable_id>(query.begin(), query.end())}, *network_);
    return estimates(layout).front();
  }

  [[nodiscard]] std::vector<posterior> marginals(std::span<const variable_id> nodes) {
    std::vector<std::vector<variable_id>> groups;
    for (auto v : nodes) groups.push_back({v});
    return estimates(detail::tally_layout(std::move(groups), *network_));
  }

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

  [[nodiscard]] std::vector<posterior> estimates(const detail::tally_layout& layout) {
    const double log_evidence = log_probability_of_evidence();
    const detail::sampler_evidence observed(network_->size(), evidence_);
    const std::size_t chains = options_.chains;
    const std::size_t per_chain = options_.samples / chains;
    const std::size_t per_batch = std::max<std::size_t>(1, per_chain / batches_per_chain);
    const std::size_t batches = per_chain / per_batch;
    // counts[chain][batch][cell]
    std::vector<std::vector<std::vector<double>>> counts(
        chains, std::vector<std::vector<double>>(batches, std::vector<double>(layout.cells, 0.0)));
    detail::parallel_options parallel;
    parallel.threads = options_.threads;
    detail::parallel_for(chains, parallel, [&](detail::item_range range) {
      for (std::size_t c = range.begin; c < range.end; ++c) run_chain(c, observed, layout, per_batch, counts[c]);
    });
    std::vector<posterior> result;
    for (std::size_t g = 0; g < layout.groups.size(); ++g) {
      const auto& group = layout.groups[g];
      posterior p;
      p.engine = std::string(name());
      std::vector<std::size_t> cards;
      std::size_t size = 1;
      for (auto v : group) {
        p.variables.push_back(network_->variables()[v.value()]);
        cards.push_back(p.variables.back().cardinality());
        size *= cards.back();
      }
      std::vector<double> values(size, 0.0);
      p.standard_errors.assign(size, 0.0);
      const double all_batches = static_cast<double>(chains * batches);
      for (std::size_t cell = 0; cell < size; ++cell) {
        double sum = 0.0;
        double sum_squares = 0.0;
        for (std::size_t c = 0; c < chains; ++c) {
          for (std::size_t b = 0; b < batches; ++b) {
            const double mean = counts[c][b][layout.offsets[g] + cell] / static_cast<double>(per_batch);
            sum += mean;
            sum_squares += mean * mean;
          }
        }
        const double mean = sum / all_batches;
        values[cell] = mean;
        const double spread = all_batches > 1 ? (sum_squares - all_batches * mean * mean) / (all_batches - 1) : 0.0;
        p.standard_errors[cell] = std::sqrt(std::max(0.0, spread) / all_batches);
      }
      p.table = factor(group, std::move(cards), std::move(values));
      p.log_evidence_probability = log_evidence;
      p.evidence_probability = std::exp(log_evidence);
      result.push_back(std::move(p));
    }
    return result;
  }

  void run_chain(std::size_t chain, const detail::sampler_evidence& observed, const detail::tally_layout& layout,
                 std::size_t per_batch, std::vector<std::vector<double>>& counts) const {
    detail::sample_stream stream(detail::mix_seed(options_.seed ^ 0x6962626773ULL, chain));
    std::vector<std::uint32_t> state(network_->size());
    if (!start(state, observed, stream)) {
      throw impossible_evidence("Gibbs sampling found no state consistent with the evidence " +
                                detail::describe(*network_, evidence_) + " in " + std::to_string(start_attempts) +
                                " forward samples: it is impossible or too unlikely; use an exact engine (jt, ve)");
    }
    std::vector<std::size_t> free;
    for (auto node : tables_.order()) {
      if (observed.fixed[node.value()] < 0) free.push_back(node.value());
    }
    std::vector<double> weights;
    for (std::size_t sweep = 0; sweep < options_.burn_in; ++sweep) step(state, free, observed, stream, weights);
    for (std::size_t b = 0; b < counts.size(); ++b) {
      for (std::size_t s = 0; s < per_batch; ++s) {
        step(state, free, observed, stream, weights);
        for (std::size_t g = 0; g < layout.groups.size(); ++g) {
          std::size_t cell = 0;
          for (auto v : layout.groups[g]) cell = cell * tables_.cardinality(v.value()) + state[v.value()];
          counts[b][layout.offsets[g] + cell] += 1.0;
        }
      }
    }
  }

  /// A forward sample with the evidence clamped and nonzero weight.
  bool start(std::vector<std::uint32_t>& state, const detail::sampler_evidence& observed,
             detail::sample_stream& stream) const {
    for (std::size_t attempt = 0; attempt < start_attempts; ++attempt) {
      if (detail::draw_weighted(tables_, state, observed, stream) > 0.0) return true;
    }
    return false;
  }

  /// One sweep: every free variable redrawn from its distribution given its Markov blanket.
  void step(std::vector<std::uint32_t>& state, std::span<const std::size_t> free,
            const detail::sampler_evidence& observed, detail::sample_stream& stream,
            std::vector<double>& weights) const {
    for (const auto i : free) {
      const auto j = tables_.cardinality(i);
      const auto before = state[i];
      weights.assign(j, 0.0);
      const auto u = tables_.configuration(i, state);
      double total = 0.0;
      for (std::size_t x = 0; x < j; ++x) {
        double w = tables_.probability(i, u, x);
        if (!observed.likelihood[i].empty()) w *= observed.likelihood[i][x];
        state[i] = static_cast<std::uint32_t>(x);
        for (const auto& child : children_[i]) {
          if (w == 0.0) break;
          if (observed.intervened[child.node]) continue;  // its table is out of the mutilated model
          w *= tables_.probability(child.node, tables_.configuration(child.node, state), state[child.node]);
        }
        weights[x] = w;
        total += w;
      }
      // A state the blanket gives no weight stays where it is (it cannot arise from a valid start).
      double draw = stream.uniform() * total;
      std::uint32_t chosen = 0;
      while (chosen + 1 < j && draw >= weights[chosen]) draw -= weights[chosen++];
      state[i] = total > 0.0 ? chosen : before;
    }
  }

  const bayesian_network* network_;
  detail::sampler_tables tables_;
  likelihood_weighting weighting_;
  sampling_options options_;
  evidence_set evidence_;
  std::vector<std::vector<child_link>> children_;
  std::optional<double> log_evidence_;
};

}  // namespace pgm
