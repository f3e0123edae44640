#pragma once
// The definitions of pgm/inference/likelihood_weighting.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/inference/likelihood_weighting.hpp"

namespace pgm::detail {

PGM_DECL sampler_tables::sampler_tables(const bayesian_network& network) : order_(network.graph().topological_order()) {
  const auto n = network.size();
  cumulative_.resize(n);
  parents_.resize(n);
  strides_.resize(n);
  cards_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& table = network.tables()[i];
    const auto j = table.child_cardinality();
    cards_[i] = j;
    parents_[i] = network.graph().parents(index_at<variable_id>(i));
    strides_[i] = table.parent_radix().strides();
    cumulative_[i] = cumulative_columns(table, true);
  }
}

PGM_DECL std::size_t sampler_tables::configuration(std::size_t node,
                                                   std::span<const std::uint32_t> state) const noexcept {
  std::size_t u = 0;
  const auto& ps = parents_[node];
  for (std::size_t p = 0; p < ps.size(); ++p) u += state[ps[p].value()] * strides_[node][p];
  return u;
}

PGM_DECL std::uint32_t sampler_tables::draw(std::size_t node, std::size_t u, double uniform) const noexcept {
  const auto j = cards_[node];
  const double* c = cumulative_[node].column(u);
  std::size_t x = 0;
  while (x + 1 < j && uniform >= c[x]) ++x;
  return static_cast<std::uint32_t>(x);
}

PGM_DECL sampler_evidence::sampler_evidence(std::size_t n, const evidence_set& observed)
    : fixed(n, -1), intervened(n, 0), likelihood(n) {
  for (const auto& o : observed.hard) fixed[o.variable.value()] = o.state.value();
  for (const auto& o : observed.intervened) {
    fixed[o.variable.value()] = o.state.value();
    intervened[o.variable.value()] = 1;
  }
  for (const auto& l : observed.soft) {
    auto& scaled = likelihood[l.variable.value()];
    scaled = l.weights;
    const double largest = *std::max_element(scaled.begin(), scaled.end());
    for (auto& w : scaled) w /= largest;
    log_likelihood_scale += std::log(largest);
  }
}

PGM_DECL double draw_weighted(const sampler_tables& tables, std::vector<std::uint32_t>& state,
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

PGM_DECL weighted_tally& weighted_tally::operator+=(const weighted_tally& other) {
  weight += other.weight;
  weight_squared += other.weight_squared;
  for (std::size_t c = 0; c < weighted.size(); ++c) {
    weighted[c] += other.weighted[c];
    squared_weighted[c] += other.squared_weighted[c];
  }
  return *this;
}

PGM_DECL tally_layout::tally_layout(std::vector<std::vector<variable_id>> of, const bayesian_network& network)
    : groups(std::move(of)) {
  for (const auto& g : groups) {
    offsets.push_back(cells);
    std::size_t size = 1;
    for (auto v : g) size *= network.variables()[v.value()].cardinality();
    cells += size;
  }
}

PGM_DECL posterior tallied_posterior(const bayesian_network& network, std::span<const variable_id> group,
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
  result.log_evidence_probability = std::log(tally.weight / n) + tally.log_likelihood_scale;
  result.evidence_probability = std::exp(result.log_evidence_probability);
  return result;
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL posterior likelihood_weighting::joint(std::span<const variable_id> query) {
  const detail::tally_layout layout({std::vector<variable_id>(query.begin(), query.end())}, *network_);
  const auto tally = run(layout);
  return detail::tallied_posterior(*network_, query, tally, 0, options_.samples, std::string(name()));
}

PGM_DECL std::vector<posterior> likelihood_weighting::marginals(std::span<const variable_id> nodes) {
  std::vector<std::vector<variable_id>> groups;
  for (auto v : nodes) groups.push_back({v});
  const detail::tally_layout layout(std::move(groups), *network_);
  const auto tally = run(layout);
  std::vector<posterior> result;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    result.push_back(detail::tallied_posterior(*network_, layout.groups[i], tally, layout.offsets[i], options_.samples,
                                               std::string(name())));
  }
  return result;
}

PGM_DECL detail::weighted_tally likelihood_weighting::run(const detail::tally_layout& layout,
                                                          bool allow_nothing) const {
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
  total.log_likelihood_scale = observed.log_likelihood_scale;
  if (!(total.weight > 0.0) && !allow_nothing) {
    throw impossible_evidence("none of " + std::to_string(options_.samples) +
                              " samples of likelihood weighting is consistent with the evidence " +
                              detail::describe(*network_, evidence_) +
                              ": it is impossible or too unlikely to sample; use an exact engine (jt, ve) or "
                              "more samples");
  }
  return total;
}

}  // namespace pgm
