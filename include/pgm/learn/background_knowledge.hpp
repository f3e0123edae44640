#pragma once
/// \file
/// Background knowledge for structure learning: tiers (no edge points from a later tier to
/// an earlier one, e.g. outcomes last), forbidden edges and required edges. The user gives
/// them by name (`background_knowledge`); a learner resolves them against its variables once
/// (`edge_constraints`), which is where unknown names and contradictions are reported.

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/dag.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/detail/text.hpp"

namespace pgm {

struct background_knowledge {
  /// Earlier tiers first. Variables in no tier are unconstrained by tiers.
  std::vector<std::vector<std::string>> tiers;
  /// a->b may not be in the graph. Forbidding both directions removes the adjacency.
  std::vector<named_edge> forbidden;
  /// a->b is in the graph whatever the data say (it is never tested).
  std::vector<named_edge> required;

  [[nodiscard]] bool empty() const noexcept { return tiers.empty() && forbidden.empty() && required.empty(); }
};

/// Parses "a,b;c;d" into tiers {a, b}, {c}, {d}. Throws model_error on an empty tier or name.
[[nodiscard]] inline std::vector<std::vector<std::string>> parse_tiers(std::string_view text) {
  std::vector<std::vector<std::string>> tiers;
  for (const auto& tier : detail::split(text, ';')) {
    auto names = detail::split(tier, ',');
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

/// Background knowledge resolved against a list of variables: which directed edges may
/// exist and which must.
class edge_constraints {
 public:
  /// No constraints over `size` variables.
  explicit edge_constraints(std::size_t size = 0) : size_(size), allowed_(size * size, 1), required_(size * size, 0) {
    for (std::size_t i = 0; i < size; ++i) allowed_[i * size + i] = 0;
  }

  /// Throws model_error for a name not among `names`, a variable in two tiers, a required
  /// edge that is also forbidden, and not_a_dag for required edges that close a cycle.
  edge_constraints(const background_knowledge& knowledge, const std::vector<std::string>& names)
      : edge_constraints(names.size()) {
    std::map<std::string, std::size_t, std::less<>> index;
    for (std::size_t i = 0; i < names.size(); ++i) index.emplace(names[i], i);
    auto find = [&](const std::string& name, const std::string& where) {
      const auto it = index.find(name);
      if (it == index.end()) {
        throw model_error("unknown variable '" + name + "' in the " + where +
                          " (variables: " + detail::list_for_message(names) + ")");
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

  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  /// Whether i -> j may be in the graph.
  [[nodiscard]] bool allowed(std::size_t i, std::size_t j) const { return allowed_[i * size_ + j] != 0; }
  /// Whether i -> j must be in the graph.
  [[nodiscard]] bool required(std::size_t i, std::size_t j) const { return required_[i * size_ + j] != 0; }
  /// Whether i and j may be adjacent at all.
  [[nodiscard]] bool may_be_adjacent(std::size_t i, std::size_t j) const { return allowed(i, j) || allowed(j, i); }
  /// Whether i and j must be adjacent (one way or the other).
  [[nodiscard]] bool must_be_adjacent(std::size_t i, std::size_t j) const { return required(i, j) || required(j, i); }

 private:
  static constexpr std::size_t no_tier = static_cast<std::size_t>(-1);

  std::size_t size_;
  std::vector<unsigned char> allowed_;
  std::vector<unsigned char> required_;
  std::map<std::size_t, std::string> why_;
};

}  // namespace pgm
