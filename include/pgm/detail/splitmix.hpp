#pragma once
/// \file
/// Internal, do not depend on it: SplitMix64's bijective mixer, which turns counters and
/// coordinates (seed, row, repetition) into independent-looking 64-bit seeds, so that results
/// depend on where work sits, never on which thread did it.

#include <cstdint>

namespace pgm::detail {

inline constexpr std::uint64_t golden_gamma = 0x9e3779b97f4a7c15ULL;

[[nodiscard]] constexpr std::uint64_t splitmix64_mix(std::uint64_t z) noexcept {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// A seed for coordinate `b` under seed `a`.
[[nodiscard]] constexpr std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b) noexcept {
  return splitmix64_mix(a + golden_gamma * (b + 1));
}

}  // namespace pgm::detail
