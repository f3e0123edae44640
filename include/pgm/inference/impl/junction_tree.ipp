#pragma once
// The definitions of pgm/inference/junction_tree.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/inference/junction_tree.hpp"

namespace pgm {

PGM_DECL junction_tree::junction_tree(std::vector<std::size_t> cardinalities,
                                      const std::vector<std::vector<variable_id>>& scopes,
                                      const junction_tree_options& options)
    : cardinalities_(std::move(cardinalities)) {
  const auto triangulated = searched_elimination(interaction_graph_of(cardinalities_.size(), scopes), cardinalities_,
                                                 options.heuristic, options.search);
  build_cliques(triangulated, cardinalities_);
  check_size(options.max_cells);
  assign_factors(scopes);
  root_and_number();
}

PGM_DECL std::size_t junction_tree::largest_clique_cells() const noexcept {
  std::size_t largest = 0;
  for (const auto& c : cliques_) largest = std::max(largest, c.cells);
  return largest;
}

PGM_DECL std::size_t junction_tree::treewidth() const noexcept {
  std::size_t width = 0;
  for (const auto& c : cliques_) width = std::max(width, c.variables.size());
  return width == 0 ? 0 : width - 1;
}

PGM_DECL std::size_t junction_tree::position(std::size_t c, variable_id node) const noexcept {
  const auto& vars = cliques_[c].variables;
  const auto it = std::lower_bound(vars.begin(), vars.end(), node);
  return it != vars.end() && *it == node ? static_cast<std::size_t>(it - vars.begin()) : vars.size();
}

PGM_DECL std::vector<std::size_t> junction_tree::strides_into(std::size_t c, std::span<const variable_id> scope) const {
  std::vector<std::size_t> result(cliques_[c].variables.size(), 0);
  std::size_t stride = 1;
  for (std::size_t k = scope.size(); k-- > 0;) {
    const auto p = position(c, scope[k]);
    if (p < result.size()) result[p] = stride;
    stride *= cardinalities_[scope[k].value()];
  }
  return result;
}

PGM_DECL void junction_tree::build_cliques(const elimination& triangulated, const std::vector<std::size_t>& cards) {
  const auto n = triangulated.order.size();
  std::vector<std::size_t> position_of(n);
  for (std::size_t k = 0; k < n; ++k) position_of[triangulated.order[k]] = k;
  // Parent of elimination clique k: the clique of its first-eliminated neighbour.
  constexpr auto none = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> parent(n, none);
  std::vector<std::vector<std::size_t>> children(n);
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t first = none;
    for (auto v : triangulated.cliques[k]) {
      if (v != triangulated.order[k] && (first == none || position_of[v] < first)) first = position_of[v];
    }
    parent[k] = first;
    if (first != none) children[first].push_back(k);
  }
  // A non-maximal clique is contained in one of its children (which eliminate earlier): it
  // takes that child's representative, contracting the edge between them.
  std::vector<std::size_t> representative(n);
  for (std::size_t k = 0; k < n; ++k) {
    representative[k] = k;
    const auto& mine = triangulated.cliques[k];
    for (auto c : children[k]) {
      const auto& theirs = triangulated.cliques[representative[c]];
      if (std::includes(theirs.begin(), theirs.end(), mine.begin(), mine.end())) {
        representative[k] = representative[c];
        break;
      }
    }
  }
  std::vector<std::size_t> index(n, none);
  for (std::size_t k = 0; k < n; ++k) {
    if (representative[k] != k) continue;
    index[k] = cliques_.size();
    clique c;
    for (auto v : triangulated.cliques[k]) {
      c.variables.push_back(index_at<variable_id>(v));
      c.cardinalities.push_back(cards[v]);
      c.cells = detail::saturating_multiply(c.cells, cards[v]);
    }
    cliques_.push_back(std::move(c));
  }
  std::vector<std::size_t> roots;
  for (std::size_t k = 0; k < n; ++k) {
    const auto from = index[representative[k]];
    if (parent[k] == none) {
      roots.push_back(from);  // one per connected part: its last-eliminated clique
      continue;
    }
    const auto to = index[representative[parent[k]]];
    if (from != to) add_edge(from, to);
  }
  // Disconnected parts: each further root hangs from the first by an empty separator.
  for (std::size_t r = 1; r < roots.size(); ++r) add_edge(roots[r], roots[0]);
  for (auto& c : cliques_) {
    for (std::size_t k = 0; k < c.edges.size(); ++k) {
      auto same = std::find_if(c.groups.begin(), c.groups.end(), [&](const std::vector<std::size_t>& g) {
        return edges_[c.edges[g.front()]].separator == edges_[c.edges[k]].separator;
      });
      if (same == c.groups.end()) {
        c.groups.push_back({k});
      } else {
        same->push_back(k);
      }
    }
  }
}

PGM_DECL void junction_tree::add_edge(std::size_t a, std::size_t b) {
  edge e{a, b, {}, 1};
  std::set_intersection(cliques_[a].variables.begin(), cliques_[a].variables.end(), cliques_[b].variables.begin(),
                        cliques_[b].variables.end(), std::back_inserter(e.separator));
  for (auto v : e.separator) e.cells *= cardinalities_[v.value()];
  const auto id = edges_.size();
  edges_.push_back(std::move(e));
  for (auto c : {a, b}) {
    cliques_[c].edges.push_back(id);
    cliques_[c].strides.push_back(strides_into(c, edges_[id].separator));
  }
}

PGM_DECL void junction_tree::check_size(std::size_t max_cells) {
  total_cells_ = 0;
  for (const auto& c : cliques_) total_cells_ = detail::saturating_add(total_cells_, c.cells);
  if (total_cells_ > max_cells) {
    throw table_too_large("the junction tree of this network needs " + std::to_string(total_cells_) +
                          " cells (largest clique " + std::to_string(largest_clique_cells()) +
                          "), more than the limit of " + std::to_string(max_cells) +
                          "; use an approximate engine (lw, gibbs) or auto");
  }
}

PGM_DECL void junction_tree::assign_factors(const std::vector<std::vector<variable_id>>& scopes) {
  // A model of no variables still has its constant factors: they go to one empty clique.
  if (cliques_.empty()) cliques_.emplace_back();
  const auto n = cardinalities_.size();
  std::vector<std::vector<std::size_t>> holding(n);
  for (std::size_t c = 0; c < cliques_.size(); ++c) {
    for (auto v : cliques_[c].variables) holding[v.value()].push_back(c);
  }
  auto smaller = [&](std::size_t a, std::size_t b) { return cliques_[a].cells < cliques_[b].cells; };
  home_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    PGM_ASSERT(!holding[i].empty(), "every variable is in a clique");
    home_[i] = *std::min_element(holding[i].begin(), holding[i].end(), smaller);
  }
  factor_clique_.resize(scopes.size());
  for (std::size_t f = 0; f < scopes.size(); ++f) {
    const auto& scope = scopes[f];
    if (scope.empty()) {
      factor_clique_[f] = 0;
      continue;
    }
    // The smallest clique holding the scope, among those holding its first variable.
    std::size_t best = cliques_.size();
    for (auto c : holding[scope.front().value()]) {
      const bool holds = std::all_of(scope.begin(), scope.end(),
                                     [&](variable_id v) { return position(c, v) < cliques_[c].variables.size(); });
      if (holds && (best == cliques_.size() || smaller(c, best))) best = c;
    }
    PGM_ASSERT(best < cliques_.size(), "a triangulated graph's factor scope lies in one clique");
    factor_clique_[f] = best;
  }
}

PGM_DECL void junction_tree::root_and_number() {
  const auto m = cliques_.size();
  first_.assign(m, 0);
  last_.assign(m, 0);
  parent_edge_.assign(m, edges_.size());
  preorder_.clear();
  if (m == 0) return;
  // Orient every edge away from clique 0 and number subtrees by a depth-first walk.
  std::vector<std::pair<std::size_t, std::size_t>> stack{{0, 0}};  // (clique, next incident edge)
  std::vector<char> seen(m, 0);
  seen[0] = 1;
  std::size_t counter = 0;
  first_[0] = counter++;
  preorder_.push_back(0);
  while (!stack.empty()) {
    auto& [c, next] = stack.back();
    if (next == cliques_[c].edges.size()) {
      last_[c] = counter;
      stack.pop_back();
      continue;
    }
    const auto e = cliques_[c].edges[next++];
    const auto other = across(e, c);
    if (seen[other]) continue;
    seen[other] = 1;
    if (edges_[e].child != other) std::swap(edges_[e].child, edges_[e].parent);
    parent_edge_[other] = e;
    first_[other] = counter++;
    preorder_.push_back(other);
    stack.emplace_back(other, 0);
  }
}

}  // namespace pgm
