#pragma once
/// \file
/// Strong index types, so that a variable id cannot be passed where a state index is meant.

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>

namespace pgm {

template <class Tag, class Rep>
class strong_index {
 public:
  using rep = Rep;

  constexpr strong_index() noexcept = default;
  constexpr explicit strong_index(Rep value) noexcept : value_(value) {}

  [[nodiscard]] constexpr Rep value() const noexcept { return value_; }

  friend constexpr auto operator<=>(strong_index, strong_index) noexcept = default;

 private:
  Rep value_ = 0;
};

/// The position of a variable in a network, a DAG or a structure.
using variable_id = strong_index<struct variable_id_tag, std::uint32_t>;
/// The position of a state in a variable's ordered list of states.
using state_index = strong_index<struct state_index_tag, std::uint32_t>;
/// The mixed-radix index of one configuration of a node's parents.
using config_index = strong_index<struct config_index_tag, std::size_t>;

/// The index at position `i` of a container or a loop: the one conversion from a position to a
/// strong index (a network's variables, a variable's states, a table's configurations).
template <class Index>
[[nodiscard]] constexpr Index index_at(std::size_t i) noexcept {
  return Index(static_cast<typename Index::rep>(i));
}

/// The indices 0, 1, …, n − 1 as a range. A class of its own rather than std::views::iota |
/// transform, which clang 14 (the fuzzing build's compiler) cannot compile with libstdc++ 12.
template <class Index>
class index_range {
 public:
  class iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = Index;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = Index;

    constexpr iterator() noexcept = default;
    constexpr explicit iterator(std::size_t i) noexcept : i_(i) {}
    [[nodiscard]] constexpr Index operator*() const noexcept { return index_at<Index>(i_); }
    constexpr iterator& operator++() noexcept {
      ++i_;
      return *this;
    }
    constexpr iterator operator++(int) noexcept {
      auto before = *this;
      ++i_;
      return before;
    }
    friend constexpr bool operator==(iterator, iterator) noexcept = default;

   private:
    std::size_t i_ = 0;
  };

  constexpr explicit index_range(std::size_t n) noexcept : n_(n) {}
  [[nodiscard]] constexpr iterator begin() const noexcept { return iterator(0); }
  [[nodiscard]] constexpr iterator end() const noexcept { return iterator(n_); }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return n_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return n_ == 0; }

 private:
  std::size_t n_;
};

/// The indices 0, 1, …, n − 1, for range-for: `for (auto s : indices<state_index>(states))`.
template <class Index>
[[nodiscard]] constexpr index_range<Index> indices(std::size_t n) noexcept {
  return index_range<Index>(n);
}

/// The ids of a model's n variables: `for (auto v : ids(model.size()))`.
[[nodiscard]] constexpr index_range<variable_id> ids(std::size_t n) noexcept { return indices<variable_id>(n); }

}  // namespace pgm

template <class Tag, class Rep>
struct std::hash<pgm::strong_index<Tag, Rep>> {
  std::size_t operator()(pgm::strong_index<Tag, Rep> index) const noexcept { return std::hash<Rep>{}(index.value()); }
};
