#pragma once
/// \file
/// One entry point for structure learning, which the program and the Python package both call:
/// `learn_structure(data, choice)` runs PC-stable (pgm/learn/pc.hpp), hill climbing or tabu
/// search (pgm/learn/hill_climbing.hpp), or the hybrid MMHC-style search in which PC-stable's
/// skeleton restricts the candidate parents of hill climbing (bnlearn's rsmax2 with PC as the
/// restrict phase). Every algorithm returns one DAG; PC also its CPDAG.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/learn/background_knowledge.hpp"
#include "pgm/learn/cpdag.hpp"
#include "pgm/learn/hill_climbing.hpp"
#include "pgm/learn/pc.hpp"

namespace pgm {

enum class structure_algorithm { pc, hc, tabu, mmhc };

[[nodiscard]] PGM_DECL std::string to_string(structure_algorithm algorithm);

inline constexpr std::array structure_algorithms{structure_algorithm::pc, structure_algorithm::hc,
                                                 structure_algorithm::tabu, structure_algorithm::mmhc};

/// The algorithms' names, for parsing, messages and the command line's allowed values.
[[nodiscard]] inline std::vector<std::string> known_structure_algorithms() { return names_of(structure_algorithms); }

/// "pc", "hc", "tabu" or "mmhc"; throws unknown_name otherwise.
[[nodiscard]] inline structure_algorithm parse_structure_algorithm(std::string_view text) {
  return parse_choice("structure learning algorithm", text, structure_algorithms);
}

struct structure_choice {
  structure_algorithm algorithm = structure_algorithm::hc;
  /// PC-stable's tests (pc, and the skeleton of mmhc).
  pc_options pc;
  /// The score search (hc, tabu, mmhc). For tabu, a tabu length of 0 means bnlearn's 10.
  search_options search;
  /// Tiers, forbidden and required edges, for every algorithm.
  background_knowledge knowledge;
  /// Worker threads; 0 uses every hardware thread. The result is the same for any number.
  unsigned threads = 0;
  /// hc and tabu: start from a DAG of PC-stable's CPDAG (with `pc`'s tests) instead of
  /// `search.start`.
  bool start_from_pc = false;
};

struct structure_result {
  structure_algorithm algorithm = structure_algorithm::hc;
  /// The learned DAG (for PC, one DAG of its CPDAG's class).
  std::vector<named_edge> edges;
  /// PC's CPDAG; for the score searches, the CPDAG of the learned DAG's class.
  cpdag graph;
  /// PC: the nodes given new v-structures to extend its CPDAG to a DAG.
  std::size_t relaxed = 0;
  std::optional<pc_result> pc;
  std::optional<search_result> search;
};

/// Learns a structure over the named columns of `data` (all discrete). Throws model_error for
/// bad options or knowledge, data_error for a missing or continuous column.
[[nodiscard]] PGM_DECL structure_result learn_structure(const dataset& data, std::span<const std::string> names,
                                                        const structure_choice& choice);

/// Learns a structure over every column of `data`.
[[nodiscard]] inline structure_result learn_structure(const dataset& data, const structure_choice& choice) {
  const auto names = data.names();
  return learn_structure(data, names, choice);
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/learn_structure.ipp"
#endif
