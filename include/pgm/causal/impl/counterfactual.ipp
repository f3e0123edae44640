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

/// The monotone equation of one table of `network`.
inline structural_equation monotone_equation(const bayesian_network& network, variable_id id) {
  const auto& table = network.table(id);
  const auto states = table.child_cardinality();
  const auto configurations = table.configurations();
  std::vector<double> cumulative;
  // The noise's cut points: every cumulative probability strictly inside (0, 1).
  std::vector<double> cuts{0.0};
  for (std::size_t c = 0; c < configurations; ++c) {
    cumulative_column(table.column(index_at<config_index>(c)), cumulative);
    for (const double p : cumulative) {
      if (p > 0 && p < 1) cuts.push_back(p);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  structural_equation e;
  for (const auto& parent : table.parents()) e.parents.push_back(network.id(parent.name()));
  for (std::size_t k = 0; k < cuts.size(); ++k) e.noise.push_back((k + 1 < cuts.size() ? cuts[k + 1] : 1.0) - cuts[k]);
  e.values.reserve(checked_table_cells(table.child().name(), cuts.size(), configurations));
  for (std::size_t c = 0; c < configurations; ++c) {
    cumulative_column(table.column(index_at<config_index>(c)), cumulative);
    // The noise [cuts[k], cuts[k+1]) gives the first state whose cumulative probability
    // exceeds its left end: exact, as the ends are those very sums.
    std::size_t s = 0;
    for (const double left : cuts) {
      while (s < cumulative.size() && !(left < cumulative[s])) ++s;
      e.values.push_back(std::min(s, states - 1));
    }
  }
  return e;
}

/// The twin network of the model whose implied network is `implied`; `equation_of(id)` gives the
/// equation of a variable the intervention reaches (others keep their tables). A function
/// whose parent is known in its world (observed in `observed`, or set) is taken at that state:
/// the parent's own node keeps its evidence, so the answer is the same and the table smaller.
template <class EquationOf>
twin_network build_twin(const bayesian_network& implied, const intervention& set, const evidence& observed,
                        EquationOf&& equation_of) {
  const auto n = implied.size();
  const auto& variables = implied.variables();
  std::vector<std::optional<std::size_t>> forced(n);  // the state do() sets
  for (const auto& [name, state] : set) {
    const auto id = implied.id(name);
    forced[id.value()] = variables[id.value()].state(state).value();
  }
  std::vector<std::optional<std::size_t>> seen(n);  // the state observed in the factual world
  for (const auto& [name, state] : observed) {
    const auto id = implied.id(name);
    seen[id.value()] = variables[id.value()].state(state).value();
  }
  // Reached: set, or a descendant of something set.
  std::vector<bool> reached(n, false);
  for (const auto v : implied.graph().topological_order()) {
    const auto parents = implied.graph().parents(v);
    reached[v.value()] = forced[v.value()].has_value() ||
                         std::any_of(parents.begin(), parents.end(), [&](auto p) { return reached[p.value()]; });
  }
  std::set<std::string, std::less<>> taken;
  for (const auto& v : variables) taken.insert(v.name());
  std::vector<std::optional<variable>> copies(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (reached[i]) copies[i].emplace(fresh_name(variables[i].name() + "*", '*', taken), variables[i].states());
  }
  const auto in_world = [&](variable_id v) -> const variable& {
    return reached[v.value()] ? *copies[v.value()] : variables[v.value()];
  };
  std::vector<cpt<double>> tables;
  for (std::size_t i = 0; i < n; ++i) {
    const auto id = index_at<variable_id>(i);
    const auto& v = variables[i];
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
    const structural_equation e = equation_of(id);
    std::vector<std::string> labels;
    for (std::size_t k = 0; k < e.noise.size(); ++k) labels.push_back(std::to_string(k));
    const variable noise(fresh_name("U_" + v.name(), '_', taken), std::move(labels));
    tables.emplace_back(noise, std::vector<variable>{}, e.noise);
    // `parents[k]` is the node of e.parents[k] in the child's world, `known[k]` its state if fixed.
    const auto deterministic = [&](const variable& child, const std::vector<const variable*>& parents,
                                   const std::vector<std::optional<std::size_t>>& known) {
      std::vector<variable> kept;
      std::vector<std::size_t> cards;
      std::size_t kept_configurations = 1;
      for (std::size_t k = 0; k < parents.size(); ++k) {
        cards.push_back(parents[k]->cardinality());
        if (!known[k]) {
          kept.push_back(*parents[k]);
          kept_configurations *= cards[k];
        }
      }
      const auto states = v.cardinality();
      const auto width = e.noise.size();
      std::vector<double> values(checked_table_cells(child.name(), states, kept_configurations * width), 0.0);
      std::vector<std::size_t> codes(parents.size(), 0);
      for (std::size_t k = 0; k < parents.size(); ++k) codes[k] = known[k].value_or(0);
      for (std::size_t c = 0; c < kept_configurations; ++c) {
        std::size_t full = 0;
        for (std::size_t k = 0; k < parents.size(); ++k) full = full * cards[k] + codes[k];
        for (std::size_t u = 0; u < width; ++u) values[(c * width + u) * states + e.values[full * width + u]] = 1;
        for (std::size_t k = parents.size(); k-- > 0;) {  // the next kept configuration, the last fastest
          if (known[k]) continue;
          if (++codes[k] < cards[k]) break;
          codes[k] = 0;
        }
      }
      kept.push_back(noise);  // the noise fastest, as the function numbers it
      tables.emplace_back(child, std::move(kept), std::move(values));
    };
    std::vector<const variable*> factual_parents;
    std::vector<const variable*> intervened_parents;
    std::vector<std::optional<std::size_t>> factual_known;
    std::vector<std::optional<std::size_t>> intervened_known;
    for (const auto p : e.parents) {
      factual_parents.push_back(&variables[p.value()]);
      factual_known.push_back(seen[p.value()]);
      intervened_parents.push_back(&in_world(p));
      intervened_known.push_back(reached[p.value()] ? forced[p.value()] : seen[p.value()]);
    }
    deterministic(v, factual_parents, factual_known);
    deterministic(*copies[i], intervened_parents, intervened_known);
  }
  twin_network twin{bayesian_network::from_tables(std::move(tables)), {}};
  for (std::size_t i = 0; i < n; ++i) {
    twin.intervened.push_back(twin.network.id(in_world(index_at<variable_id>(i)).name()));
  }
  return twin;
}

/// The counterfactual distribution of `names` on a twin network of the model implying `implied`.
inline posterior query_twin(const bayesian_network& implied, const twin_network& twin,
                            std::span<const std::string> names, const evidence& observed, const intervention& set) {
  if (names.empty()) throw model_error("the query names no variable");
  std::vector<variable> asked;
  std::vector<std::optional<std::size_t>> known;  // a state the answer cannot but take
  std::vector<std::string> free;                  // the twin's nodes left to infer
  for (const auto& name : names) {
    const auto id = implied.id(name);
    const auto& v = implied.variables()[id.value()];
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
  // Infer what is free, then place the known states.
  posterior inner;
  if (free.empty()) {
    const auto resolved = resolve_evidence(twin.network, observed);
    const double p = joint_with_evidence(twin.network, {}, resolved.hard).values().front();
    if (!(p > 0)) throw_impossible(twin.network, resolved);
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
    ids.push_back(implied.id(v.name()));
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

}  // namespace detail

PGM_DECL structural_model monotone_structural_model(const bayesian_network& network) {
  std::vector<structural_equation> equations;
  equations.reserve(network.size());
  for (std::size_t i = 0; i < network.size(); ++i) {
    equations.push_back(detail::monotone_equation(network, index_at<variable_id>(i)));
  }
  return {network.variables(), std::move(equations)};
}

PGM_DECL twin_network make_twin_network(const structural_model& model, const intervention& set) {
  return detail::build_twin(model.network(), set, {}, [&](variable_id id) { return model.equation(id); });
}

PGM_DECL twin_network make_monotone_twin_network(const bayesian_network& network, const intervention& set) {
  return detail::build_twin(network, set, {}, [&](variable_id id) { return detail::monotone_equation(network, id); });
}

PGM_DECL posterior counterfactual_query(const structural_model& model, std::span<const std::string> names,
                                        const evidence& observed, const intervention& set) {
  const auto implied = model.network();
  const auto twin = detail::build_twin(implied, set, observed, [&](variable_id id) { return model.equation(id); });
  return detail::query_twin(implied, twin, names, observed, set);
}

PGM_DECL posterior monotone_counterfactual_query(const bayesian_network& network, std::span<const std::string> names,
                                                 const evidence& observed, const intervention& set) {
  const auto twin = detail::build_twin(network, set, observed,
                                       [&](variable_id id) { return detail::monotone_equation(network, id); });
  return detail::query_twin(network, twin, names, observed, set);
}

}  // namespace pgm
