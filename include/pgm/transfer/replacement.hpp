#pragma once
/// \file
/// The paper's three strategies (Sec. III-B): Direct-Replacement (u′ = u restricted to the
/// identical parents), Cross-Replacement (u′ = u restricted to the related parents, read as
/// their prior counterparts) and Minimal-Replacement (eq. 9: per u, whichever of the two gives
/// the smaller prior success probability; for a child with more than two states the success
/// states are compared and the winner's whole distribution is taken, so columns still sum to 1).

#include <string_view>
#include <vector>

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
  [[nodiscard]] transferred_prior operator()(const transfer_problem& problem) const {
    const std::size_t success = problem.success_state();
    const auto direct = direct_replacement{}(problem);
    const auto cross = cross_replacement{}(problem);
    const auto& table = direct.table();
    std::vector<double> values;
    values.reserve(table.size());
    std::vector<prior_term> terms;
    std::vector<std::uint32_t> counts;
    std::vector<replacement> via;
    for (std::size_t u = 0; u < table.configurations(); ++u) {
      const config_index c(static_cast<config_index::rep>(u));
      // Eq. 9: the direct candidate only when strictly smaller; ties go to cross.
      const bool take_direct = direct.table().column(c)[success] < cross.table().column(c)[success];
      const auto& chosen = take_direct ? direct : cross;
      const auto column = chosen.table().column(c);
      values.insert(values.end(), column.begin(), column.end());
      const auto sources = chosen.sources(c);
      terms.insert(terms.end(), sources.begin(), sources.end());
      counts.push_back(static_cast<std::uint32_t>(sources.size()));
      via.push_back(take_direct ? replacement::direct : replacement::cross);
    }
    return transferred_prior(cpt<double>(table.child(), table.parents(), std::move(values)),
                             direct.prior_parents(), std::move(terms), std::move(counts), std::move(via));
  }
};

static_assert(PriorTransfer<direct_replacement>);
static_assert(PriorTransfer<cross_replacement>);
static_assert(PriorTransfer<minimal_replacement>);

}  // namespace pgm
