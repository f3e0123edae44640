#pragma once
/// \file
/// What a dynamic fit learned (pgm/learn/fit_dynamic.hpp), kept beside the model so that new
/// episodes can be added later without the old ones, as fit_statistics does for a static fit:
/// the first slice's counts over the episodes' first rows, and each template variable's tied
/// transition counts over every later step, each table with the prior it was estimated with.
/// Counts add up, so a model updated with new episodes equals, to the last bit, the model
/// fitted on all the episodes at once.

#include <cstddef>

#include "pgm/core/compilation.hpp"
#include "pgm/core/dynamic_network.hpp"
#include "pgm/learn/fit_dynamic.hpp"
#include "pgm/learn/fit_statistics.hpp"

namespace pgm {

struct dynamic_fit_statistics {
  /// One family per template variable, its rows the episodes.
  fit_statistics initial;
  /// One transition family per template variable, in template order; its rows the transitions
  /// (every step but each episode's first).
  fit_statistics transition;
};

/// The statistics of a fit of `structure` from `counts` under `options`' priors (those
/// fit_dynamic takes).
[[nodiscard]] PGM_DECL dynamic_fit_statistics dynamic_statistics_of(const dynamic_structure& structure,
                                                                    const dynamic_counts& counts,
                                                                    const dynamic_fit_options& options = {});

/// The dynamic network the statistics give: each table estimated from its counts under its
/// prior. Throws model_error for statistics that are not one family per table of `structure`.
[[nodiscard]] PGM_DECL dynamic_network estimate_dynamic(const dynamic_structure& structure,
                                                        const dynamic_fit_statistics& statistics);

/// The statistics after new episodes' counts: decay · the old counts + the new (as updated()
/// for a static fit). Throws model_error for counts of other families or a decay outside (0, 1].
[[nodiscard]] PGM_DECL dynamic_fit_statistics updated(const dynamic_fit_statistics& old, const dynamic_counts& more,
                                                      double decay = 1.0);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/dynamic_statistics.ipp"
#endif
