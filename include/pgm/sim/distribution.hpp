#pragma once
/// \file
/// `distribution`: how a task variable is sampled — normal (optionally truncated), uniform,
/// shifted log-normal (optionally truncated above), a grid of values, a constant, or uniform
/// over categorical states. The analytic ground truth needs more than sampling, so every
/// continuous kind also gives its CDF and quantile function.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/sim/random.hpp"

namespace pgm::sim {

enum class distribution_kind { normal, uniform, lognormal, grid, constant, categorical };

[[nodiscard]] PGM_DECL const char* to_string(distribution_kind kind) noexcept;

/// Standard normal CDF.
[[nodiscard]] inline double normal_cdf(double z) noexcept { return 0.5 * std::erfc(-z / std::numbers::sqrt2); }
/// Standard normal density.
[[nodiscard]] inline double normal_pdf(double z) noexcept {
  return std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi);
}
/// Inverse of normal_cdf: Acklam's rational approximation refined by one Halley step
/// (relative error below 1e-13 on (0, 1)).
[[nodiscard]] PGM_DECL double normal_quantile(double p) noexcept;

struct distribution {
  distribution_kind kind = distribution_kind::constant;
  /// normal: mean and standard deviation; lognormal: mu and sigma of log(x - shift).
  double location = 0.0;
  double scale = 1.0;
  double shift = 0.0;
  /// Truncation (normal, lognormal) or support (uniform). Infinite when absent.
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  /// grid: the values, drawn with equal probability; constant: one value.
  std::vector<double> values;
  /// categorical: number of states, drawn with equal probability.
  std::size_t states = 0;

  [[nodiscard]] bool continuous() const noexcept {
    return kind == distribution_kind::normal || kind == distribution_kind::uniform ||
           kind == distribution_kind::lognormal;
  }

  /// One draw. Categorical draws are state indices. Truncation is by rejection: the task
  /// files keep the truncated mass small, so few draws are rejected.
  PGM_DECL double sample(random_stream& random) const;

  /// The untruncated CDF of a continuous kind (the standardised value for normal, lognormal).
  [[nodiscard]] PGM_DECL double raw_cdf(double x) const noexcept;
  [[nodiscard]] PGM_DECL double raw_quantile(double p) const noexcept;
};

}  // namespace pgm::sim

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/sim/impl/distribution.ipp"
#endif
