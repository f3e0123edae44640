#pragma once
// The definitions of pgm/learn/hill_climbing.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/hill_climbing.hpp"

namespace pgm::detail {

PGM_DECL std::uint64_t splitmix64(std::uint64_t x) noexcept {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

PGM_DECL search_state::search_state(family_score_cache& cache, const edge_constraints& constraints,
                                    const search_options& options)
    : cache_(cache),
      constraints_(constraints),
      options_(options),
      n_(cache.size()),
      words_((n_ + 63) / 64),
      edge_(n_ * n_, 0),
      parents_(n_),
      reach_(n_ * words_, 0),
      delta_(n_ * n_, nan()),
      node_score_(n_, 0.0),
      zobrist_(n_ * n_),
      bonus_(n_ * n_, 0.0) {
  for (std::size_t k = 0; k < zobrist_.size(); ++k) zobrist_[k] = splitmix64(k * 0x2545f4914f6cdd1dULL + 24);
}

PGM_DECL double search_state::total() const {
  double sum = 0.0;
  for (auto s : node_score_) sum += s;
  return sum + prior_bonus();
}

PGM_DECL double search_state::prior_bonus() const {
  double sum = 0.0;
  if (!has_bonus_) return sum;
  for (std::size_t k = 0; k < edge_.size(); ++k) {
    if (edge_[k]) sum += bonus_[k];
  }
  return sum;
}

PGM_DECL void search_state::load(const std::vector<std::vector<std::size_t>>& parents) {
  std::fill(edge_.begin(), edge_.end(), 0);
  hash_ = 0;
  for (std::size_t j = 0; j < n_; ++j) {
    parents_[j] = parents[j];
    std::sort(parents_[j].begin(), parents_[j].end());
    for (auto i : parents_[j]) {
      edge_[i * n_ + j] = 1;
      hash_ ^= zobrist_[i * n_ + j];
    }
  }
  rebuild_reach();
  std::vector<std::size_t> all(n_);
  for (std::size_t j = 0; j < n_; ++j) all[j] = j;
  refresh(all);
}

PGM_DECL bool search_state::may_add(std::size_t i, std::size_t j) const {
  if (!constraints_.allowed(i, j)) return false;
  if (!options_.candidates.empty() && !options_.candidates[i * n_ + j]) return false;
  return parents_[j].size() < options_.max_parents;
}

PGM_DECL bool search_state::legal(move_kind kind, std::size_t i, std::size_t j) const {
  switch (kind) {
    case move_kind::add:
      return !has_edge(i, j) && !has_edge(j, i) && may_add(i, j) && !reaches(j, i);
    case move_kind::remove:
      return has_edge(i, j) && !constraints_.required(i, j);
    case move_kind::reverse:
      return has_edge(i, j) && !constraints_.required(i, j) && may_add(j, i) && !other_path(i, j);
  }
  return false;
}

PGM_DECL double search_state::gain(move_kind kind, std::size_t i, std::size_t j) const {
  if (kind != move_kind::reverse) return delta(i, j);
  double value = delta(i, j) + delta(j, i);
  if (std::abs(value) < search_tolerance) value = 0.0;
  return value;
}

PGM_DECL bool search_state::equal_after(move_kind kind, std::size_t i, std::size_t j,
                                        const std::vector<unsigned char>& graph) const {
  for (std::size_t k = 0; k < edge_.size(); ++k) {
    unsigned char e = edge_[k];
    if (k == i * n_ + j) e ^= 1;
    if (kind == move_kind::reverse && k == j * n_ + i) e ^= 1;
    if (e != graph[k]) return false;
  }
  return true;
}

PGM_DECL void search_state::apply(move_kind kind, std::size_t i, std::size_t j) {
  switch (kind) {
    case move_kind::add:
      set_edge(i, j, true);
      // i and every ancestor of i now reach j and j's descendants.
      for (std::size_t x = 0; x < n_; ++x) {
        if (x != i && !reaches(x, i)) continue;
        reach_[x * words_ + j / 64] |= std::uint64_t{1} << (j % 64);
        for (std::size_t w = 0; w < words_; ++w) reach_[x * words_ + w] |= reach_[j * words_ + w];
      }
      refresh(std::vector<std::size_t>{j});
      break;
    case move_kind::remove:
      set_edge(i, j, false);
      rebuild_reach();
      refresh(std::vector<std::size_t>{j});
      break;
    case move_kind::reverse:
      set_edge(i, j, false);
      set_edge(j, i, true);
      rebuild_reach();
      refresh(std::vector<std::size_t>{std::min(i, j), std::max(i, j)});
      break;
  }
}

PGM_DECL bool search_state::other_path(std::size_t i, std::size_t j) const {
  for (auto p : parents_[j]) {
    if (p != i && reaches(i, p)) return true;
  }
  return false;
}

PGM_DECL void search_state::set_edge(std::size_t i, std::size_t j, bool present) {
  edge_[i * n_ + j] = present ? 1 : 0;
  hash_ ^= zobrist_[i * n_ + j];
  auto& pa = parents_[j];
  if (present) {
    pa.insert(std::lower_bound(pa.begin(), pa.end(), i), i);
  } else {
    pa.erase(std::find(pa.begin(), pa.end(), i));
  }
}

PGM_DECL void search_state::rebuild_reach() {
  std::fill(reach_.begin(), reach_.end(), 0);
  std::vector<std::size_t> indegree(n_), order;
  order.reserve(n_);
  for (std::size_t j = 0; j < n_; ++j) {
    indegree[j] = parents_[j].size();
    if (indegree[j] == 0) order.push_back(j);
  }
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto v = order[k];
    for (std::size_t c = 0; c < n_; ++c) {
      if (has_edge(v, c) && --indegree[c] == 0) order.push_back(c);
    }
  }
  PGM_ASSERT(order.size() == n_, "the search's graph has a cycle");
  for (std::size_t k = order.size(); k-- > 0;) {
    const auto v = order[k];
    for (std::size_t c = 0; c < n_; ++c) {
      if (!has_edge(v, c)) continue;
      reach_[v * words_ + c / 64] |= std::uint64_t{1} << (c % 64);
      for (std::size_t w = 0; w < words_; ++w) reach_[v * words_ + w] |= reach_[c * words_ + w];
    }
  }
}

PGM_DECL void search_state::refresh(const std::vector<std::size_t>& targets) {
  std::vector<family_key> keys;
  std::vector<std::size_t> slots;  // delta slot, or n*n + j for node j's own family
  for (auto j : targets) {
    keys.push_back({j, parents_[j]});
    slots.push_back(n_ * n_ + j);
    for (std::size_t i = 0; i < n_; ++i) {
      delta_[i * n_ + j] = nan();
      if (i == j) continue;
      const bool present = has_edge(i, j);
      if (!present && !may_add(i, j)) continue;
      family_key key{j, parents_[j]};
      if (present) {
        key.parents.erase(std::find(key.parents.begin(), key.parents.end(), i));
      } else {
        key.parents.insert(std::lower_bound(key.parents.begin(), key.parents.end(), i), i);
      }
      keys.push_back(std::move(key));
      slots.push_back(i * n_ + j);
    }
  }
  const auto values = cache_.score_all(keys);
  for (std::size_t k = 0; k < keys.size(); ++k) {
    if (slots[k] >= n_ * n_) node_score_[slots[k] - n_ * n_] = values[k];
  }
  for (std::size_t k = 0; k < keys.size(); ++k) {
    if (slots[k] < n_ * n_) {
      const auto slot = slots[k];
      delta_[slot] = values[k] - node_score_[slot % n_] + (edge_[slot] ? -bonus_[slot] : bonus_[slot]);
    }
  }
}

PGM_DECL void tabu_list::push(const search_state& state) {
  if (length == 0) return;
  if (graphs.size() < length) {
    graphs.emplace_back(state.hash(), state.edges());
  } else {
    graphs[next] = {state.hash(), state.edges()};
  }
  next = (next + 1) % length;
}

PGM_DECL bool tabu_list::holds(const search_state& state, move_kind kind, std::size_t i, std::size_t j) const {
  const auto h = state.hash_after(kind, i, j);
  for (const auto& [hash, graph] : graphs) {
    if (hash == h && state.equal_after(kind, i, j, graph)) return true;
  }
  return false;
}

PGM_DECL std::optional<search_move> best_move(const search_state& state, double threshold, const tabu_list* tabu) {
  std::optional<search_move> best;
  double bar = threshold;
  const std::size_t n = state.size();
  for (auto kind : {move_kind::add, move_kind::remove, move_kind::reverse}) {
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) {
        if (i == j) continue;
        // Cheap checks first: the gain, then legality and the tabu list.
        if (kind == move_kind::add ? state.has_edge(i, j) || state.has_edge(j, i) : !state.has_edge(i, j)) continue;
        const double g = state.gain(kind, i, j);
        if (std::isnan(g) || !(g - bar > search_tolerance)) continue;
        if (!state.legal(kind, i, j)) continue;
        if (tabu && tabu->holds(state, kind, i, j)) continue;
        best = search_move{kind, i, j, g};
        bar = g;
      }
    }
  }
  return best;
}

PGM_DECL std::vector<search_move> legal_moves(const search_state& state) {
  std::vector<search_move> moves;
  const std::size_t n = state.size();
  for (auto kind : {move_kind::add, move_kind::remove, move_kind::reverse}) {
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) {
        if (i != j && state.legal(kind, i, j)) moves.push_back({kind, i, j, 0.0});
      }
    }
  }
  return moves;
}

PGM_DECL std::size_t climb(search_state& state, const search_options& options) {
  std::size_t moves = 0;
  if (options.tabu == 0) {
    while (moves < options.max_iterations) {
      const auto move = best_move(state, 0.0, nullptr);
      if (!move) break;
      state.apply(move->kind, move->from, move->to);
      ++moves;
    }
    return moves;
  }
  tabu_list tabu{options.tabu, {}, 0};
  tabu.push(state);
  auto best = state.all_parents();
  double best_score = state.total();
  std::size_t loss = 0;
  bool at_best = true;
  while (moves < options.max_iterations) {
    auto move = best_move(state, 0.0, &tabu);
    if (!move) {
      if (loss >= options.max_tabu) break;
      ++loss;
      move = best_move(state, -std::numeric_limits<double>::infinity(), &tabu);
      if (!move) break;
    }
    state.apply(move->kind, move->from, move->to);
    ++moves;
    tabu.push(state);
    at_best = false;
    if (state.total() - best_score > search_tolerance) {
      best = state.all_parents();
      best_score = state.total();
      loss = 0;
      at_best = true;
    }
  }
  if (!at_best) state.load(best);
  return moves;
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL search_result hill_climb(std::span<const discrete_column* const> columns, const search_options& options) {
  const std::size_t n = columns.size();
  std::vector<std::string> names;
  for (const auto* c : columns) names.push_back(c->name());
  const edge_constraints constraints(options.knowledge, names);
  if (!options.candidates.empty() && options.candidates.size() != n * n) {
    throw model_error("the candidate parents are for another set of variables");
  }
  family_score_cache cache(columns, options.score, options.threads);

  // The start network: the given edges and the required ones.
  std::map<std::string, std::size_t, std::less<>> index;
  for (std::size_t i = 0; i < n; ++i) index.emplace(names[i], i);
  std::vector<std::vector<std::size_t>> start(n);
  auto start_edge = [&](std::size_t i, std::size_t j) {
    if (std::find(start[j].begin(), start[j].end(), i) == start[j].end()) start[j].push_back(i);
  };
  for (const auto& e : options.start) {
    const auto from = index.find(e.from);
    const auto to = index.find(e.to);
    for (const auto& it : {from, to}) {
      if (it == index.end()) {
        throw model_error("the start network's edge " + e.from + "->" + e.to + " names a variable not in the data (" +
                          text::list_for_message(names) + ")");
      }
    }
    if (!constraints.allowed(from->second, to->second)) {
      throw model_error("the start network has the edge " + e.from + "->" + e.to +
                        ", which the background knowledge forbids");
    }
    start_edge(from->second, to->second);
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (!constraints.required(i, j)) continue;
      if (std::find(start[i].begin(), start[i].end(), j) != start[i].end()) {
        throw model_error("edge " + names[i] + "->" + names[j] + " is required, but the start network has " + names[j] +
                          "->" + names[i]);
      }
      start_edge(i, j);
    }
  }
  {
    std::vector<named_edge> edges;
    for (std::size_t j = 0; j < n; ++j) {
      if (start[j].size() > options.max_parents) {
        throw model_error("'" + names[j] + "' has " + std::to_string(start[j].size()) +
                          " parents in the start network, more than the maximum " +
                          std::to_string(options.max_parents));
      }
      for (auto i : start[j]) edges.push_back({names[i], names[j]});
    }
    dag check(names);
    for (const auto& e : edges) check.add_edge(e.from, e.to);  // throws not_a_dag on a cycle
  }

  detail::search_state state(cache, constraints, options);
  if (!options.favoured.empty()) {
    if (!(options.favour_weight >= 0.0) || !(options.favour_weight <= max_favour_weight)) {
      throw model_error("the structure prior's weight must be a number from 0 to " +
                        text::format_short(max_favour_weight) + ", got " + text::format_short(options.favour_weight));
    }
    std::vector<double> bonus(n * n, 0.0);
    for (const auto& e : options.favoured) {
      const auto from = index.find(e.from);
      const auto to = index.find(e.to);
      if (from == index.end() || to == index.end() || from->second == to->second) {
        throw model_error("the favoured edge " + e.from + "->" + e.to + " is not between two variables of the data");
      }
      bonus[from->second * n + to->second] = options.favour_weight;
    }
    state.set_bonus(std::move(bonus));
  }
  state.load(start);
  search_result result;
  result.moves = detail::climb(state, options);
  auto best = state.all_parents();
  double best_score = state.total();
  for (std::size_t r = 0; r < options.restarts; ++r) {
    // Perturb the best network so far with random legal moves, then climb again.
    std::uint64_t stream = detail::splitmix64(options.seed ^ detail::splitmix64(r + 1));
    for (std::size_t p = 0; p < options.perturb; ++p) {
      const auto moves = detail::legal_moves(state);
      if (moves.empty()) break;
      stream = detail::splitmix64(stream);
      const auto& move = moves[stream % moves.size()];
      state.apply(move.kind, move.from, move.to);
    }
    result.moves += detail::climb(state, options);
    ++result.restarts;
    if (state.total() - best_score > detail::search_tolerance) {
      best = state.all_parents();
      best_score = state.total();
    } else {
      state.load(best);
    }
  }

  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (state.has_edge(i, j)) result.edges.push_back({names[i], names[j]});
    }
  }
  for (std::size_t j = 0; j < n; ++j) result.node_scores.push_back(state.node_score(j));
  result.score = state.total();
  result.prior_bonus = state.prior_bonus();
  result.families_scored = cache.computed();
  result.cache_hits = cache.hits();
  return result;
}

PGM_DECL search_result hill_climb(const dataset& data, std::span<const std::string> columns,
                                  const search_options& options) {
  std::vector<const discrete_column*> picked;
  for (const auto& name : columns) picked.push_back(&data.discrete(name));
  return hill_climb(picked, options);
}

}  // namespace pgm
