#pragma once
// The definitions of pgm/transfer/replacement_plan.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/transfer/replacement_plan.hpp"

namespace pgm::detail {

PGM_DECL std::vector<weighted_state> prior_marginal(const transfer_problem& problem, const variable& v) {
  const auto* network = problem.prior_network();
  if (!network) {
    throw model_error("marginalizing the prior's '" + v.name() + "' needs the prior network, not only its table");
  }
  const auto& table = network->table(v.name());
  if (!table.parents().empty()) {
    throw model_error("the prior's '" + v.name() +
                      "' has parents, so its marginal would need inference; pin it to a value instead");
  }
  std::vector<weighted_state> shares;
  for (std::size_t s = 0; s < v.cardinality(); ++s) {
    const double p = table.column(config_index(0))[s];
    if (p > 0) shares.push_back({s, p});
  }
  return shares;
}

PGM_DECL std::vector<std::size_t> match_child(const transfer_problem& problem) {
  const auto& target = problem.target_child();
  const auto& prior = problem.prior_table().child();
  const auto mapping = map_states(target, prior);
  std::vector<std::size_t> child(mapping.size());
  std::vector<bool> used(prior.cardinality(), false);
  for (std::size_t s = 0; s < mapping.size(); ++s) {
    child[s] = mapping[s].front().state;
    if (used[child[s]]) break;
    used[child[s]] = true;
  }
  if (target.cardinality() != prior.cardinality() || std::find(used.begin(), used.end(), false) != used.end()) {
    throw model_error("the states of '" + target.name() + "' {" + text::list_for_message(target.states()) +
                      "} and of the prior's '" + prior.name() + "' {" + text::list_for_message(prior.states()) +
                      "} do not correspond one to one");
  }
  return child;
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL replacement_plan direct_plan(const transfer_problem& problem) {
  const auto& map = problem.map();
  return make_plan(
      problem, [&](const std::string& target) { return std::optional(map.identical_to(target)); },
      "Direct-Replacement");
}

PGM_DECL replacement_plan cross_plan(const transfer_problem& problem) {
  const auto& map = problem.map();
  return make_plan(
      problem, [&](const std::string& target) { return map.related_to(target); }, "Cross-Replacement");
}

PGM_DECL plan_terms expand_plan(const replacement_plan& plan, const transfer_problem& problem) {
  const auto& prior_strides = problem.prior_table().parent_radix().strides();
  const auto& targets = problem.target_parents();
  std::vector<std::size_t> target_cards;
  for (const auto& t : targets) target_cards.push_back(t.cardinality());
  const mixed_radix target_radix(std::move(target_cards));
  const std::size_t k = plan.parents.size();
  plan_terms out;
  out.counts.resize(target_radix.size());
  std::vector<std::size_t> digits(targets.size(), 0);

  const bool single = std::all_of(plan.parents.begin(), plan.parents.end(), [](const parent_source& s) {
    if (!s.target_parent) return s.fixed.size() == 1;
    return std::all_of(s.mapping.begin(), s.mapping.end(), [](const auto& m) { return m.size() == 1; });
  });
  if (single) {
    // One u′ per u: u′'s index is a fixed part plus one offset per target parent digit, so
    // walking u in order only adjusts the sum by the digits that change.
    std::size_t fixed = 0;
    std::vector<std::size_t> first_offset(targets.size() + 1, 0);
    for (std::size_t t = 0; t < targets.size(); ++t) first_offset[t + 1] = first_offset[t] + targets[t].cardinality();
    std::vector<std::size_t> offset(first_offset.back(), 0);
    for (std::size_t p = 0; p < k; ++p) {
      const auto& source = plan.parents[p];
      if (!source.target_parent) {
        fixed += source.fixed.front().state * prior_strides[p];
        continue;
      }
      for (std::size_t s = 0; s < source.mapping.size(); ++s) {
        offset[first_offset[*source.target_parent] + s] += source.mapping[s].front().state * prior_strides[p];
      }
    }
    out.terms.resize(target_radix.size());
    std::fill(out.counts.begin(), out.counts.end(), 1U);
    std::size_t configuration = fixed;
    for (std::size_t t = 0; t < targets.size(); ++t) configuration += offset[first_offset[t]];
    for (std::size_t u = 0; u < target_radix.size(); ++u) {
      out.terms[u] = {static_cast<std::uint32_t>(configuration), 1.0};
      for (std::size_t d = digits.size(); d > 0; --d) {
        const std::size_t t = d - 1;
        configuration -= offset[first_offset[t] + digits[t]];
        if (++digits[t] == target_radix.radix(t)) digits[t] = 0;
        configuration += offset[first_offset[t] + digits[t]];
        if (digits[t] != 0) break;
      }
    }
    return out;
  }

  std::vector<const std::vector<weighted_state>*> choices(k);
  std::vector<std::size_t> pick(k);
  for (std::size_t u = 0; u < target_radix.size(); ++u) {
    for (std::size_t p = 0; p < k; ++p) {
      const auto& source = plan.parents[p];
      choices[p] = source.target_parent ? &source.mapping[digits[*source.target_parent]] : &source.fixed;
    }
    // Odometer over the combinations of weighted prior states.
    std::fill(pick.begin(), pick.end(), 0);
    std::uint32_t count = 0;
    while (true) {
      std::size_t configuration = 0;
      double weight = 1.0;
      for (std::size_t p = 0; p < k; ++p) {
        const auto& chosen = (*choices[p])[pick[p]];
        configuration += chosen.state * prior_strides[p];
        weight *= chosen.weight;
      }
      out.terms.push_back({static_cast<std::uint32_t>(configuration), weight});
      ++count;
      std::size_t p = k;
      while (p > 0 && ++pick[p - 1] == choices[p - 1]->size()) pick[--p] = 0;
      if (p == 0) break;
    }
    out.counts[u] = count;
    for (std::size_t d = digits.size(); d > 0 && ++digits[d - 1] == target_radix.radix(d - 1);) digits[--d] = 0;
  }
  return out;
}

PGM_DECL std::vector<double> mix_prior_columns(const plan_terms& expanded, const replacement_plan& plan,
                                               const cpt<double>& prior) {
  const std::size_t j = plan.child_state.size();
  std::vector<double> values(expanded.counts.size() * j, 0.0);
  // A sparse prior table (fitted from few rows) is read column by column, as it is stored.
  const double* dense = prior.is_sparse() ? nullptr : prior.values().data();
  std::size_t next = 0;
  for (std::size_t u = 0; u < expanded.counts.size(); ++u) {
    for (std::uint32_t n = 0; n < expanded.counts[u]; ++n, ++next) {
      const auto& term = expanded.terms[next];
      const double* column =
          dense ? dense + std::size_t{term.configuration} * j : prior.column(config_index(term.configuration)).data();
      for (std::size_t x = 0; x < j; ++x) values[u * j + x] += term.weight * column[plan.child_state[x]];
    }
  }
  return values;
}

PGM_DECL transferred_prior evaluate_plan(const replacement_plan& plan, const transfer_problem& problem,
                                         replacement via) {
  auto expanded = expand_plan(plan, problem);
  auto values = mix_prior_columns(expanded, plan, problem.prior_table());
  const auto configurations = expanded.counts.size();
  return transferred_prior(cpt<double>(problem.target_child(), problem.target_parents(), std::move(values)),
                           problem.prior_table().parents(), std::move(expanded.terms), std::move(expanded.counts),
                           std::vector<replacement>(configurations, via));
}

}  // namespace pgm
