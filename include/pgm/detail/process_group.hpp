#pragma once
/// \file
/// Internal, do not depend on it: values as bytes between the processes of a group
/// (pgm/core/process_group.hpp), for the gathers and broadcasts of count_csv and the drivers.

#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "pgm/core/compilation.hpp"
#include "pgm/core/process_group.hpp"

namespace pgm::detail {

/// Appends values to bytes for another process of the same machine type (pgm's clusters are
/// homogeneous: values cross in their in-memory form).
class byte_writer {
 public:
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void put(const T& value) {
    const auto* bytes = reinterpret_cast<const char*>(&value);
    bytes_.append(bytes, sizeof(T));
  }
  void put(std::string_view text) {
    put<std::uint64_t>(text.size());
    bytes_.append(text);
  }
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void put_all(std::span<const T> values) {
    bytes_.append(reinterpret_cast<const char*>(values.data()), values.size_bytes());
  }
  [[nodiscard]] std::string take() noexcept { return std::move(bytes_); }

 private:
  std::string bytes_;
};

/// Reads what a byte_writer wrote, in the same order. Reading past the end is a logic error.
class byte_reader {
 public:
  explicit byte_reader(std::string_view bytes) noexcept : bytes_(bytes) {}
  template <class T>
  requires std::is_trivially_copyable_v<T>
  [[nodiscard]] T get() {
    T value;
    std::memcpy(&value, take(sizeof(T)).data(), sizeof(T));
    return value;
  }
  [[nodiscard]] std::string get_string() { return std::string(take(get<std::uint64_t>())); }
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void get_all(std::span<T> values) {
    const auto bytes = take(values.size_bytes());
    if (!bytes.empty()) std::memcpy(values.data(), bytes.data(), bytes.size());
  }
  [[nodiscard]] bool at_end() const noexcept { return bytes_.empty(); }

 private:
  PGM_DECL std::string_view take(std::size_t n);
  std::string_view bytes_;
};

}  // namespace pgm::detail

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/detail/impl/process_group.ipp"
#endif
