#pragma once
/// \file
/// The paper's transferred priors (eq. 7–9) for a dynamic network: a static network's tables as
/// the priors of template variables' tables, in the first slice and in the tied transition. The
/// map names template variables (this slice) as targets, as for a static target; a parent in the
/// previous slice has counterparts of its own (`onTop=onTop1, xOff~xOff1, xOff@-1==xOff1`).

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/learn/fit_dynamic.hpp"
#include "pgm/transfer/transfer_settings.hpp"

namespace pgm {

/// Gives every template variable the map transfers to its weighted prior (eq. 8) in both
/// slices: the transition's table in `options.fit.node_priors`, by `settings`, and the first
/// slice's in `options.initial_priors`, by `initial` (its own map and strategy: the first step of
/// a tower is the 1-Stack itself, `onTop=onTop1, xOff==xOff1`), or without it by `settings` less
/// what the map says of `x@-1`; `initial` with the map "none" leaves the first slice out. Each
/// weight is chosen from its table's counts where the settings give none; "auto" proposes a map
/// over the template variables. Returns what the transfer into the transition decided. Throws
/// model_error for a map whose target is no template variable or that does not fit the networks
/// (naming the first slice where it fails there).
PGM_DECL transfer_report add_transferred_priors(dynamic_fit_options& options, const dynamic_structure& structure,
                                                const dynamic_counts& counts, const bayesian_network& prior,
                                                const transfer_settings& settings,
                                                const transfer_settings* initial = nullptr);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/transfer/impl/dynamic_transfer.ipp"
#endif
