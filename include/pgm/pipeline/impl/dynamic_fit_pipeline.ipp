#pragma once
// The definitions of pgm/pipeline/dynamic_fit_pipeline.hpp: inline in a header-only build, compiled once into
// libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <optional>
#include <utility>
#include <variant>

#include "pgm/pipeline/dynamic_fit_pipeline.hpp"
#include "pgm/transfer/dynamic_transfer.hpp"

namespace pgm {

namespace detail {

/// `data` with a column of missing values for each template variable that has none (a latent
/// one), so that counting leaves out the families it is in.
inline dataset with_latent_columns(const dataset& data, const dynamic_structure& structure) {
  auto out = data;
  for (const auto& v : structure.variables()) {
    if (data.contains(v.name())) continue;
    auto codes = make_code_vector(v.cardinality() + 1, data.rows());
    std::visit(
        [](auto& stored) {
          using code = typename std::decay_t<decltype(stored)>::value_type;
          std::fill(stored.begin(), stored.end(), missing_code<code>);
        },
        codes);
    out.add(discrete_column(v, std::move(codes), std::in_place, data.rows()));
  }
  return out;
}

}  // namespace detail

PGM_DECL fitted_dynamic fit_from_episodes(const dynamic_structure& structure, const dataset& data,
                                          const dynamic_fit_request& request) {
  if (request.em && request.keep_statistics) {
    throw model_error(
        "the counts are not kept with EM: they are expectations under its tables, which new episodes "
        "would change");
  }
  auto options = request.options;
  // EM counts for itself; a transfer reads the counts of the families observed whole.
  std::optional<dynamic_counts> counts;
  if (!request.em || request.prior_network) {
    counts = count_dynamic(structure, request.em ? detail::with_latent_columns(data, structure) : data, options.columns,
                           options.fit.counting);
  }
  fitted_dynamic result;
  if (request.prior_network) {
    std::optional<transfer_settings> initial;
    if (request.initial_map || request.initial_strategy) {
      initial = request.transfer;
      if (request.initial_map) initial->map = *request.initial_map;
      if (request.initial_strategy) initial->strategy = *request.initial_strategy;
    }
    result.transfer = add_transferred_priors(options, structure, *counts, *request.prior_network, request.transfer,
                                             initial ? &*initial : nullptr);
  }
  if (request.em) {
    result.em = dynamic_expectation_maximization(structure, data, options, *request.em);
    result.model = std::move(result.em->model);
    result.episodes = result.em->episodes;
    result.steps = result.em->steps;
    return result;
  }
  result.model = fit_dynamic(structure, *counts, options);
  if (request.keep_statistics) result.statistics = dynamic_statistics_of(structure, *counts, options);
  result.episodes = counts->episodes;
  result.steps = counts->steps;
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
