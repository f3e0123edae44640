#pragma once
// The definitions of pgm/learn/bootstrap.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/bootstrap.hpp"

namespace pgm::detail {

PGM_DECL dataset resample_rows(const dataset& data, std::span<const std::string> names,
                               const std::vector<std::size_t>& picked) {
  dataset result;
  for (const auto& name : names) {
    const auto& column = data.discrete(name);
    std::size_t missing = 0;
    auto codes = std::visit(
        [&](const auto& source) {
          using code_type = typename std::decay_t<decltype(source)>::value_type;
          std::vector<code_type> out(picked.size());
          for (std::size_t r = 0; r < picked.size(); ++r) {
            out[r] = source[picked[r]];
            missing += out[r] == missing_code<code_type> && column.missing() != 0;
          }
          return code_vector(std::move(out));
        },
        column.codes());
    result.add(discrete_column(column.var(), std::move(codes), std::in_place, missing));
  }
  return result;
}

PGM_DECL double l1_threshold(std::vector<double> strengths) {
  if (strengths.empty()) return 0.0;
  std::sort(strengths.begin(), strengths.end());
  const auto n = static_cast<double>(strengths.size());
  // F is a step function: on [knot_k, knot_{k+1}) it is the fraction of strengths <= knot_k.
  std::vector<double> knots;
  for (auto s : strengths) {
    if (knots.empty() || knots.back() != s) knots.push_back(s);
  }
  std::vector<double> left{0.0}, width, value;
  for (auto k : knots) {
    if (k > 0.0 && k < 1.0) left.push_back(k);
  }
  auto cdf = [&](double t) {
    return static_cast<double>(std::upper_bound(strengths.begin(), strengths.end(), t) - strengths.begin()) / n;
  };
  for (std::size_t k = 0; k < left.size(); ++k) {
    const double right = k + 1 < left.size() ? left[k + 1] : 1.0;
    width.push_back(right - left[k]);
    value.push_back(cdf(left[k]));
  }
  // The minimizer of sum width_k |value_k - p| is a weighted median of the values.
  std::vector<std::size_t> order(value.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return value[a] < value[b]; });
  double total = 0.0;
  for (auto w : width) total += w;
  double below = 0.0;
  double p0 = value[order.front()];
  for (auto k : order) {
    below += width[k];
    p0 = value[k];
    if (below >= total / 2) break;
  }
  // The p0 quantile, type 1: the smallest strength with F(s) >= p0.
  for (auto s : strengths) {
    if (cdf(s) >= p0) return s;
  }
  return strengths.back();
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL bootstrap_result bootstrap_structure(const dataset& data, std::span<const std::string> names,
                                              const structure_learner& learner, const structure_context& context,
                                              const bootstrap_options& options) {
  detail::check_bootstrap_options(options);
  const std::size_t n = names.size();
  std::vector<std::vector<unsigned char>> found(options.replicates);
  auto inner = context;
  inner.threads = 1;  // the replicates run in parallel
  detail::parallel_for(options.replicates, {.threads = context.threads}, [&](detail::item_range chunk) {
    for (std::size_t r = chunk.begin; r < chunk.end; ++r) {
      const auto resampled = detail::resample_rows(data, names, detail::bootstrap_draw(options.seed, r, data.rows()));
      const auto learned = learn_structure(resampled, names, learner, inner);
      std::vector<unsigned char> edges(n * n, 0);
      dag index(std::vector<std::string>(names.begin(), names.end()));
      for (const auto& e : learned.edges) edges[index.id(e.from).value() * n + index.id(e.to).value()] = 1;
      found[r] = std::move(edges);
    }
  });
  return detail::summarize_replicates(names, found, options);
}

}  // namespace pgm

namespace pgm::detail {

PGM_DECL void check_bootstrap_options(const bootstrap_options& options) {
  if (options.replicates == 0) throw model_error("the bootstrap needs at least one replicate");
  if (options.threshold && !(*options.threshold >= 0.0 && *options.threshold <= 1.0)) {
    throw model_error("the bootstrap threshold must lie between 0 and 1, got " +
                      text::format_short(*options.threshold));
  }
}

PGM_DECL std::vector<std::size_t> bootstrap_draw(std::uint64_t seed, std::size_t r, std::size_t count) {
  std::uint64_t stream = splitmix64(seed ^ splitmix64(r + 0x5eed));
  std::vector<std::size_t> picked(count);
  for (auto& p : picked) {
    stream = splitmix64(stream);
    p = static_cast<std::size_t>(stream % count);
  }
  return picked;
}

PGM_DECL bootstrap_result summarize_replicates(std::span<const std::string> names,
                                               const std::vector<std::vector<unsigned char>>& found,
                                               const bootstrap_options& options) {
  const std::size_t n = names.size();
  bootstrap_result result;
  result.replicates = found.size();
  const auto reps = static_cast<double>(found.size());
  std::vector<double> strengths;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j) continue;
      std::size_t forward = 0, backward = 0;
      for (const auto& edges : found) {
        forward += edges[i * n + j];
        backward += edges[j * n + i];
      }
      const double adjacent = static_cast<double>(forward + backward);
      result.arcs.push_back(
          {names[i], names[j], adjacent / reps, adjacent > 0 ? static_cast<double>(forward) / adjacent : 0.0});
      strengths.push_back(adjacent / reps);
    }
  }
  result.threshold = options.threshold ? *options.threshold : l1_threshold(strengths);

  // The averaged network: significant arcs, strongest first, without cycles or both directions.
  std::vector<std::size_t> significant;
  for (std::size_t k = 0; k < result.arcs.size(); ++k) {
    const auto& a = result.arcs[k];
    if ((a.strength > result.threshold || a.strength == 1.0) && a.direction >= 0.5) significant.push_back(k);
  }
  std::stable_sort(significant.begin(), significant.end(), [&](auto a, auto b) {
    return result.arcs[a].strength > result.arcs[b].strength ||
           (result.arcs[a].strength == result.arcs[b].strength && result.arcs[a].direction > result.arcs[b].direction);
  });
  dag averaged(std::vector<std::string>(names.begin(), names.end()));
  for (auto k : significant) {
    const auto& a = result.arcs[k];
    const auto from = averaged.id(a.from);
    const auto to = averaged.id(a.to);
    if (averaged.has_edge(to, from)) continue;
    try {
      averaged.add_edge(from, to);
    } catch (const not_a_dag&) {
      // an arc that closes a cycle with stronger ones is left out
    }
  }
  for (const auto& a : result.arcs) {
    if (averaged.has_edge(averaged.id(a.from), averaged.id(a.to))) result.averaged.push_back({a.from, a.to});
  }
  return result;
}

}  // namespace pgm::detail
