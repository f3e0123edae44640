#pragma once
// The options `pgm fit` and `pgm transfer` share for a transferred prior, and turning them
// into priors for a target structure.

#include <CLI/CLI.hpp>
#include <map>
#include <string>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/transfer/network_transfer.hpp"
#include "pgm/transfer/transfer_settings.hpp"

namespace pgm::cli {

struct transfer_arguments {
  std::string prior_model;
  std::string strategy = "minimal";
  std::string map;
  std::string w_prior = "5";
  std::string success = "1";
  std::string matching = "midpoint";
};

/// Adds --prior-model, --strategy, --map, --w-prior, --success and --match; `with_weight`
/// leaves --w-prior out (pgm transfer writes f itself).
void add_transfer_options(CLI::App& command, transfer_arguments& args, bool with_weight);

/// The library's settings from the options; throws pgm::error for a --w-prior that is not a
/// number ≥ 0 or auto.
transfer_settings settings_of(const transfer_arguments& args);

/// Throws pgm::error when --map is missing.
void require_map(const transfer_arguments& args);

/// The map of --map: parsed, or proposed from the two networks with `auto` (printed).
correspondence resolve_map(const transfer_arguments& args, const bayesian_network& prior,
                           const network_structure& target);

/// The transferred prior of every `target=prior` pair, by the named strategy.
std::map<std::string, transferred_prior, std::less<>> resolve_priors(const transfer_arguments& args,
                                                                     const bayesian_network& prior,
                                                                     const network_structure& target,
                                                                     const correspondence& map);

}  // namespace pgm::cli
