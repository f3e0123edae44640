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

#include "pgm/core/compilation.hpp"
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
  [[nodiscard]] PGM_DECL std::size_t key(variable_id a, variable_id b) const;
  std::size_t size_;
  std::vector<std::optional<std::vector<variable_id>>> sets_;
};

namespace detail {

inline variable_id node(std::size_t i) { return index_at<variable_id>(i); }

/// Orients a - b into a -> b unless that closes a directed cycle; records a conflict then.
PGM_DECL bool orient_if_acyclic(cpdag& graph, variable_id a, variable_id b, const char* why,
                                std::vector<std::string>& conflicts);

}  // namespace detail

/// Directs every edge whose direction the constraints fix: a required edge, or an edge that
/// may only point one way (tiers, a forbidden direction).
PGM_DECL void orient_by_knowledge(cpdag& graph, const edge_constraints& constraints);

/// For every unshielded triple a - c - b (a, b not adjacent) whose separating set does not
/// hold c, orients a -> c <- b. Only undirected edges are oriented; an edge already directed
/// the other way is left as it is and the conflict reported.
PGM_DECL void orient_v_structures(cpdag& graph, const separation_sets& sepsets, std::vector<std::string>& conflicts);

/// Meek's rules to a fixed point; each orients an undirected edge a - b into a -> b when
///  R1: some c -> a with c, b not adjacent (else a new v-structure at a);
///  R2: a -> c -> b for some c (else a cycle);
///  R3: a - c -> b and a - d -> b with c, d not adjacent (else a cycle or a new v-structure);
///  R4: d -> c -> b with a adjacent to c and to d, and b, d not adjacent (needed only when
///      background knowledge has oriented edges).
PGM_DECL void apply_meek_rules(cpdag& graph, std::vector<std::string>& conflicts);

/// The CPDAG (essential graph) of a DAG: its skeleton, its v-structures, Meek's rules.
[[nodiscard]] PGM_DECL cpdag cpdag_of(const dag& graph);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/orientation.ipp"
#endif
