#pragma once
/// \file
/// Mixed-radix numbering of parent configurations. The last digit varies fastest (row-major,
/// as pgmpy and NumPy order a table), so the index of (u_1, …, u_k) is
/// sum_i u_i * stride_i with stride_k = 1.

#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "pgm/core/assert.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"

namespace pgm {

class mixed_radix {
 public:
  mixed_radix() = default;

  /// Throws model_error when a radix is zero or the product overflows.
  PGM_DECL explicit mixed_radix(std::vector<std::size_t> radices);

  /// Number of configurations (1 for no digits).
  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  [[nodiscard]] std::size_t digits() const noexcept { return radices_.size(); }
  [[nodiscard]] std::size_t radix(std::size_t digit) const { return radices_.at(digit); }
  [[nodiscard]] std::size_t stride(std::size_t digit) const { return strides_.at(digit); }
  [[nodiscard]] const std::vector<std::size_t>& radices() const noexcept { return radices_; }
  [[nodiscard]] const std::vector<std::size_t>& strides() const noexcept { return strides_; }

  [[nodiscard]] PGM_DECL std::size_t encode(std::span<const std::size_t> digit_values) const;

  PGM_DECL void decode(std::size_t index, std::span<std::size_t> digit_values) const;

  [[nodiscard]] PGM_DECL std::vector<std::size_t> decode(std::size_t index) const;

  friend bool operator==(const mixed_radix& a, const mixed_radix& b) { return a.radices_ == b.radices_; }

 private:
  std::vector<std::size_t> radices_;
  std::vector<std::size_t> strides_;
  std::size_t size_ = 1;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/mixed_radix.ipp"
#endif
