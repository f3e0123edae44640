#pragma once
/// \file
/// The `PriorTransfer` concept: a transfer strategy has a `name()` and a const call that maps a
/// `transfer_problem` (prior family, target family, correspondence) to a `transferred_prior`.
/// Direct-, Cross- and Minimal-Replacement model it; so does any strategy a user writes, in
/// their own translation unit, with nothing else to derive from or register.

#include <concepts>
#include <string_view>

#include "pgm/transfer/transfer_problem.hpp"

namespace pgm {

namespace detail {

/// A strategy names itself, for the registry, the program and the plots.
template <class S>
concept NamedStrategy = requires(const S& s) {
  { s.name() } -> std::convertible_to<std::string_view>;
};

/// A strategy maps a problem to a prior without changing itself, so one object can serve
/// many nodes and threads.
template <class S>
concept MapsProblemToPrior = requires(const S& s, const transfer_problem& problem) {
  { s(problem) } -> std::same_as<transferred_prior>;
};

}  // namespace detail

template <class S>
concept PriorTransfer = std::copy_constructible<S> && detail::NamedStrategy<S> && detail::MapsProblemToPrior<S>;

}  // namespace pgm
