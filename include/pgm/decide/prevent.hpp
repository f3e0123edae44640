#pragma once
/// \file
/// Failure prevention (the method the paper cites as [8], and its metric 3; docs/decide.md).
/// For a parent configuration u of the success variable with estimated P(success | u) < ε,
/// the target u* is the nearest configuration — moving only the controllable parents — whose
/// estimate is > ε; among equally near ones the higher estimate wins, then the lower index.
/// If no configuration reachable from u exceeds ε, u* is the one with the highest estimate
/// (ties: nearest, then lower index). "Near" counts bin steps (one variable, one bin, per step:
/// L1 over bin indices) or, as an option, Euclidean distance between interval midpoints.
///
/// Configurations that differ only in controllable parents form a slice; each slice is solved
/// once for all its configurations. With steps, a breadth-first search from all targets at
/// once labels every cell with its nearest target (the nearest targets of a cell are the
/// union of those of its neighbours one step closer, so the best of them propagates), which
/// is linear in the slice. With units, each cell below ε scans the targets of its slice.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"

namespace pgm {

struct prevention_options {
  /// Configurations predicted below this are moved; targets must be predicted above it.
  double epsilon = 0.8;
  enum class distance {
    steps,  ///< bin steps, L1 over bin indices (the method's breadth-first search)
    units   ///< Euclidean distance between interval midpoints, in the variables' units
  } metric = distance::steps;
};

/// "steps" or "units", as the command line and Python spell a distance.
[[nodiscard]] constexpr std::string_view to_string(prevention_options::distance distance) noexcept {
  return distance == prevention_options::distance::units ? "units" : "steps";
}

inline constexpr std::array distances{prevention_options::distance::steps, prevention_options::distance::units};

/// The distances' names, for parsing, messages and the command line's allowed values.
[[nodiscard]] inline std::vector<std::string> known_distances() { return names_of(distances); }

/// Parses "steps" or "units"; throws unknown_name otherwise.
[[nodiscard]] inline prevention_options::distance parse_distance(std::string_view text) {
  return parse_choice("distance", text, distances);
}

namespace detail {

/// Success is a prediction above ε, so ε = 1 could never be reached: refused rather than
/// reporting the best change as short of ε when it predicts 1.
PGM_DECL void check_epsilon(double epsilon);

PGM_DECL void check_prevention_inputs(const cpt<double>& table, std::size_t success_state,
                                      std::span<const bool> controllable, const prevention_options& options);

/// The sum of one weight per configuration; throws model_error for a wrong count, a negative
/// or non-finite weight, or a zero sum.
PGM_DECL double checked_weight_total(std::span<const double> weights, std::size_t configurations);

/// Per controllable parent, the squared midpoint differences between its states.
PGM_DECL std::vector<std::vector<double>> squared_midpoint_gaps(const cpt<double>& table,
                                                                const std::vector<std::size_t>& dims);

/// Solves prevention slice by slice; the buffers live as long as one call.
class prevention_solver {
 public:
  /// `table` is dense: prevention_targets densifies a sparse one.
  PGM_DECL prevention_solver(const cpt<double>& table, std::size_t success_state, std::span<const bool> controllable,
                             const prevention_options& options);

  /// The base (all controllable digits zero) of every slice.
  [[nodiscard]] PGM_DECL std::vector<std::size_t> slice_bases() const;

  /// The base of the slice holding configuration u.
  [[nodiscard]] PGM_DECL std::size_t base_of(std::size_t u) const;

  /// Writes u* into targets[u] for every u of the slice at `base`.
  PGM_DECL void solve(std::size_t base, std::span<std::size_t> targets);

 private:
  /// Whether target a beats target b at equal distance: higher estimate, then lower index.
  bool better(std::uint32_t a, std::uint32_t b) const {
    return estimate_[a] > estimate_[b] || (estimate_[a] == estimate_[b] && a < b);
  }

  PGM_DECL void spread_steps();

  PGM_DECL void nearest_in_units(double epsilon);

  const cpt<double>& table_;
  std::size_t success_;
  prevention_options options_;
  std::vector<std::size_t> dims_;
  std::vector<std::size_t> fixed_;
  std::size_t cells_ = 1;
  std::vector<std::size_t> local_stride_;
  std::vector<std::size_t> offset_;
  std::vector<std::uint32_t> digits_;
  std::vector<std::vector<double>> gaps_;
  std::vector<double> estimate_;
  std::vector<std::uint32_t> distance_;
  std::vector<std::uint32_t> best_;
  std::vector<std::uint32_t> queue_;
  std::vector<std::uint32_t> targets_;
};

}  // namespace detail

/// For every parent configuration u of `estimated` (a success variable's table), the index of
/// the configuration u* that prevention chooses (u itself when its estimate is not below ε).
/// `controllable` has one flag per parent; the others never move. Throws model_error on
/// mismatched sizes, an ε outside [0, 1], or units asked for a parent without midpoints.
[[nodiscard]] PGM_DECL std::vector<std::size_t> prevention_targets(const cpt<double>& estimated,
                                                                   std::size_t success_state,
                                                                   std::span<const bool> controllable,
                                                                   const prevention_options& options = {});

/// The target u* for one configuration u.
[[nodiscard]] PGM_DECL std::size_t prevention_target(const cpt<double>& estimated, std::size_t success_state,
                                                     std::size_t configuration, std::span<const bool> controllable,
                                                     const prevention_options& options = {});

/// Metric 3: sum_u weight[u] · truth(success | u*(u)) / sum_u weight[u], u* chosen on
/// `estimated`. With estimated = truth this is the "oracle" value, which is not an upper bound
/// (it stops at the nearest configuration above ε). Throws model_error if the two tables differ
/// in shape, or the weights are not one non-negative finite number per configuration with a
/// positive sum.
[[nodiscard]] PGM_DECL double failure_prevention_rate(const cpt<double>& estimated, const cpt<double>& truth,
                                                      std::size_t success_state, std::span<const bool> controllable,
                                                      std::span<const double> configuration_weights,
                                                      const prevention_options& options = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/decide/impl/prevent.ipp"
#endif
