#pragma once
/// \file
/// The paper's three strategies (Sec. III-B): Direct-Replacement (u′ = u restricted to the
/// identical parents), Cross-Replacement (u′ = u restricted to the related parents, read as
/// their prior counterparts) and Minimal-Replacement (eq. 9: per u, whichever of the two gives
/// the smaller prior success probability; for a child with more than two states the success
/// states are compared and the winner's whole distribution is taken, so columns still sum to 1).

#include <algorithm>
#include <string_view>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/transfer/prior_transfer.hpp"
#include "pgm/transfer/replacement_plan.hpp"

namespace pgm {

struct direct_replacement {
  [[nodiscard]] static constexpr std::string_view name() noexcept { return "direct"; }
  [[nodiscard]] transferred_prior operator()(const transfer_problem& problem) const {
    return evaluate_plan(direct_plan(problem), problem, replacement::direct);
  }
};

struct cross_replacement {
  [[nodiscard]] static constexpr std::string_view name() noexcept { return "cross"; }
  [[nodiscard]] transferred_prior operator()(const transfer_problem& problem) const {
    return evaluate_plan(cross_plan(problem), problem, replacement::cross);
  }
};

struct minimal_replacement {
  [[nodiscard]] static constexpr std::string_view name() noexcept { return "minimal"; }
  [[nodiscard]] PGM_DECL transferred_prior operator()(const transfer_problem& problem) const;
};

static_assert(PriorTransfer<direct_replacement>);
static_assert(PriorTransfer<cross_replacement>);
static_assert(PriorTransfer<minimal_replacement>);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/transfer/impl/replacement.ipp"
#endif
