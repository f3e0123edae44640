#pragma once
/// \file
/// Proposing correspondences automatically (the paper's stated future work): candidate pairs
/// of a target and a prior variable are ranked by name stem (`xOff2` and `xOff1` share
/// `xOff`), semantic tags (quantity, unit), value range and, where both networks hold a table
/// for them, the distance between their marginal distributions. Every score comes with its
/// reasons, so the user can confirm the proposal (`--map`) or accept it (`--map auto`).

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/correspondence.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/core/text.hpp"
#include "pgm/transfer/state_map.hpp"

namespace pgm {

struct correspondence_candidate {
  std::string target;
  std::string prior;
  double score;  ///< in [0, 1]
  std::vector<std::string> reasons;
};

/// A network's variables, with the table of each where it has one (for marginals).
struct network_view {
  const network_structure* structure;
  const bayesian_network* network = nullptr;
};

namespace detail {

/// The name without trailing digits and lower-cased: "xOff2" → "xoff".
[[nodiscard]] PGM_DECL std::string name_stem(std::string_view name);

[[nodiscard]] PGM_DECL std::optional<std::pair<double, double>> value_range(const variable& v);

/// The marginal of a root variable, or nothing.
[[nodiscard]] PGM_DECL std::optional<std::vector<double>> root_marginal(const network_view& view,
                                                                        const std::string& name);

}  // namespace detail

/// Scores one pair of variables; `target_view`/`prior_view` give marginals where available.
[[nodiscard]] PGM_DECL correspondence_candidate score_pair(const variable& target, const variable& prior,
                                                           const network_view& target_view,
                                                           const network_view& prior_view);

/// Every pair of a target variable and a prior variable with different names, best first.
[[nodiscard]] PGM_DECL std::vector<correspondence_candidate> rank_correspondences(const network_view& target,
                                                                                  const network_view& prior);

/// The proposal `--map auto` accepts: unless `map` names one already, the transferred pair is
/// the best-scored pair of outcomes (nodes without children); then, for each parent of the
/// prior node, the best-scored parent of the target node that is not its identical variable,
/// each target parent used once, if it scores at least `threshold`.
[[nodiscard]] PGM_DECL correspondence propose_correspondence(const network_view& target, const network_view& prior,
                                                             correspondence map = {}, double threshold = 0.5);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/transfer/impl/propose.ipp"
#endif
