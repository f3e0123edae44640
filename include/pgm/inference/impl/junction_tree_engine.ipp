#pragma once
// The definitions of pgm/inference/junction_tree_engine.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/inference/junction_tree_engine.hpp"

namespace pgm {

PGM_DECL void junction_tree_engine::set_evidence(evidence_set observed) {
  evidence_ = std::move(observed);
  ++version_;
  queries_since_evidence_ = 0;
}

PGM_DECL posterior junction_tree_engine::joint(std::span<const variable_id> query) {
  if (eliminating_pays(query)) {
    auto result = elimination().joint(query);
    result.engine = std::string(name());
    return result;
  }
  return detail::exact_posterior(*network_, query, evidence_, std::string(name()),
                                 [&]<Semiring S>() { return in<S>().joint(query); });
}

PGM_DECL std::vector<posterior> junction_tree_engine::marginals(std::span<const variable_id> nodes) {
  std::vector<posterior> result;
  result.reserve(nodes.size());
  if (eliminating_each_pays(nodes)) {
    // Each variable's relevant part is small (pathfinder's findings hang from one node):
    // eliminating them one by one beats the propagation.
    for (auto node : nodes) {
      const variable_id one[] = {node};
      result.push_back(elimination().joint(one));
      result.back().engine = std::string(name());
    }
    return result;
  }
  const auto sums = in<sum_product<double>>().marginals(nodes);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    double total = 0.0;
    for (double v : sums[i]) total += v;
    if (!detail::well_represented(total)) {
      // Underflow somewhere: every marginal from log space, each on its own.
      result.clear();
      for (auto node : nodes) {
        const variable_id one[] = {node};
        result.push_back(joint(one));
      }
      return result;
    }
    posterior p;
    p.engine = std::string(name());
    p.variables.push_back(network_->variables()[nodes[i].value()]);
    p.table = factor({nodes[i]}, {sums[i].size()}, sums[i]);
    p.table.normalize();
    p.evidence_probability = total;
    p.log_evidence_probability = std::log(total);
    result.push_back(std::move(p));
  }
  return result;
}

PGM_DECL mpe_result junction_tree_engine::mpe(std::span<const variable_id> variables) {
  std::vector<variable_id> unobserved;
  for (std::size_t i = 0; i < network_->size(); ++i) {
    const variable_id id(static_cast<variable_id::rep>(i));
    if (!evidence_.fixes(id)) unobserved.push_back(id);
  }
  const double log_evidence = log_probability_of_evidence();
  std::vector<variable_id> chosen(variables.begin(), variables.end());
  std::sort(chosen.begin(), chosen.end());
  if (!variables.empty() && chosen != unobserved) {
    auto result = elimination().mpe(variables);
    result.engine = std::string(name());
    return result;
  }
  return detail::exact_mpe(*network_, unobserved, evidence_, log_evidence, std::string(name()), [&]<Semiring S>() {
    auto best = in<S>().maximize();
    std::vector<std::size_t> states;
    for (auto id : unobserved) states.push_back(best.states[id.value()]);
    return std::pair{std::move(states), best.value};
  });
}

PGM_DECL std::size_t junction_tree_engine::relevant_cells(std::span<const variable_id> query) const {
  const auto relevant = detail::relevant_set(*network_, query, evidence_);
  std::size_t cells = 0;
  for (std::size_t i = 0; i < network_->size(); ++i) {
    if (relevant[i]) cells += network_->tables()[i].size();
  }
  return cells;
}

PGM_DECL bool junction_tree_engine::eliminating_pays(std::span<const variable_id> query) {
  const auto shared = ++queries_since_evidence_;
  if (!options_.prune) return false;
  auto& sums = in<sum_product<double>>();
  const std::size_t c[] = {sums.smallest_holding(query)};
  if (c[0] >= tree_->cliques().size()) return false;
  return detail::saturating_multiply(relevant_cells(query), elimination_cell_cost * shared) < sums.cost_of_beliefs(c);
}

PGM_DECL bool junction_tree_engine::eliminating_each_pays(std::span<const variable_id> nodes) {
  if (!options_.prune) return false;
  std::size_t eliminating = 0;
  std::vector<std::size_t> homes;
  for (auto node : nodes) {
    const variable_id one[] = {node};
    eliminating = detail::saturating_add(eliminating, relevant_cells(one));
    homes.push_back(tree_->home(node));
  }
  std::sort(homes.begin(), homes.end());
  homes.erase(std::unique(homes.begin(), homes.end()), homes.end());
  return detail::saturating_multiply(eliminating, elimination_cell_cost) <
         in<sum_product<double>>().cost_of_beliefs(homes);
}

PGM_DECL variable_elimination& junction_tree_engine::elimination() {
  if (!elimination_)
    elimination_ = std::make_unique<variable_elimination>(*network_, variable_elimination_options{options_.heuristic});
  if (elimination_version_ != version_) {
    elimination_->set_evidence(evidence_);
    elimination_version_ = version_;
  }
  return *elimination_;
}

}  // namespace pgm
