#pragma once
// The definitions of pgm/transfer/transfer_settings.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/transfer/transfer_settings.hpp"

namespace pgm {

PGM_DECL correspondence resolve_correspondence(std::string_view text, const bayesian_network& prior,
                                               const network_structure& target) {
  if (text.empty()) {
    throw error("a transferred prior needs a correspondence map, e.g. \"onTop2=onTop1,xOff2~xOff1\", or auto");
  }
  if (text != "auto") return parse_correspondence(text);
  return propose_correspondence({&target, nullptr}, {&prior.structure(), &prior});
}

PGM_DECL std::map<std::string, transferred_prior, std::less<>> transfer_priors(const bayesian_network& prior,
                                                                               const network_structure& target,
                                                                               const correspondence& map,
                                                                               const transfer_settings& settings) {
  transfer_options options;
  options.success_state = settings.success;
  options.matching = settings.matching;
  return transfer_priors(prior, target, map, transfer_registry::instance().at(settings.strategy), options);
}

PGM_DECL transfer_report add_transferred_priors(fit_options& options, const network_structure& structure,
                                                const dataset& data, const bayesian_network& prior,
                                                const transfer_settings& settings) {
  return detail::add_transferred_priors(options, structure, prior, settings, [&](variable_id node) {
    return count_node(structure, node, data, options.counting);
  });
}

PGM_DECL transfer_report add_transferred_priors(fit_options& options, const network_structure& structure,
                                                std::span<const count_table> counts, const bayesian_network& prior,
                                                const transfer_settings& settings) {
  return detail::add_transferred_priors(options, structure, prior, settings,
                                        [&](variable_id node) -> const count_table& { return counts[node.value()]; });
}

}  // namespace pgm
