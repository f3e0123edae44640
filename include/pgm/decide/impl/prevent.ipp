#pragma once
// The definitions of pgm/decide/prevent.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/decide/prevent.hpp"

namespace pgm::detail {

PGM_DECL void check_epsilon(double epsilon) {
  if (!(epsilon >= 0.0 && epsilon < 1.0)) {
    throw model_error(
        "epsilon must be at least 0 and below 1 (success is a prediction above epsilon, and no "
        "probability exceeds 1), got " +
        text::format_double(epsilon));
  }
}

PGM_DECL void check_prevention_inputs(const cpt<double>& table, std::size_t success_state,
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

PGM_DECL std::vector<std::vector<double>> squared_midpoint_gaps(const cpt<double>& table,
                                                                const std::vector<std::size_t>& dims) {
  std::vector<std::vector<double>> gaps;
  for (auto d : dims) {
    const auto& v = table.parents()[d];
    const auto k = v.cardinality();
    std::vector<double> mid(k);
    for (std::size_t s = 0; s < k; ++s) {
      const auto m = v.midpoint(index_at<state_index>(s));
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

PGM_DECL prevention_solver::prevention_solver(const cpt<double>& table, std::size_t success_state,
                                              std::span<const bool> controllable, const prevention_options& options)
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

PGM_DECL std::vector<std::size_t> prevention_solver::slice_bases() const {
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

PGM_DECL std::size_t prevention_solver::base_of(std::size_t u) const {
  const auto& radix = table_.parent_radix();
  std::size_t base = 0;
  for (auto d : fixed_) base += (u / radix.stride(d)) % radix.radix(d) * radix.stride(d);
  return base;
}

PGM_DECL void prevention_solver::solve(std::size_t base, std::span<std::size_t> targets) {
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

PGM_DECL void prevention_solver::spread_steps() {
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

PGM_DECL void prevention_solver::nearest_in_units(double epsilon) {
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

}  // namespace pgm::detail

namespace pgm {

PGM_DECL std::vector<std::size_t> prevention_targets(const cpt<double>& estimated, std::size_t success_state,
                                                     std::span<const bool> controllable,
                                                     const prevention_options& options) {
  // A target for every configuration: a sparse table is looked at dense (within pgm's limit).
  if (estimated.is_sparse()) return prevention_targets(estimated.dense(), success_state, controllable, options);
  detail::prevention_solver solver(estimated, success_state, controllable, options);
  std::vector<std::size_t> targets(estimated.configurations());
  for (auto base : solver.slice_bases()) solver.solve(base, targets);
  return targets;
}

PGM_DECL std::size_t prevention_target(const cpt<double>& estimated, std::size_t success_state,
                                       std::size_t configuration, std::span<const bool> controllable,
                                       const prevention_options& options) {
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

namespace detail {

PGM_DECL double checked_weight_total(std::span<const double> weights, std::size_t configurations) {
  if (weights.size() != configurations) {
    throw model_error("expected " + std::to_string(configurations) + " configuration weights, got " +
                      std::to_string(weights.size()));
  }
  double total = 0.0;
  for (double w : weights) {
    if (!std::isfinite(w) || w < 0.0) throw model_error("configuration weights must be finite and non-negative");
    total += w;
  }
  if (!(total > 0.0)) throw model_error("the configuration weights sum to zero");
  return total;
}

}  // namespace detail

PGM_DECL double failure_prevention_rate(const cpt<double>& estimated, const cpt<double>& truth,
                                        std::size_t success_state, std::span<const bool> controllable,
                                        std::span<const double> configuration_weights,
                                        const prevention_options& options) {
  if (estimated.parent_radix() != truth.parent_radix() || estimated.child_cardinality() != truth.child_cardinality()) {
    throw model_error("the estimated and the true table of '" + estimated.child().name() + "' differ in shape");
  }
  const double total = detail::checked_weight_total(configuration_weights, estimated.configurations());
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
