#pragma once
/// \file
/// "Fit this dynamic network from these episodes" and "add these episodes to it" in one call
/// each: the families counted over the long-form data, the transferred priors given to both
/// slices where a related task's network is given, the tied tables estimated, the counts kept
/// for updates. `pgm fit --dynamic`, `pgm update` and the Python module fit through it.

#include <cstddef>
#include <optional>
#include <string>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/dynamic_network.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/learn/dynamic_em.hpp"
#include "pgm/learn/dynamic_statistics.hpp"
#include "pgm/learn/fit_dynamic.hpp"
#include "pgm/transfer/transfer_settings.hpp"

namespace pgm {

struct dynamic_fit_request {
  /// Priors, the empty-configuration rule, counting threads, the episode columns.
  dynamic_fit_options options;
  /// A related task's static network: the map of `transfer` gives template variables their
  /// transferred priors (pgm/transfer/dynamic_transfer.hpp).
  const bayesian_network* prior_network = nullptr;
  transfer_settings transfer;
  /// The first slice's own map and strategy; where unset, the transition's.
  std::optional<std::string> initial_map, initial_strategy;
  /// Keep the counts with the model, for updates (not with `em`).
  bool keep_statistics = false;
  /// Fit by EM (pgm/learn/dynamic_em.hpp) instead of counting once: the missing values and the
  /// latent template variables (those in no column) estimated. A transfer reads the counts of
  /// the families observed whole.
  std::optional<dynamic_em_options> em;
};

struct fitted_dynamic {
  dynamic_network model;
  std::optional<dynamic_fit_statistics> statistics;
  /// What the transfer into the transition decided, when there was one.
  std::optional<transfer_report> transfer;
  /// How EM went, when it fitted the model (its `model` moved to the one above).
  std::optional<dynamic_em_result> em;
  std::size_t episodes = 0;
  std::size_t steps = 0;
};

/// Fits `structure` from the long-form `data` as `request` asks.
[[nodiscard]] PGM_DECL fitted_dynamic fit_from_episodes(const dynamic_structure& structure, const dataset& data,
                                                        const dynamic_fit_request& request);

/// The model with the episodes of `data` added to its counts (the old ones weighted by
/// `decay`), every table estimated again under the prior it was fitted with.
[[nodiscard]] PGM_DECL fitted_dynamic update_with_episodes(const dynamic_network& model,
                                                           const dynamic_fit_statistics& statistics,
                                                           const dataset& data, double decay, unsigned threads = 0);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/pipeline/impl/dynamic_fit_pipeline.ipp"
#endif
