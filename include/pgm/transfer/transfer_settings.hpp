#pragma once
/// \file
/// A fit with priors transferred from a related task's network, in the terms a user gives it:
/// a strategy by name, a correspondence map as text or "auto", a weight w or "choose it from
/// the data". `pgm fit --prior-model --strategy --map --w-prior` and the Python
/// `pgm.fit(prior_model=, strategy=, map=, w_prior=)` both end here, so both fit the same tables.

#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/correspondence.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/learn/fit.hpp"
#include "pgm/learn/parameter_prior.hpp"
#include "pgm/transfer/network_transfer.hpp"
#include "pgm/transfer/prior_weight.hpp"
#include "pgm/transfer/propose.hpp"
#include "pgm/transfer/registry.hpp"
#include "pgm/transfer/transfer_problem.hpp"

namespace pgm {

struct transfer_settings {
  /// A registered strategy: direct, cross, minimal, or one of the user's.
  std::string strategy = "minimal";
  /// "onTop2=onTop1,xOff2~xOff1,yOff2~yOff1" (parse_correspondence), or "auto" to propose one.
  std::string map;
  /// The prior weight w of eq. 8; none: chosen per node from the data (choose_prior_weight).
  std::optional<double> weight = 5.0;
  /// The success state of a transferred node (Minimal-Replacement compares it).
  std::string success = "1";
  /// How differently discretized states are matched.
  state_matching matching = state_matching::midpoint;
};

/// What a transfer decided, for the user to read.
struct transfer_report {
  correspondence map;
  /// The map was proposed ("auto") rather than given.
  bool map_proposed = false;
  struct node {
    std::string prior_node;
    double weight;
    /// Why this weight, when it was chosen from the data.
    std::optional<std::string> reason;
  };
  /// By transferred target node.
  std::map<std::string, node, std::less<>> nodes;
};

/// The map `text` gives, or with "auto" the one proposed from the two networks. Throws
/// pgm::error for an empty text, model_error for a malformed map.
[[nodiscard]] PGM_DECL correspondence resolve_correspondence(std::string_view text, const bayesian_network& prior,
                                                             const network_structure& target);

/// The transferred prior of every `target=prior` pair of `map`, by the named strategy.
[[nodiscard]] PGM_DECL std::map<std::string, transferred_prior, std::less<>> transfer_priors(
    const bayesian_network& prior, const network_structure& target, const correspondence& map,
    const transfer_settings& settings);

namespace detail {

/// add_transferred_priors with the counts of a node's family from `count_of(variable_id)`.
template <class CountOf>
transfer_report add_transferred_priors(fit_options& options, const network_structure& structure,
                                       const bayesian_network& prior, const transfer_settings& settings,
                                       CountOf&& count_of) {
  if (settings.weight) check_pseudo_count(*settings.weight, "the prior weight w");
  transfer_report report;
  report.map = resolve_correspondence(settings.map, prior, structure);
  report.map_proposed = settings.map == "auto";
  const auto priors = transfer_priors(prior, structure, report.map, settings);
  std::map<std::string, double, std::less<>> weights;
  for (const auto& [node, transferred] : priors) {
    transfer_report::node entry{report.map.transferred.at(node), settings.weight.value_or(0.0), std::nullopt};
    if (!settings.weight) {
      const auto choice = choose_prior_weight(count_of(structure.id(node)), transferred.table());
      entry.weight = choice.weight;
      entry.reason = choice.reason;
    }
    weights.emplace(node, entry.weight);
    report.nodes.emplace(node, std::move(entry));
  }
  use_transferred_priors(options, priors, weights);
  return report;
}

}  // namespace detail

/// Gives every node the map transfers to its weighted prior (eq. 8) in `options`, the weight
/// chosen from `data` where `settings.weight` is empty. Throws model_error for a weight that is
/// negative or not finite, or a map that does not fit the networks.
PGM_DECL transfer_report add_transferred_priors(fit_options& options, const network_structure& structure,
                                                const dataset& data, const bayesian_network& prior,
                                                const transfer_settings& settings);

/// The same, the weights chosen from counts already made: `counts[i]` is node i's family (as
/// `pgm fit` counts them while it streams the data).
PGM_DECL transfer_report add_transferred_priors(fit_options& options, const network_structure& structure,
                                                std::span<const count_table> counts, const bayesian_network& prior,
                                                const transfer_settings& settings);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/transfer/impl/transfer_settings.ipp"
#endif
