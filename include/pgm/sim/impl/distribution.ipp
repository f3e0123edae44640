#pragma once
// The definitions of pgm/sim/distribution.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/sim/distribution.hpp"

namespace pgm::sim {

PGM_DECL const char* to_string(distribution_kind kind) noexcept {
  switch (kind) {
    case distribution_kind::normal:
      return "normal";
    case distribution_kind::uniform:
      return "uniform";
    case distribution_kind::lognormal:
      return "lognormal";
    case distribution_kind::grid:
      return "grid";
    case distribution_kind::constant:
      return "constant";
    case distribution_kind::categorical:
      return "categorical";
  }
  return "?";
}

PGM_DECL double normal_quantile(double p) noexcept {
  if (p <= 0.0) return -std::numeric_limits<double>::infinity();
  if (p >= 1.0) return std::numeric_limits<double>::infinity();
  constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,  -2.759285104469687e+02,
                          1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02, 6.680131188771972e+01,
                          -1.328068155288572e+01};
  constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                          -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00, 3.754408661907416e+00};
  constexpr double low = 0.02425;
  double x;
  if (p < low) {
    const double q = std::sqrt(-2.0 * std::log(p));
    x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  } else if (p <= 1.0 - low) {
    const double q = p - 0.5;
    const double r = q * q;
    x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
        (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
  } else {
    const double q = std::sqrt(-2.0 * std::log(1.0 - p));
    x = -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  }
  const double e = normal_cdf(x) - p;
  const double u = e * std::sqrt(2.0 * std::numbers::pi) * std::exp(0.5 * x * x);
  return x - u / (1.0 + 0.5 * x * u);
}

PGM_DECL double distribution::sample(random_stream& random) const {
  switch (kind) {
    case distribution_kind::normal:
      for (;;) {
        const double x = location + scale * random.normal();
        if (x >= min && x <= max) return x;
      }
    case distribution_kind::uniform:
      return random.uniform(min, max);
    case distribution_kind::lognormal:
      for (;;) {
        const double x = shift + std::exp(location + scale * random.normal());
        if (x >= min && x <= max) return x;
      }
    case distribution_kind::grid:
      return values[random.below(values.size())];
    case distribution_kind::constant:
      return values.front();
    case distribution_kind::categorical:
      return static_cast<double>(random.below(states));
  }
  return 0.0;
}

PGM_DECL double distribution::raw_cdf(double x) const noexcept {
  switch (kind) {
    case distribution_kind::normal:
      return normal_cdf((x - location) / scale);
    case distribution_kind::uniform:
      return std::clamp((x - min) / (max - min), 0.0, 1.0);
    case distribution_kind::lognormal:
      return x <= shift ? 0.0 : normal_cdf((std::log(x - shift) - location) / scale);
    default:
      return 0.0;
  }
}

PGM_DECL double distribution::raw_quantile(double p) const noexcept {
  switch (kind) {
    case distribution_kind::normal:
      return location + scale * normal_quantile(p);
    case distribution_kind::uniform:
      return min + p * (max - min);
    case distribution_kind::lognormal:
      return shift + std::exp(location + scale * normal_quantile(p));
    default:
      return 0.0;
  }
}

}  // namespace pgm::sim
