#pragma once
// The definitions of pgm/core/mixed_radix.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/core/mixed_radix.hpp"

namespace pgm {

PGM_DECL mixed_radix::mixed_radix(std::vector<std::size_t> radices)
    : radices_(std::move(radices)), strides_(radices_.size()) {
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

PGM_DECL std::size_t mixed_radix::encode(std::span<const std::size_t> digit_values) const {
  PGM_ASSERT(digit_values.size() == radices_.size(), "wrong number of digits");
  std::size_t index = 0;
  for (std::size_t i = 0; i < digit_values.size(); ++i) {
    PGM_ASSERT(digit_values[i] < radices_[i], "digit out of range");
    index += digit_values[i] * strides_[i];
  }
  return index;
}

PGM_DECL void mixed_radix::decode(std::size_t index, std::span<std::size_t> digit_values) const {
  PGM_ASSERT(digit_values.size() == radices_.size(), "wrong number of digits");
  PGM_ASSERT(index < size_, "index out of range");
  for (std::size_t i = 0; i < radices_.size(); ++i) {
    digit_values[i] = index / strides_[i];
    index %= strides_[i];
  }
}

PGM_DECL std::vector<std::size_t> mixed_radix::decode(std::size_t index) const {
  std::vector<std::size_t> digit_values(radices_.size());
  decode(index, digit_values);
  return digit_values;
}

}  // namespace pgm
