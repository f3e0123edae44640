#pragma once
// The definitions of pgm/transfer/transfer_problem.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/transfer/transfer_problem.hpp"

namespace pgm {

PGM_DECL transfer_problem::transfer_problem(const bayesian_network& prior_network, std::string_view prior_node,
                                            variable target_child, std::vector<variable> target_parents,
                                            correspondence map, transfer_options options)
    : transfer_problem(prior_network.table(prior_node), std::move(target_child), std::move(target_parents),
                       std::move(map), std::move(options)) {
  prior_network_ = &prior_network;
}

PGM_DECL transfer_problem::transfer_problem(const cpt<double>& prior_table, variable target_child,
                                            std::vector<variable> target_parents, correspondence map,
                                            transfer_options options)
    : prior_table_(&prior_table),
      target_child_(std::move(target_child)),
      target_parents_(std::move(target_parents)),
      map_(std::move(map)),
      options_(std::move(options)) {}

PGM_DECL std::size_t transfer_problem::success_state() const {
  if (const auto s = target_child_.find_state(options_.success_state)) return s->value();
  throw model_error("'" + target_child_.name() + "' has no success state '" + options_.success_state +
                    "' (its states: " + text::list_for_message(target_child_.states()) + ")");
}

PGM_DECL const char* to_string(replacement r) {
  switch (r) {
    case replacement::direct:
      return "direct";
    case replacement::cross:
      return "cross";
    case replacement::other:
      break;
  }
  return "other";
}

PGM_DECL transferred_prior::transferred_prior(cpt<double> table, std::vector<variable> prior_parents,
                                              std::vector<prior_term> terms, std::vector<std::uint32_t> term_counts,
                                              std::vector<replacement> via)
    : table_(std::move(table)),
      prior_parents_(std::move(prior_parents)),
      terms_(std::move(terms)),
      via_(std::move(via)) {
  if (term_counts.size() != table_.configurations() || via_.size() != table_.configurations()) {
    throw model_error("a transferred prior needs sources for each of the " + std::to_string(table_.configurations()) +
                      " configurations of '" + table_.child().name() + "'");
  }
  offsets_.reserve(term_counts.size() + 1);
  offsets_.push_back(0);
  for (auto n : term_counts) offsets_.push_back(offsets_.back() + n);
  if (offsets_.back() != terms_.size()) throw model_error("a transferred prior's term counts do not add up");
}

PGM_DECL std::string transferred_prior::describe_sources(config_index u) const {
  mixed_radix radix = prior_radix();
  std::string text;
  for (const auto& term : sources(u)) {
    if (!text.empty()) text += " + ";
    const auto codes = radix.decode(term.configuration);
    std::string states;
    for (std::size_t k = 0; k < codes.size(); ++k) {
      states += (k ? ", " : "") + prior_parents_[k].name() + "=" + prior_parents_[k].states()[codes[k]];
    }
    if (states.empty()) states = "(no parents)";
    text += term.weight == 1.0 ? states : text::format_short(term.weight, 4) + "·(" + states + ")";
  }
  return text;
}

PGM_DECL mixed_radix transferred_prior::prior_radix() const {
  std::vector<std::size_t> cards;
  for (const auto& p : prior_parents_) cards.push_back(p.cardinality());
  return mixed_radix(std::move(cards));
}

}  // namespace pgm
