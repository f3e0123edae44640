#pragma once
// The definitions of pgm/causal/counterfactual.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string>

#include "pgm/causal/counterfactual.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/inference/variable_elimination.hpp"

namespace pgm {

namespace detail {

/// P(V ≤ s | configuration) for s = 0 … states − 2, summed in one order so that equal sums
/// compare equal wherever they are formed.
inline void cumulative_column(std::span<const double> column, std::vector<double>& out) {
  out.clear();
  double total = 0;
  for (std::size_t s = 0; s + 1 < column.size(); ++s) out.push_back(total += column[s]);
}

/// `base` with `mark` appended until no name of `taken` has it; the result is then taken.
inline std::string fresh_name(std::string base, char mark, std::set<std::string, std::less<>>& taken) {
  while (taken.contains(base)) base += mark;
  taken.insert(base);
  return base;
}

}  // namespace detail

PGM_DECL structural_model monotone_structural_model(const bayesian_network& network) {
  std::vector<variable> variables = network.variables();
  std::vector<structural_equation> equations;
  equations.reserve(network.size());
  std::vector<double> cumulative;
  for (std::size_t i = 0; i < network.size(); ++i) {
    const auto& table = network.tables()[i];
    const auto states = table.child_cardinality();
    const auto configurations = table.configurations();
    // The noise's cut points: every cumulative probability strictly inside (0, 1).
    std::vector<double> cuts{0.0};
    for (std::size_t c = 0; c < configurations; ++c) {
      detail::cumulative_column(table.column(index_at<config_index>(c)), cumulative);
      for (const double p : cumulative) {
        if (p > 0 && p < 1) cuts.push_back(p);
      }
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    structural_equation e;
    for (const auto& parent : table.parents()) e.parents.push_back(network.id(parent.name()));
    for (std::size_t k = 0; k < cuts.size(); ++k)
      e.noise.push_back((k + 1 < cuts.size() ? cuts[k + 1] : 1.0) - cuts[k]);
    e.values.reserve(checked_table_cells(variables[i].name(), cuts.size(), configurations));
    for (std::size_t c = 0; c < configurations; ++c) {
      detail::cumulative_column(table.column(index_at<config_index>(c)), cumulative);
      // The noise [cuts[k], cuts[k+1]) gives the first state whose cumulative probability
      // exceeds its left end: exact, as the ends are those very sums.
      std::size_t s = 0;
      for (const double left : cuts) {
        while (s < cumulative.size() && !(left < cumulative[s])) ++s;
        e.values.push_back(std::min(s, states - 1));
      }
    }
    equations.push_back(std::move(e));
  }
  return {std::move(variables), std::move(equations)};
}

PGM_DECL twin_network make_twin_network(const structural_model& model, const intervention& set) {
  const auto n = model.size();
  std::vector<std::optional<std::size_t>> forced(n);  // the state do() sets
  for (const auto& [name, state] : set) {
    const auto id = model.id(name);
    forced[id.value()] = model.at(id).state(state).value();
  }
  // Reached: set, or a descendant of something set.
  std::vector<bool> reached(n, false);
  for (const auto v : model.graph().topological_order()) {
    const auto& parents = model.equation(v).parents;
    reached[v.value()] = forced[v.value()].has_value() ||
                         std::any_of(parents.begin(), parents.end(), [&](auto p) { return reached[p.value()]; });
  }
  std::set<std::string, std::less<>> taken;
  for (const auto& v : model.variables()) taken.insert(v.name());
  const auto implied = model.network();
  std::vector<std::optional<variable>> copies(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (reached[i])
      copies[i].emplace(detail::fresh_name(model.variables()[i].name() + "*", '*', taken),
                        model.variables()[i].states());
  }
  const auto in_world = [&](variable_id v) -> const variable& {
    return reached[v.value()] ? *copies[v.value()] : model.at(v);
  };
  std::vector<cpt<double>> tables;
  for (std::size_t i = 0; i < n; ++i) {
    const auto id = index_at<variable_id>(i);
    const auto& v = model.at(id);
    if (!reached[i] || forced[i]) {
      tables.push_back(implied.table(id));  // the noise is needed in one world only
      if (forced[i]) {
        std::vector<double> point(v.cardinality(), 0.0);
        point[*forced[i]] = 1;
        tables.emplace_back(*copies[i], std::vector<variable>{}, std::move(point));
      }
      continue;
    }
    // Both worlds share the noise: V = f(parents, U) and V* = f(parents*, U).
    const auto& e = model.equation(id);
    const variable noise(detail::fresh_name("U_" + v.name(), '_', taken), [&] {
      std::vector<std::string> labels;
      for (std::size_t k = 0; k < e.noise.size(); ++k) labels.push_back(std::to_string(k));
      return labels;
    }());
    tables.emplace_back(noise, std::vector<variable>{}, e.noise);
    const auto deterministic = [&](const variable& child, std::vector<variable> parents) {
      const auto configurations = parent_configurations(model, e.parents);
      const auto states = v.cardinality();
      std::vector<double> values(checked_table_cells(child.name(), states, configurations * e.noise.size()), 0.0);
      for (std::size_t c = 0; c < configurations; ++c) {
        for (std::size_t k = 0; k < e.noise.size(); ++k) {
          values[(c * e.noise.size() + k) * states + model.value(id, c, k)] = 1;
        }
      }
      parents.push_back(noise);  // the noise fastest, as the function numbers it
      tables.emplace_back(child, std::move(parents), std::move(values));
    };
    std::vector<variable> factual_parents;
    std::vector<variable> intervened_parents;
    for (const auto p : e.parents) {
      factual_parents.push_back(model.at(p));
      intervened_parents.push_back(in_world(p));
    }
    deterministic(v, std::move(factual_parents));
    deterministic(*copies[i], std::move(intervened_parents));
  }
  twin_network twin{bayesian_network::from_tables(std::move(tables)), {}};
  for (std::size_t i = 0; i < n; ++i) {
    twin.intervened.push_back(twin.network.id(in_world(index_at<variable_id>(i)).name()));
  }
  return twin;
}

PGM_DECL posterior counterfactual_query(const structural_model& model, std::span<const std::string> names,
                                        const evidence& observed, const intervention& set) {
  if (names.empty()) throw model_error("the query names no variable");
  const auto twin = make_twin_network(model, set);
  std::vector<variable> asked;
  std::vector<std::optional<std::size_t>> known;  // a state the answer cannot but take
  std::vector<std::string> free;                  // the twin's nodes left to infer
  for (const auto& name : names) {
    const auto id = model.id(name);
    const auto& v = model.at(id);
    if (std::any_of(asked.begin(), asked.end(), [&](const variable& a) { return a.name() == v.name(); })) {
      throw model_error("the query names '" + name + "' twice");
    }
    asked.push_back(v);
    const auto& node = twin.network.variables()[twin.intervened[id.value()].value()];
    if (const auto s = set.find(name); s != set.end()) {
      known.push_back(v.state(s->second).value());
    } else if (const auto o = observed.find(node.name()); o != observed.end()) {
      known.push_back(v.state(o->second).value());
    } else {
      known.push_back(std::nullopt);
      free.push_back(node.name());
    }
  }
  for (const auto& [name, state] : observed) (void)model.at(model.id(name)).state(state);
  // Infer what is free, then place the known states.
  posterior inner;
  if (free.empty()) {
    const auto resolved = resolve_evidence(twin.network, observed);
    const double p = joint_with_evidence(twin.network, {}, resolved.hard).values().front();
    if (!(p > 0)) detail::throw_impossible(twin.network, resolved);
    inner.evidence_probability = p;
    inner.log_evidence_probability = std::log(p);
  } else {
    inner = query(twin.network, free, observed);
  }
  std::vector<std::size_t> cards;
  std::vector<variable_id> ids;
  std::size_t cells = 1;
  for (const auto& v : asked) {
    cards.push_back(v.cardinality());
    ids.push_back(model.id(v.name()));
    cells *= v.cardinality();
  }
  std::vector<double> values(cells, 0.0);
  std::vector<std::size_t> codes(asked.size(), 0);
  for (std::size_t cell = 0; cell < cells; ++cell) {
    bool possible = true;
    std::size_t at = 0;
    for (std::size_t k = 0; k < asked.size(); ++k) {
      if (known[k]) {
        possible = possible && codes[k] == *known[k];
      } else {
        at = at * cards[k] + codes[k];
      }
    }
    if (possible) values[cell] = free.empty() ? 1.0 : inner.table.values()[at];
    for (std::size_t k = codes.size(); k-- > 0;) {
      if (++codes[k] < cards[k]) break;
      codes[k] = 0;
    }
  }
  posterior answer;
  answer.variables = std::move(asked);
  answer.table = factor(std::move(ids), std::move(cards), std::move(values));
  answer.evidence_probability = inner.evidence_probability;
  answer.log_evidence_probability = inner.log_evidence_probability;
  answer.engine = "twin";
  return answer;
}

}  // namespace pgm
