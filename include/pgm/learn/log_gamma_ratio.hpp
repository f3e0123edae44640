#pragma once
/// \file
/// ln Γ(a + n) − ln Γ(a): the Dirichlet marginal likelihood's building block (BDeu, K2, the
/// prior weight's evidence), ln of a(a+1)…(a+n−1) for a whole n. As boost's lgamma difference
/// where that is exact; for a ≥ 10⁷, where ln Γ(a) nears a double's range (an imaginary sample
/// size of 10³⁰⁶ overflows it) and the difference cancels, by Stirling's series, whose large
/// terms cancel in the algebra instead: (a − ½)·log1p(n/a) + n·ln(a + n) − n + 1/(12(a + n)) − 1/(12a).

#include <boost/math/special_functions/gamma.hpp>
#include <cmath>

namespace pgm::detail {

/// ln Γ(a + n) − ln Γ(a) for one a > 0 and many n ≥ 0, ln Γ(a) computed once.
class log_gamma_ratio {
 public:
  explicit log_gamma_ratio(double a) : a_(a), large_(a >= large), lgamma_a_(large_ ? 0.0 : boost::math::lgamma(a)) {}

  [[nodiscard]] double operator()(double n) const {
    if (!large_) return boost::math::lgamma(a_ + n) - lgamma_a_;
    const double b = a_ + n;
    return (a_ - 0.5) * std::log1p(n / a_) + n * std::log(b) - n + (1.0 / (12.0 * b) - 1.0 / (12.0 * a_));
  }

 private:
  /// From here Stirling's series with one correction term is exact to a double's precision
  /// (the next term is 1/(360 a³) < 10⁻²³).
  static constexpr double large = 1e7;

  double a_;
  bool large_;
  double lgamma_a_;
};

}  // namespace pgm::detail
