#pragma once
// The definitions of pgm/inference/gibbs_sampling.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/inference/gibbs_sampling.hpp"

namespace pgm {

PGM_DECL gibbs_sampling::gibbs_sampling(const bayesian_network& network, sampling_options options)
    : network_(&network), tables_(network), weighting_(network, options), options_(options) {
  if (options_.chains == 0) throw model_error("Gibbs sampling needs at least one chain");
  if (options_.samples < options_.chains) {
    throw model_error("Gibbs sampling needs at least one sample per chain (" + std::to_string(options_.chains) +
                      " chains, " + std::to_string(options_.samples) + " samples)");
  }
  const auto n = network.size();
  children_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto parents = network.graph().parents(index_at<variable_id>(i));
    for (std::size_t p = 0; p < parents.size(); ++p) {
      children_[parents[p].value()].push_back({i, tables_.strides(i)[p]});
    }
  }
}

PGM_DECL void gibbs_sampling::set_evidence(evidence_set observed) {
  evidence_ = observed;
  weighting_.set_evidence(std::move(observed));
  log_evidence_.reset();
}

PGM_DECL std::vector<posterior> gibbs_sampling::marginals(std::span<const variable_id> nodes) {
  std::vector<std::vector<variable_id>> groups;
  for (auto v : nodes) groups.push_back({v});
  return estimates(detail::tally_layout(std::move(groups), *network_));
}

PGM_DECL std::vector<posterior> gibbs_sampling::estimates(const detail::tally_layout& layout) {
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

PGM_DECL void gibbs_sampling::run_chain(std::size_t chain, const detail::sampler_evidence& observed,
                                        const detail::tally_layout& layout, std::size_t per_batch,
                                        std::vector<std::vector<double>>& counts) const {
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

PGM_DECL bool gibbs_sampling::start(std::vector<std::uint32_t>& state, const detail::sampler_evidence& observed,
                                    detail::sample_stream& stream) const {
  for (std::size_t attempt = 0; attempt < start_attempts; ++attempt) {
    if (detail::draw_weighted(tables_, state, observed, stream) > 0.0) return true;
  }
  return false;
}

PGM_DECL void gibbs_sampling::step(std::vector<std::uint32_t>& state, std::span<const std::size_t> free,
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

}  // namespace pgm
