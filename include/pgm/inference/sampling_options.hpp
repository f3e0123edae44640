#pragma once
/// \file
/// The settings of the sampling engines (likelihood weighting, Gibbs sampling), and the rule
/// that makes them repeatable: samples come in blocks of a fixed size, each block drawing from
/// its own stream keyed by (seed, block), and blocks are summed in block order — so a seed gives
/// the same numbers for any thread count.

#include <cstddef>
#include <cstdint>

#include "pgm/detail/splitmix.hpp"

namespace pgm {

struct sampling_options {
  /// Samples per query (for Gibbs, after burn-in, over all chains together).
  std::size_t samples = 100'000;
  std::uint64_t seed = 1;
  /// Threads, the calling one included; 0 uses every hardware thread.
  unsigned threads = 0;
  /// Gibbs sampling: independent chains, and sweeps each discards before it counts.
  std::size_t chains = 4;
  std::size_t burn_in = 1'000;
};

namespace detail {

/// Samples per block of likelihood weighting: large enough to pay for a thread's hand-off.
inline constexpr std::size_t sampling_block = 4096;

/// A SplitMix64 stream: 64 random bits per step, uniform doubles from the top 53.
class sample_stream {
 public:
  explicit sample_stream(std::uint64_t seed) noexcept : state_(seed) {}
  std::uint64_t next() noexcept {
    state_ += golden_gamma;
    return splitmix64_mix(state_);
  }
  double uniform() noexcept { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

 private:
  std::uint64_t state_;
};

}  // namespace detail

}  // namespace pgm
