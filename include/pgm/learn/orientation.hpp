#pragma once
/// \file
/// Orienting a skeleton into a CPDAG, the phases after the PC skeleton: background knowledge,
/// v-structures from the separating sets, then Meek's rules R1–R4 to a fixed point. Also
/// `cpdag_of`, the CPDAG of a known DAG, to compare a learned graph with the truth.
///
/// Conflicts (two v-structures that want opposite directions on one edge, or an orientation
/// that would close a directed cycle) are resolved first come, first served in node order,
/// and reported as text; pcalg does the same with its default `solve.confl = FALSE` except
/// that it lets the later orientation win.

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pgm/core/dag.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/learn/background_knowledge.hpp"
#include "pgm/learn/cpdag.hpp"

namespace pgm {

/// The separating set found for each removed pair of nodes.
class separation_sets {
 public:
  explicit separation_sets(std::size_t size = 0) : size_(size), sets_(size * size) {}

  void set(variable_id a, variable_id b, std::vector<variable_id> given) { sets_[key(a, b)] = std::move(given); }
  /// The separating set of a and b, or nullptr if none was recorded (they stayed adjacent,
  /// or background knowledge removed the pair).
  [[nodiscard]] const std::vector<variable_id>* get(variable_id a, variable_id b) const {
    const auto& entry = sets_[key(a, b)];
    return entry ? &*entry : nullptr;
  }
  [[nodiscard]] bool separates(variable_id a, variable_id b, variable_id c) const {
    const auto* given = get(a, b);
    return given && std::find(given->begin(), given->end(), c) != given->end();
  }

 private:
  [[nodiscard]] std::size_t key(variable_id a, variable_id b) const {
    const auto lo = std::min(a.value(), b.value());
    const auto hi = std::max(a.value(), b.value());
    return std::size_t{lo} * size_ + hi;
  }
  std::size_t size_;
  std::vector<std::optional<std::vector<variable_id>>> sets_;
};

namespace detail {

inline variable_id node(std::size_t i) { return variable_id(static_cast<variable_id::rep>(i)); }

/// Orients a - b into a -> b unless that closes a directed cycle; records a conflict then.
inline bool orient_if_acyclic(cpdag& graph, variable_id a, variable_id b, const char* why,
                              std::vector<std::string>& conflicts) {
  if (graph.has_directed_path(b, a)) {
    conflicts.push_back(why + std::string(": ") + graph.name(a) + " -> " + graph.name(b) +
                        " would close a directed cycle; left undirected");
    return false;
  }
  graph.orient(a, b);
  return true;
}

}  // namespace detail

/// Directs every edge whose direction the constraints fix: a required edge, or an edge that
/// may only point one way (tiers, a forbidden direction).
inline void orient_by_knowledge(cpdag& graph, const edge_constraints& constraints) {
  for (std::size_t i = 0; i < graph.size(); ++i) {
    for (std::size_t j = 0; j < graph.size(); ++j) {
      const auto a = detail::node(i);
      const auto b = detail::node(j);
      if (i == j || !graph.undirected(a, b)) continue;
      if (constraints.required(i, j) || !constraints.allowed(j, i)) graph.orient(a, b);
    }
  }
}

/// For every unshielded triple a - c - b (a, b not adjacent) whose separating set does not
/// hold c, orients a -> c <- b. Only undirected edges are oriented; an edge already directed
/// the other way is left as it is and the conflict reported.
inline void orient_v_structures(cpdag& graph, const separation_sets& sepsets, std::vector<std::string>& conflicts) {
  const auto skeleton = graph;  // unshielded triples are those of the skeleton
  for (std::size_t k = 0; k < graph.size(); ++k) {
    const auto c = detail::node(k);
    const auto around = skeleton.adjacent_nodes(c);
    for (std::size_t x = 0; x < around.size(); ++x) {
      for (std::size_t y = x + 1; y < around.size(); ++y) {
        const auto a = around[x];
        const auto b = around[y];
        if (skeleton.adjacent(a, b) || sepsets.separates(a, b, c)) continue;
        for (auto end : {a, b}) {
          if (graph.undirected(end, c)) {
            detail::orient_if_acyclic(graph, end, c, "v-structure", conflicts);
          } else if (graph.directed(c, end)) {
            conflicts.push_back("v-structure " + graph.name(a) + " -> " + graph.name(c) + " <- " + graph.name(b) +
                                ": " + graph.name(c) + " -> " + graph.name(end) + " is already oriented");
          }
        }
      }
    }
  }
}

/// Meek's rules to a fixed point; each orients an undirected edge a - b into a -> b when
///  R1: some c -> a with c, b not adjacent (else a new v-structure at a);
///  R2: a -> c -> b for some c (else a cycle);
///  R3: a - c -> b and a - d -> b with c, d not adjacent (else a cycle or a new v-structure);
///  R4: d -> c -> b with a adjacent to c and to d, and b, d not adjacent (needed only when
///      background knowledge has oriented edges).
inline void apply_meek_rules(cpdag& graph, std::vector<std::string>& conflicts) {
  const auto n = graph.size();
  bool changed = true;
  while (changed) {
    changed = false;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) {
        const auto a = detail::node(i);
        const auto b = detail::node(j);
        if (i == j || !graph.undirected(a, b)) continue;
        bool orient = false;
        for (auto c : graph.parents(a)) {
          if (c != b && !graph.adjacent(c, b)) orient = true;
        }
        if (!orient) {
          for (auto c : graph.children(a)) {
            if (graph.directed(c, b)) orient = true;
          }
        }
        if (!orient) {
          const auto into_b = graph.parents(b);
          for (std::size_t x = 0; x < into_b.size() && !orient; ++x) {
            for (std::size_t y = x + 1; y < into_b.size() && !orient; ++y) {
              const auto c = into_b[x];
              const auto d = into_b[y];
              orient = graph.undirected(a, c) && graph.undirected(a, d) && !graph.adjacent(c, d);
            }
          }
        }
        if (!orient) {
          for (auto c : graph.parents(b)) {
            if (c == a || !graph.adjacent(a, c)) continue;
            for (auto d : graph.parents(c)) {
              if (d != a && d != b && graph.adjacent(a, d) && !graph.adjacent(b, d)) orient = true;
            }
          }
        }
        if (orient && detail::orient_if_acyclic(graph, a, b, "Meek's rules", conflicts)) changed = true;
      }
    }
  }
}

/// The CPDAG (essential graph) of a DAG: its skeleton, its v-structures, Meek's rules.
[[nodiscard]] inline cpdag cpdag_of(const dag& graph) {
  cpdag result(graph.names());
  for (auto [from, to] : graph.edges()) result.add_undirected(from, to);
  for (std::size_t k = 0; k < graph.size(); ++k) {
    const auto c = detail::node(k);
    const auto parents = graph.parents(c);
    for (std::size_t x = 0; x < parents.size(); ++x) {
      for (std::size_t y = x + 1; y < parents.size(); ++y) {
        if (!result.adjacent(parents[x], parents[y])) {
          result.orient(parents[x], c);
          result.orient(parents[y], c);
        }
      }
    }
  }
  std::vector<std::string> conflicts;  // none: a DAG's orientations are consistent
  apply_meek_rules(result, conflicts);
  return result;
}

}  // namespace pgm
