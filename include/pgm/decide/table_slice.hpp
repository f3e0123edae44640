#pragma once
/// \file
/// A table read as a map over two of its parents, as the paper's Fig. 5 shows a success table:
/// P(node = state | x, y, the other parents fixed), or with `average` the other parents summed out
/// under the network's joint (P(node = state | x, y, given) by inference). With the counts a fit
/// kept, each cell's rows beside it. What `pgm plot-table` and `Network.plot_table` draw.

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/decide/assignment.hpp"
#include "pgm/decide/success_table.hpp"
#include "pgm/inference/junction_tree_engine.hpp"
#include "pgm/learn/fit_statistics.hpp"

namespace pgm {

struct table_slice_request {
  std::string node;
  /// Two parents of `node`: x across, y up.
  std::string x, y;
  /// The other parents' values (each needed unless `average`), as `pgm predict` reads them: a
  /// label, or a number in an interval variable's units; with `average` any other observations.
  assignment given;
  bool average = false;
  /// The state whose probability is shown; by default the last one (a success's "1").
  std::optional<std::string> state;
};

struct table_slice {
  const variable* node = nullptr;
  const variable* x = nullptr;
  const variable* y = nullptr;
  std::size_t state = 0;
  /// P(node = state | x_i, y_j, ...) at [j * x_states + i].
  std::vector<double> probability;
  /// The rows behind each cell, when the network's counts were given: the node's family counts
  /// at x, y and the given parents, summed over the others (observations of variables outside
  /// the family do not narrow them).
  std::optional<std::vector<double>> rows;
  [[nodiscard]] double at(std::size_t i, std::size_t j) const { return probability[j * x->cardinality() + i]; }
};

namespace detail {

/// The rows of each (x, y) cell in `counts` (the node's family), the other parents at `fixed`
/// (name → state) or summed when not fixed.
[[nodiscard]] PGM_DECL std::vector<double> cell_rows(const expected_count_table& counts, const variable& x,
                                                     const variable& y,
                                                     const std::vector<std::pair<std::string, state_index>>& fixed);

}  // namespace detail

/// The slice `request` asks for; `statistics` (the network's kept counts), when given, adds
/// the rows behind each cell. Throws model_error for an unknown variable or state, x or y not
/// a parent of the node, or another parent neither given nor averaged.
[[nodiscard]] PGM_DECL table_slice slice_table(const bayesian_network& network, const table_slice_request& request,
                                               const fit_statistics* statistics = nullptr);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/decide/impl/table_slice.ipp"
#endif
