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
#include "pgm/core/error.hpp"

namespace pgm {

class mixed_radix {
 public:
  mixed_radix() = default;

  /// Throws model_error when a radix is zero or the product overflows.
  explicit mixed_radix(std::vector<std::size_t> radices) : radices_(std::move(radices)), strides_(radices_.size()) {
    std::size_t size = 1;
    for (std::size_t i = radices_.size(); i-- > 0;) {
      if (radices_[i] == 0) throw model_error("a variable with no states has no configurations");
      strides_[i] = size;
      if (size > std::numeric_limits<std::size_t>::max() / radices_[i]) {
        throw model_error("the number of parent configurations overflows");
      }
      size *= radices_[i];
    }
    size_ = size;
  }

  /// Number of configurations (1 for no digits).
  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  [[nodiscard]] std::size_t digits() const noexcept { return radices_.size(); }
  [[nodiscard]] std::size_t radix(std::size_t digit) const { return radices_.at(digit); }
  [[nodiscard]] std::size_t stride(std::size_t digit) const { return strides_.at(digit); }
  [[nodiscard]] const std::vector<std::size_t>& radices() const noexcept { return radices_; }
  [[nodiscard]] const std::vector<std::size_t>& strides() const noexcept { return strides_; }

  [[nodiscard]] std::size_t encode(std::span<const std::size_t> digit_values) const {
    PGM_ASSERT(digit_values.size() == radices_.size(), "wrong number of digits");
    std::size_t index = 0;
    for (std::size_t i = 0; i < digit_values.size(); ++i) {
      PGM_ASSERT(digit_values[i] < radices_[i], "digit out of range");
      index += digit_values[i] * strides_[i];
    }
    return index;
  }

  void decode(std::size_t index, std::span<std::size_t> digit_values) const {
    PGM_ASSERT(digit_values.size() == radices_.size(), "wrong number of digits");
    PGM_ASSERT(index < size_, "index out of range");
    for (std::size_t i = 0; i < radices_.size(); ++i) {
      digit_values[i] = index / strides_[i];
      index %= strides_[i];
    }
  }

  [[nodiscard]] std::vector<std::size_t> decode(std::size_t index) const {
    std::vector<std::size_t> digit_values(radices_.size());
    decode(index, digit_values);
    return digit_values;
  }

  friend bool operator==(const mixed_radix& a, const mixed_radix& b) { return a.radices_ == b.radices_; }

 private:
  std::vector<std::size_t> radices_;
  std::vector<std::size_t> strides_;
  std::size_t size_ = 1;
};

}  // namespace pgm
