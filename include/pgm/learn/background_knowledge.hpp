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

#include "pgm/core/compilation.hpp"
#include "pgm/core/dag.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/core/text.hpp"

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
[[nodiscard]] PGM_DECL std::vector<std::vector<std::string>> parse_tiers(std::string_view text);

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
  PGM_DECL edge_constraints(const background_knowledge& knowledge, const std::vector<std::string>& names);

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

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/background_knowledge.ipp"
#endif
