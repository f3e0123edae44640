#pragma once
/// \file
/// The semirings exact inference runs in. One elimination or propagation code, instantiated per
/// semiring, answers three questions:
///
/// | semiring | ⊕ | ⊗ | stores | answers |
/// |---|---|---|---|---|
/// | `sum_product<T>` | + | × | probabilities | marginals, P(evidence) |
/// | `max_product<T>` | max | × | probabilities | the most probable explanation (MPE) |
/// | `log_sum_product<T>` | log-sum-exp | + | log-probabilities | marginals when P(evidence) underflows |
/// | `log_max_product<T>` | max | + | log-probabilities | MPE when its probability underflows |
///
/// A semiring of one's own models `Semiring`: a value type, the identities of ⊕ and ⊗, the two
/// operations, and the conversions from and to a probability.

#include <algorithm>
#include <cmath>
#include <concepts>
#include <limits>

namespace pgm {

namespace detail {

template <class S>
concept HasSemiringValues = requires {
  typename S::value_type;
  requires std::floating_point<typename S::value_type>;
  { S::zero() } -> std::same_as<typename S::value_type>;
  { S::one() } -> std::same_as<typename S::value_type>;
};

template <class S>
concept HasSemiringOperations = requires(typename S::value_type a, typename S::value_type b) {
  { S::plus(a, b) } -> std::same_as<typename S::value_type>;
  { S::times(a, b) } -> std::same_as<typename S::value_type>;
};

template <class S>
concept HasProbabilityConversions = requires(double p, typename S::value_type a) {
  { S::from_probability(p) } -> std::same_as<typename S::value_type>;
  { S::to_probability(a) } -> std::same_as<double>;
};

}  // namespace detail

/// A commutative semiring over a floating-point type, with the probability it stands for.
/// `idempotent` (⊕ is max) tells elimination that an argument of the maximum can be traced back.
template <class S>
concept Semiring = detail::HasSemiringValues<S> && detail::HasSemiringOperations<S> &&
    detail::HasProbabilityConversions<S> && requires {
  { S::idempotent } -> std::convertible_to<bool>;
};

/// Probabilities, summed and multiplied: marginals.
template <std::floating_point T = double>
struct sum_product {
  using value_type = T;
  static constexpr bool idempotent = false;
  static constexpr T zero() noexcept { return T{0}; }
  static constexpr T one() noexcept { return T{1}; }
  static constexpr T plus(T a, T b) noexcept { return a + b; }
  static constexpr T times(T a, T b) noexcept { return a * b; }
  static constexpr T from_probability(double p) noexcept { return static_cast<T>(p); }
  static constexpr double to_probability(T a) noexcept { return static_cast<double>(a); }
};

/// Probabilities, maximized and multiplied: the most probable joint state.
template <std::floating_point T = double>
struct max_product {
  using value_type = T;
  static constexpr bool idempotent = true;
  static constexpr T zero() noexcept { return T{0}; }
  static constexpr T one() noexcept { return T{1}; }
  static constexpr T plus(T a, T b) noexcept { return std::max(a, b); }
  static constexpr T times(T a, T b) noexcept { return a * b; }
  static constexpr T from_probability(double p) noexcept { return static_cast<T>(p); }
  static constexpr double to_probability(T a) noexcept { return static_cast<double>(a); }
};

/// Natural logarithms of probabilities: products become sums, so no product underflows; sums
/// are log-sum-exp. log 0 is −∞.
template <std::floating_point T = double>
struct log_sum_product {
  using value_type = T;
  static constexpr bool idempotent = false;
  static constexpr T zero() noexcept { return -std::numeric_limits<T>::infinity(); }
  static constexpr T one() noexcept { return T{0}; }
  static T plus(T a, T b) noexcept {
    if (a < b) std::swap(a, b);
    if (b == zero()) return a;
    return a + std::log1p(std::exp(b - a));
  }
  static constexpr T times(T a, T b) noexcept { return a + b; }
  static T from_probability(double p) noexcept { return static_cast<T>(std::log(p)); }
  static double to_probability(T a) noexcept { return std::exp(static_cast<double>(a)); }
};

/// Logarithms, maximized and added: the most probable joint state whose probability would
/// underflow a double.
template <std::floating_point T = double>
struct log_max_product {
  using value_type = T;
  static constexpr bool idempotent = true;
  static constexpr T zero() noexcept { return -std::numeric_limits<T>::infinity(); }
  static constexpr T one() noexcept { return T{0}; }
  static constexpr T plus(T a, T b) noexcept { return std::max(a, b); }
  static constexpr T times(T a, T b) noexcept { return a + b; }
  static T from_probability(double p) noexcept { return static_cast<T>(std::log(p)); }
  static double to_probability(T a) noexcept { return std::exp(static_cast<double>(a)); }
};

static_assert(Semiring<sum_product<>> && Semiring<max_product<>> && Semiring<log_sum_product<>> &&
              Semiring<log_max_product<>> && Semiring<sum_product<float>>);

/// Whether a semiring stores logarithms (its `one()` is 0), so a result is exponentiated.
template <Semiring S>
inline constexpr bool stores_logarithms = S::one() == typename S::value_type{0};

}  // namespace pgm
