#pragma once
// The definitions of pgm/learn/learn_dynamic_structure.hpp: inline in a header-only build, compiled
// once into libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/learn_dynamic_structure.hpp"

namespace pgm::detail {

PGM_DECL structure_context two_slice_context(const std::vector<variable>& templates, structure_context context) {
  for (const auto& into : templates) {
    const auto previous = slice_name(into.name(), -1);
    for (const auto& from : templates) {
      context.knowledge.forbidden.push_back({from.name(), previous});
      if (from.name() != into.name()) context.knowledge.forbidden.push_back({slice_name(from.name(), -1), previous});
    }
  }
  return context;
}

PGM_DECL std::vector<variable> template_variables(const dataset& data, std::span<const std::string> names) {
  std::vector<variable> templates;
  for (const auto& name : names) templates.push_back(data.discrete(name).var());
  return templates;
}

}  // namespace pgm::detail

namespace pgm {

namespace detail {

/// The episodes `picked` of the long-form `data`, numbered 0, 1, … in that order (an episode
/// drawn twice is two episodes), with their steps and the columns `names`.
inline dataset resample_episodes(const dataset& data, std::span<const std::string> names, const episode_index& episodes,
                                 const std::vector<std::size_t>& picked, const episode_columns& columns) {
  std::vector<std::size_t> rows;
  std::vector<double> episode, step;
  for (std::size_t k = 0; k < picked.size(); ++k) {
    for (std::size_t t = 0; t < episodes.length(picked[k]); ++t) {
      rows.push_back(episodes.row(episodes.starts[picked[k]] + t));
      episode.push_back(static_cast<double>(k));
      step.push_back(static_cast<double>(t));
    }
  }
  auto resampled = resample_rows(data, names, rows);
  resampled.add(continuous_column(columns.episode, std::move(episode)));
  resampled.add(continuous_column(columns.step, std::move(step)));
  return resampled;
}

}  // namespace detail

PGM_DECL dynamic_bootstrap_result bootstrap_dynamic_structure(const dataset& data, std::span<const std::string> names,
                                                              const structure_learner& learner,
                                                              const structure_context& context,
                                                              const bootstrap_options& options,
                                                              const episode_columns& columns) {
  detail::check_bootstrap_options(options);
  const auto templates = detail::template_variables(data, names);
  const auto episodes = index_episodes(data, columns);
  std::vector<std::string> both;
  for (const auto& v : templates) both.push_back(slice_name(v.name(), -1));
  for (const auto& v : templates) both.push_back(v.name());
  const std::size_t n = both.size();
  std::vector<std::vector<unsigned char>> found(options.replicates);
  auto inner = context;
  inner.threads = 1;  // the replicates run in parallel
  detail::parallel_for(options.replicates, {.threads = context.threads}, [&](detail::item_range chunk) {
    for (std::size_t r = chunk.begin; r < chunk.end; ++r) {
      const auto picked = detail::bootstrap_draw(options.seed, r, episodes.episodes());
      const auto learned = learn_dynamic_structure(detail::resample_episodes(data, names, episodes, picked, columns),
                                                   names, learner, inner, columns);
      std::vector<unsigned char> edges(n * n, 0);
      dag index(both);
      for (const auto& e : learned.learned.edges) edges[index.id(e.from).value() * n + index.id(e.to).value()] = 1;
      found[r] = std::move(edges);
    }
  });
  auto arcs = detail::summarize_replicates(both, found, options);
  auto structure = dynamic_structure_of(templates, arcs.averaged);
  return {std::move(structure), std::move(arcs)};
}

}  // namespace pgm
