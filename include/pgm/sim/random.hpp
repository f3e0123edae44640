#pragma once
/// \file
/// `random_stream`: the random numbers of one simulated experiment. Every experiment draws
/// from its own stream, keyed by (seed, experiment index, purpose) through SplitMix64, so the
/// data set is the same whatever the number of threads and however rows are shared out, and
/// one row can be reproduced on its own.

#include <cmath>
#include <cstdint>
#include <numbers>

#include "pgm/core/compilation.hpp"
#include "pgm/detail/splitmix.hpp"

namespace pgm::sim {

/// What a stream is for: the sampled task variables and the simulator's noise are separate
/// streams, so that two back-ends given one seed see the same inputs; the experiment's split
/// of a target's rows into D and D_GroundTruth is a third (pgm::split_rows).
enum class stream_purpose : std::uint64_t { inputs = 1, noise = 2, split = 3 };

class random_stream {
 public:
  random_stream(std::uint64_t seed, std::uint64_t experiment, stream_purpose purpose) noexcept
      : state_(mix(mix(seed ^ 0x6a09e667f3bcc909ULL) + experiment * 0x9e3779b97f4a7c15ULL +
                   static_cast<std::uint64_t>(purpose))) {}

  /// The next 64 random bits (SplitMix64: a counter run through a bijective mixer).
  std::uint64_t next() noexcept {
    state_ += 0x9e3779b97f4a7c15ULL;
    return mix(state_);
  }
  /// Uniform on [0, 1) with 53 random bits.
  double uniform() noexcept { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// Uniform on [lo, hi).
  double uniform(double lo, double hi) noexcept { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [0, n).
  std::uint64_t below(std::uint64_t n) noexcept {
    return static_cast<std::uint64_t>(uniform() * static_cast<double>(n));
  }
  /// Standard normal (Box–Muller; the second value of each pair is kept for the next call).
  PGM_DECL double normal() noexcept;

  [[nodiscard]] static constexpr std::uint64_t mix(std::uint64_t z) noexcept { return pgm::detail::splitmix64_mix(z); }

 private:
  std::uint64_t state_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace pgm::sim

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/sim/impl/random.ipp"
#endif
