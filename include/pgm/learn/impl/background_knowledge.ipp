#pragma once
// The definitions of pgm/learn/background_knowledge.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/background_knowledge.hpp"

namespace pgm {

PGM_DECL std::vector<std::vector<std::string>> parse_tiers(std::string_view text) {
  std::vector<std::vector<std::string>> tiers;
  for (const auto& tier : text::split(text, ';')) {
    auto names = text::split(tier, ',');
    for (const auto& name : names) {
      if (name.empty()) {
        throw model_error("tier " + std::to_string(tiers.size() + 1) + " ('" + tier + "') has an empty name");
      }
    }
    if (names.empty()) throw model_error("tier " + std::to_string(tiers.size() + 1) + " is empty");
    tiers.push_back(std::move(names));
  }
  if (tiers.empty()) throw model_error("the tier list is empty");
  return tiers;
}

PGM_DECL edge_constraints::edge_constraints(const background_knowledge& knowledge,
                                            const std::vector<std::string>& names)
    : edge_constraints(names.size()) {
  std::map<std::string, std::size_t, std::less<>> index;
  for (std::size_t i = 0; i < names.size(); ++i) index.emplace(names[i], i);
  auto find = [&](const std::string& name, const std::string& where) {
    const auto it = index.find(name);
    if (it == index.end()) {
      throw model_error("unknown variable '" + name + "' in the " + where +
                        " (variables: " + text::list_for_message(names) + ")");
    }
    return it->second;
  };

  std::vector<std::size_t> tier_of(names.size(), no_tier);
  for (std::size_t t = 0; t < knowledge.tiers.size(); ++t) {
    for (const auto& name : knowledge.tiers[t]) {
      const auto i = find(name, "tiers");
      if (tier_of[i] != no_tier) {
        throw model_error("variable '" + name + "' is in tier " + std::to_string(tier_of[i] + 1) + " and in tier " +
                          std::to_string(t + 1));
      }
      tier_of[i] = t;
    }
  }
  for (std::size_t i = 0; i < size_; ++i) {
    for (std::size_t j = 0; j < size_; ++j) {
      if (tier_of[i] != no_tier && tier_of[j] != no_tier && tier_of[i] > tier_of[j]) {
        allowed_[i * size_ + j] = 0;
        why_[i * size_ + j] = "the tiers put '" + names[i] + "' after '" + names[j] + "'";
      }
    }
  }
  for (const auto& edge : knowledge.forbidden) {
    const auto i = find(edge.from, "forbidden edges");
    const auto j = find(edge.to, "forbidden edges");
    allowed_[i * size_ + j] = 0;
    why_.try_emplace(i * size_ + j, "it is forbidden");
  }
  dag required_graph(names);
  for (const auto& edge : knowledge.required) {
    const auto i = find(edge.from, "required edges");
    const auto j = find(edge.to, "required edges");
    if (!allowed_[i * size_ + j]) {
      const auto it = why_.find(i * size_ + j);
      throw model_error("edge " + edge.from + "->" + edge.to + " is required, but " +
                        (it == why_.end() ? std::string("it is a self-loop") : it->second));
    }
    if (required_[i * size_ + j]) continue;
    required_graph.add_edge(edge.from, edge.to);  // throws not_a_dag on a cycle
    required_[i * size_ + j] = 1;
  }
}

}  // namespace pgm
