#pragma once
/// \file
/// Transfer at the level of whole networks: for every `target=prior` pair of a correspondence
/// map, the prior table f(θ′) of the target node, ready to be the weighted prior (eq. 8) of a
/// fit. The map is checked against both networks first, so a misspelt name is an error that
/// names it rather than a variable silently left out.

#include <map>
#include <string>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/learn/fit.hpp"
#include "pgm/transfer/prior_transfer.hpp"
#include "pgm/transfer/registry.hpp"

namespace pgm {

/// Throws model_error if the prior node `prior_node` is already the counterpart (same name, `==`
/// or `~`) of a parent of the target node `target_node`: a node cannot take the table of its own
/// parent's counterpart. Quantity tags are not compared: transferring between outcomes of different
/// quantities (`inside=onTop1`, stacking to dropping) is the paper's use. Both names must be in
/// their networks. `pgm fit` and `pgm transfer` check each pair with it (via check_correspondence).
PGM_DECL void check_transferred_pair(const correspondence& map, const std::string& prior_node,
                                     const network_structure& target, const std::string& target_node);

/// Throws model_error for a map entry that names a variable its network lacks, or a
/// transferred pair that check_transferred_pair refuses.
PGM_DECL void check_correspondence(const correspondence& map, const bayesian_network& prior,
                                   const network_structure& target);

/// The transferred prior of every `target=prior` pair of `map`, by target node.
[[nodiscard]] PGM_DECL std::map<std::string, transferred_prior, std::less<>> transfer_priors(
    const bayesian_network& prior, const network_structure& target, const correspondence& map,
    const any_prior_transfer& strategy, const transfer_options& options = {});

/// Adds the weighted prior (eq. 8) of each transferred node to a fit's options.
PGM_DECL void use_transferred_priors(fit_options& options,
                                     const std::map<std::string, transferred_prior, std::less<>>& priors,
                                     const std::map<std::string, double, std::less<>>& weights);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/transfer/impl/network_transfer.ipp"
#endif
