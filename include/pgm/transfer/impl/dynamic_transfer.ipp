#pragma once
// The definitions of pgm/transfer/dynamic_transfer.hpp: inline in a header-only build, compiled once into
// libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/core/text.hpp"
#include "pgm/transfer/dynamic_transfer.hpp"

namespace pgm {

namespace detail {

/// The map `text` resolves to over the template variables, each target one of them.
inline correspondence template_map(std::string_view text, const bayesian_network& prior,
                                   const network_structure& templates) {
  auto map = resolve_correspondence(text, prior, templates);
  for (const auto& [target, source] : map.transferred) {
    if (!templates.contains(target)) {
      throw model_error("the map transfers '" + source + "' to '" + target + "', which is not a template variable (" +
                        template_list(templates) +
                        "): a prior goes to a template variable, whose tables in both slices it then informs");
    }
  }
  return map;
}

}  // namespace detail

PGM_DECL transfer_report add_transferred_priors(dynamic_fit_options& options, const dynamic_structure& structure,
                                                const dynamic_counts& counts, const bayesian_network& prior,
                                                const transfer_settings& settings, const transfer_settings* initial) {
  const auto& templates = structure.initial;
  const auto n = templates.size();
  if (counts.initial.size() != n || counts.transition.size() != n) {
    throw model_error("transferring into a dynamic network of " + std::to_string(n) +
                      " template variables needs as many count tables for each slice");
  }
  // A map proposed ("auto") over the template variables serves both slices.
  const auto map = detail::template_map(settings.map, prior, templates);
  auto resolved = settings;
  resolved.map = to_string(map);
  auto first_settings = initial ? *initial : resolved;
  if (!initial) {  // the first slice has no previous one: what the map says of x@-1 is left out
    auto first_map = map;
    const auto previous = [](const auto& entry) { return entry.first.find('@') != std::string::npos; };
    std::erase_if(first_map.identical, previous);
    std::erase_if(first_map.related, previous);
    first_settings.map = to_string(first_map);
  }
  if (first_settings.map != "none") {
    first_settings.map = to_string(detail::template_map(first_settings.map, prior, templates));
    fit_options first = options.fit;
    first.node_priors = options.initial_priors;
    try {
      static_cast<void>(detail::add_transferred_priors(
          first, templates, prior, first_settings,
          [&](variable_id node) -> const count_table& { return counts.initial[node.value()]; }));
    } catch (const model_error& e) {
      throw model_error(std::string("the first slice: ") + e.what() +
                        (initial ? "" : " (the first slice may have a map and strategy of its own)"));
    }
    options.initial_priors = std::move(first.node_priors);
  }
  // The transition's template variables are its nodes n … 2n−1 (X@-1 are 0 … n−1).
  auto report = detail::add_transferred_priors(
      options.fit, structure.transition, prior, resolved,
      [&](variable_id node) -> const count_table& { return counts.transition.at(node.value() - n); });
  report.map_proposed = settings.map == "auto";
  return report;
}

}  // namespace pgm
