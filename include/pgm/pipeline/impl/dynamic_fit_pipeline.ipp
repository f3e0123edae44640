#pragma once
// The definitions of pgm/pipeline/dynamic_fit_pipeline.hpp: inline in a header-only build, compiled once into
// libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <utility>

#include "pgm/pipeline/dynamic_fit_pipeline.hpp"
#include "pgm/transfer/dynamic_transfer.hpp"

namespace pgm {

PGM_DECL fitted_dynamic fit_from_episodes(const dynamic_structure& structure, const dataset& data,
                                          const dynamic_fit_request& request) {
  auto options = request.options;
  const auto counts = count_dynamic(structure, data, options.columns, options.fit.counting);
  fitted_dynamic result{.episodes = counts.episodes, .steps = counts.steps};
  if (request.prior_network) {
    std::optional<transfer_settings> initial;
    if (request.initial_map || request.initial_strategy) {
      initial = request.transfer;
      if (request.initial_map) initial->map = *request.initial_map;
      if (request.initial_strategy) initial->strategy = *request.initial_strategy;
    }
    result.transfer = add_transferred_priors(options, structure, counts, *request.prior_network, request.transfer,
                                             initial ? &*initial : nullptr);
  }
  result.model = fit_dynamic(structure, counts, options);
  if (request.keep_statistics) result.statistics = dynamic_statistics_of(structure, counts, options);
  return result;
}

PGM_DECL fitted_dynamic update_with_episodes(const dynamic_network& model, const dynamic_fit_statistics& statistics,
                                             const dataset& data, double decay, unsigned threads) {
  const auto structure = structure_of(model);
  const auto counts = count_dynamic(structure, data, {}, {.threads = threads});
  auto total = updated(statistics, counts, decay);
  auto estimated = estimate_dynamic(structure, total);
  return {.model = std::move(estimated),
          .statistics = std::move(total),
          .episodes = counts.episodes,
          .steps = counts.steps};
}

}  // namespace pgm
