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
inline void check_epsilon(double epsilon) {
  if (!(epsilon >= 0.0 && epsilon < 1.0)) {
    throw model_error(
        "epsilon must be at least 0 and below 1 (success is a prediction above epsilon, and no "
        "probability exceeds 1), got " +
        detail::format_double(epsilon));
  }
}

inline void check_prevention_inputs(const cpt<double>& table, std::size_t success_state,
                                    std::span<const bool> controllable, const prevention_options& options) {
  if (success_state >= table.child_cardinality()) {
    throw model_error("success state " + std::to_string(success_state) + " is out of range for '" +
                      table.child().name() + "'");
  }
  if (controllable.size() != table.parents().size()) {
    throw model_error("'" + table.child().name() + "' has " + std::to_string(table.parents().size()) +
                      " parents, got " + std::to_string(controllable.size()) + " controllable flags");
  }
  check_epsilon(options.epsilon);
}

/// Per controllable parent, the squared midpoint differences between its states.
inline std::vector<std::vector<double>> squared_midpoint_gaps(const cpt<double>& table,
                                                              const std::vector<std::size_t>& dims) {
  std::vector<std::vector<double>> gaps;
  for (auto d : dims) {
    const auto& v = table.parents()[d];
    const auto k = v.cardinality();
    std::vector<double> mid(k);
    for (std::size_t s = 0; s < k; ++s) {
      const auto m = v.midpoint(state_index(static_cast<state_index::rep>(s)));
      if (!m) {
        throw model_error("'" + v.name() + "' has no interval edges or numeric states, so distances in units " +
                          "are undefined; use bin steps");
      }
      mid[s] = *m;
    }
    std::vector<double> g(k * k);
    for (std::size_t a = 0; a < k; ++a) {
      for (std::size_t b = 0; b < k; ++b) g[a * k + b] = (mid[a] - mid[b]) * (mid[a] - mid[b]);
    }
    gaps.push_back(std::move(g));
  }
  return gaps;
}

/// Solves prevention slice by slice; the buffers live as long as one call.
class prevention_solver {
 public:
  /// `table` is dense: prevention_targets densifies a sparse one.
  prevention_solver(const cpt<double>& table, std::size_t success_state, std::span<const bool> controllable,
                    const prevention_options& options)
      : table_(table), success_(success_state), options_(options) {
    check_prevention_inputs(table, success_state, controllable, options);
    const auto& radix = table.parent_radix();
    for (std::size_t d = 0; d < controllable.size(); ++d) {
      (controllable[d] ? dims_ : fixed_).push_back(d);
    }
    // Local numbering of a slice: mixed radix over the controllable parents, in parent order,
    // so that a lower local index is a lower table index within the slice.
    cells_ = 1;
    for (auto d : dims_) cells_ *= radix.radix(d);
    local_stride_.assign(dims_.size(), 1);
    for (std::size_t i = dims_.size(); i-- > 1;) local_stride_[i - 1] = local_stride_[i] * radix.radix(dims_[i]);
    offset_.assign(cells_, 0);
    digits_.assign(cells_ * dims_.size(), 0);
    for (std::size_t l = 0; l < cells_; ++l) {
      std::size_t rest = l;
      for (std::size_t i = 0; i < dims_.size(); ++i) {
        const auto digit = rest / local_stride_[i];
        rest %= local_stride_[i];
        digits_[l * dims_.size() + i] = static_cast<std::uint32_t>(digit);
        offset_[l] += digit * radix.stride(dims_[i]);
      }
    }
    if (options.metric == prevention_options::distance::units) gaps_ = squared_midpoint_gaps(table, dims_);
    estimate_.resize(cells_);
    distance_.resize(cells_);
    best_.resize(cells_);
    queue_.resize(cells_);
  }

  /// The base (all controllable digits zero) of every slice.
  [[nodiscard]] std::vector<std::size_t> slice_bases() const {
    const auto& radix = table_.parent_radix();
    std::size_t slices = 1;
    for (auto d : fixed_) slices *= radix.radix(d);
    std::vector<std::size_t> bases(slices, 0);
    for (std::size_t s = 0; s < slices; ++s) {
      std::size_t rest = s;
      for (std::size_t i = fixed_.size(); i-- > 0;) {
        const auto k = radix.radix(fixed_[i]);
        bases[s] += (rest % k) * radix.stride(fixed_[i]);
        rest /= k;
      }
    }
    return bases;
  }

  /// The base of the slice holding configuration u.
  [[nodiscard]] std::size_t base_of(std::size_t u) const {
    const auto& radix = table_.parent_radix();
    std::size_t base = 0;
    for (auto d : fixed_) base += (u / radix.stride(d)) % radix.radix(d) * radix.stride(d);
    return base;
  }

  /// Writes u* into targets[u] for every u of the slice at `base`.
  void solve(std::size_t base, std::span<std::size_t> targets) {
    const auto j = table_.child_cardinality();
    const auto values = table_.values();
    const double epsilon = options_.epsilon;
    targets_.clear();
    double top = -1.0;
    for (std::size_t l = 0; l < cells_; ++l) {
      estimate_[l] = values[(base + offset_[l]) * j + success_];
      if (estimate_[l] > epsilon) targets_.push_back(static_cast<std::uint32_t>(l));
      if (estimate_[l] > top) top = estimate_[l];
    }
    if (targets_.empty()) {
      for (std::size_t l = 0; l < cells_; ++l) {
        if (estimate_[l] == top) targets_.push_back(static_cast<std::uint32_t>(l));
      }
    }
    if (options_.metric == prevention_options::distance::steps) {
      spread_steps();
    } else {
      nearest_in_units(epsilon);
    }
    for (std::size_t l = 0; l < cells_; ++l) {
      targets[base + offset_[l]] = base + offset_[estimate_[l] < epsilon ? best_[l] : l];
    }
  }

 private:
  /// Whether target a beats target b at equal distance: higher estimate, then lower index.
  bool better(std::uint32_t a, std::uint32_t b) const {
    return estimate_[a] > estimate_[b] || (estimate_[a] == estimate_[b] && a < b);
  }

  void spread_steps() {
    constexpr auto unseen = std::numeric_limits<std::uint32_t>::max();
    std::fill(distance_.begin(), distance_.end(), unseen);
    std::size_t head = 0;
    std::size_t tail = 0;
    for (auto t : targets_) {
      distance_[t] = 0;
      best_[t] = t;
      queue_[tail++] = t;
    }
    const auto n = dims_.size();
    const auto& radix = table_.parent_radix();
    while (head < tail) {
      const auto x = queue_[head++];
      const auto next = distance_[x] + 1;
      for (std::size_t i = 0; i < n; ++i) {
        const auto digit = digits_[x * n + i];
        const auto stride = static_cast<std::uint32_t>(local_stride_[i]);
        auto visit = [&](std::uint32_t y) {
          if (distance_[y] == unseen) {
            distance_[y] = next;
            best_[y] = best_[x];
            queue_[tail++] = y;
          } else if (distance_[y] == next && better(best_[x], best_[y])) {
            best_[y] = best_[x];
          }
        };
        if (digit > 0) visit(x - stride);
        if (digit + 1 < radix.radix(dims_[i])) visit(x + stride);
      }
    }
  }

  void nearest_in_units(double epsilon) {
    const auto n = dims_.size();
    for (std::size_t l = 0; l < cells_; ++l) {
      if (!(estimate_[l] < epsilon)) continue;
      double nearest = std::numeric_limits<double>::infinity();
      std::uint32_t pick = targets_.front();
      for (auto t : targets_) {
        double d = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
          const auto k = table_.parent_radix().radix(dims_[i]);
          d += gaps_[i][digits_[l * n + i] * k + digits_[t * n + i]];
        }
        // Sums of the same squared gaps in another order may differ in the last bit; such
        // distances count as equal.
        const double slack = 1e-9 * std::max(1.0, d);
        if (d < nearest - slack) {
          nearest = d;
          pick = t;
        } else if (d <= nearest + slack && better(t, pick)) {
          nearest = std::min(nearest, d);
          pick = t;
        }
      }
      best_[l] = pick;
    }
  }

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
[[nodiscard]] inline std::vector<std::size_t> prevention_targets(const cpt<double>& estimated,
                                                                 std::size_t success_state,
                                                                 std::span<const bool> controllable,
                                                                 const prevention_options& options = {}) {
  // A target for every configuration: a sparse table is looked at dense (within pgm's limit).
  if (estimated.is_sparse()) return prevention_targets(estimated.dense(), success_state, controllable, options);
  detail::prevention_solver solver(estimated, success_state, controllable, options);
  std::vector<std::size_t> targets(estimated.configurations());
  for (auto base : solver.slice_bases()) solver.solve(base, targets);
  return targets;
}

/// The target u* for one configuration u.
[[nodiscard]] inline std::size_t prevention_target(const cpt<double>& estimated, std::size_t success_state,
                                                   std::size_t configuration, std::span<const bool> controllable,
                                                   const prevention_options& options = {}) {
  if (configuration >= estimated.configurations()) {
    throw model_error("configuration " + std::to_string(configuration) + " is out of range for '" +
                      estimated.child().name() + "'");
  }
  if (estimated.is_sparse()) {
    return prevention_target(estimated.dense(), success_state, configuration, controllable, options);
  }
  detail::prevention_solver solver(estimated, success_state, controllable, options);
  std::vector<std::size_t> targets(estimated.configurations());
  solver.solve(solver.base_of(configuration), targets);
  return targets[configuration];
}

/// Metric 3: sum_u weight[u] · truth(success | u*(u)) / sum_u weight[u], u* chosen on
/// `estimated`. With estimated = truth this is the "oracle" value, which is not an upper bound
/// (it stops at the nearest configuration above ε). Throws model_error if the two tables differ
/// in shape, or the weights are not one non-negative finite number per configuration with a
/// positive sum.
[[nodiscard]] inline double failure_prevention_rate(const cpt<double>& estimated, const cpt<double>& truth,
                                                    std::size_t success_state, std::span<const bool> controllable,
                                                    std::span<const double> configuration_weights,
                                                    const prevention_options& options = {}) {
  if (estimated.parent_radix() != truth.parent_radix() || estimated.child_cardinality() != truth.child_cardinality()) {
    throw model_error("the estimated and the true table of '" + estimated.child().name() + "' differ in shape");
  }
  if (configuration_weights.size() != estimated.configurations()) {
    throw model_error("expected " + std::to_string(estimated.configurations()) + " configuration weights, got " +
                      std::to_string(configuration_weights.size()));
  }
  double total = 0.0;
  for (double w : configuration_weights) {
    if (!std::isfinite(w) || w < 0.0) throw model_error("configuration weights must be finite and non-negative");
    total += w;
  }
  if (!(total > 0.0)) throw model_error("the configuration weights sum to zero");
  const auto targets = prevention_targets(estimated, success_state, controllable, options);
  const auto j = truth.child_cardinality();
  double sum = 0.0;
  for (std::size_t u = 0; u < targets.size(); ++u) {
    if (configuration_weights[u] > 0.0)
      sum += configuration_weights[u] * truth.values()[targets[u] * j + success_state];
  }
  return sum / total;
}

}  // namespace pgm
