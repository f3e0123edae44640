#pragma once
/// \file
/// Strong index types, so that a variable id cannot be passed where a state index is meant.

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <ranges>

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

/// The indices 0, 1, …, n − 1, for range-for: `for (auto v : indices<state_index>(states))`.
template <class Index>
[[nodiscard]] constexpr auto indices(std::size_t n) {
  return std::views::iota(std::size_t{0}, n) | std::views::transform(index_at<Index>);
}

/// The ids of a model's n variables: `for (auto v : ids(model.size()))`.
[[nodiscard]] constexpr auto ids(std::size_t n) { return indices<variable_id>(n); }

}  // namespace pgm

template <class Tag, class Rep>
struct std::hash<pgm::strong_index<Tag, Rep>> {
  std::size_t operator()(pgm::strong_index<Tag, Rep> index) const noexcept { return std::hash<Rep>{}(index.value()); }
};
