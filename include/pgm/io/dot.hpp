#pragma once
/// \file
/// A network's structure as Graphviz DOT text, for `pgm draw` and Python's Network.draw: one
/// node per variable (its name and number of states), the task's success variable and the
/// variables a robot controls marked, a CPDAG's undirected edges drawn without arrowheads, and
/// the strength of each edge learned by bootstrap as its width and label. Rendering the text
/// (SVG, PNG, PDF) is Graphviz's `dot`, which the program runs.

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/network_structure.hpp"

namespace pgm {

struct dot_options {
  /// The task's success variables: drawn bold on green.
  std::vector<std::string> success;
  /// The variables the robot can set (the prevention's controllable ones): drawn as boxes on blue.
  std::vector<std::string> controllable;
  /// Edges of a CPDAG that the data leave undirected (pgm learn-structure's
  /// "undirected_in_cpdag"): drawn without arrowheads.
  std::vector<std::pair<std::string, std::string>> undirected;
  /// Each edge's share of bootstrap resamples that hold it (pgm learn-structure --bootstrap),
  /// in [0, 1]: drawn as its width and label.
  std::map<std::pair<std::string, std::string>, double> strength;
};

namespace detail {

/// `text` as a DOT string literal.
[[nodiscard]] PGM_DECL std::string dot_quoted(const std::string& text);

}  // namespace detail

/// The DOT text of `structure`; throws model_error for an option naming no variable of it.
[[nodiscard]] PGM_DECL std::string to_dot(const network_structure& structure, const dot_options& options = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/io/impl/dot.ipp"
#endif
