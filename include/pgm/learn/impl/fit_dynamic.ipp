#pragma once
// The definitions of pgm/learn/fit_dynamic.hpp: inline in a header-only build, compiled once into
// libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <optional>
#include <set>
#include <utility>

#include "pgm/core/text.hpp"
#include "pgm/learn/fit_dynamic.hpp"

namespace pgm {

namespace detail {

PGM_DECL std::string template_list(const network_structure& templates) {
  std::vector<std::string> names;
  for (const auto& v : templates.variables()) names.push_back(v.name());
  return text::list_for_message(names);
}

[[noreturn]] inline void fail_unknown_template(const std::string& edge, const std::string& name,
                                               const network_structure& templates) {
  throw model_error(edge + " names '" + name + "', which is not a template variable (" + template_list(templates) +
                    ")");
}

/// Throws data_error for a template variable whose column is absent, continuous or of other
/// states: the slices' columns take the template's variable.
inline void check_template_columns(const dataset& data, const std::vector<variable>& templates) {
  for (const auto& v : templates) {
    const auto& column = data.discrete(v.name());
    if (column.var().states() != v.states()) {
      throw data_error(data.source() + ": column '" + v.name() + "' has the states {" +
                       text::join(column.var().states()) + "} but the model expects {" + text::join(v.states()) + "}");
    }
  }
}

/// Each episode's row at t = 0, the template variables' columns only.
inline dataset first_slice(const dataset& data, const std::vector<variable>& templates, const episode_index& episodes) {
  std::vector<std::size_t> first;
  for (std::size_t k = 0; k < episodes.episodes(); ++k) first.push_back(episodes.row(episodes.starts[k]));
  dataset initial(data.source());
  for (const auto& v : templates) initial.add(data.discrete(v.name()).select(first).with_variable(v));
  return initial;
}

}  // namespace detail

PGM_DECL dynamic_structure dynamic_structure_of(std::vector<variable> templates, const std::vector<named_edge>& edges) {
  for (const auto& v : templates) {
    if (v.name().find('@') != std::string::npos) {
      throw model_error("the template variable '" + v.name() + "' holds '@', which names a slice ('x@-1')");
    }
  }
  dynamic_structure structure{network_structure(templates), dynamic_network::two_slices(templates)};
  for (const auto& [from, to] : edges) {
    const auto edge = "the edge '" + from + "->" + to + "'";
    if (to.find('@') != std::string::npos) {
      throw model_error(edge + " ends in another slice: an edge's child lies in this slice ('" + template_of(to) +
                        "'), its parent in this slice or the one before ('" + template_of(from) + "@-1')");
    }
    if (!structure.initial.contains(to)) detail::fail_unknown_template(edge, to, structure.initial);
    const auto [name, slice] = detail::slice_of_parent(from, to);
    if (!structure.initial.contains(name)) detail::fail_unknown_template(edge, name, structure.initial);
    if (slice == 0) {
      structure.initial.add_edge(name, to);
      structure.transition.add_edge(name, to);
    } else {
      structure.transition.add_edge(slice_name(name, -1), to);
    }
  }
  return structure;
}

PGM_DECL dynamic_structure dynamic_structure_from_data(const dataset& data, const std::vector<named_edge>& edges,
                                                       const std::vector<variable>& latent) {
  std::set<std::string, std::less<>> hidden;
  for (const auto& v : latent) {
    if (data.contains(v.name())) {
      throw data_error(data.source() + " has a column '" + v.name() +
                       "', which is given as latent: a latent variable is one the data do not hold");
    }
    hidden.insert(v.name());
  }
  std::set<std::string, std::less<>> named;
  for (const auto& edge : edges) {
    for (const auto* name : {&edge.from, &edge.to}) {
      const auto plain = template_of(*name);
      if (named.insert(plain).second && !hidden.contains(plain)) {
        static_cast<void>(data.discrete(plain));  // exists, discrete
      }
    }
  }
  std::vector<variable> templates;
  for (const auto& name : data.names()) {
    if (named.contains(name)) templates.push_back(data.discrete(name).var());
  }
  for (const auto& v : latent) {
    if (!named.contains(v.name())) throw model_error("the latent variable '" + v.name() + "' is in no edge");
    templates.push_back(v);
  }
  return dynamic_structure_of(std::move(templates), edges);
}

PGM_DECL dynamic_structure structure_of(const dynamic_network& model) {
  return {model.initial().structure(), model.transition_structure()};
}

PGM_DECL slice_data slices_of(const dataset& data, const std::vector<variable>& templates,
                              const episode_index& episodes) {
  detail::check_template_columns(data, templates);
  std::vector<std::size_t> now;
  std::vector<std::size_t> before;
  for (std::size_t k = 0; k < episodes.episodes(); ++k) {
    for (std::size_t i = episodes.starts[k] + 1; i < episodes.starts[k + 1]; ++i) {
      now.push_back(episodes.row(i));
      before.push_back(episodes.row(i - 1));
    }
  }
  slice_data slices{detail::first_slice(data, templates, episodes), dataset(data.source())};
  for (const auto& v : templates) {
    const auto& column = data.discrete(v.name());
    slices.transitions.add(column.select(before).with_variable(detail::renamed(v, slice_name(v.name(), -1))));
    slices.transitions.add(column.select(now).with_variable(v));
  }
  return slices;
}

namespace detail {

/// Data in episode and step order as every pair of neighbouring rows: X@-1 the rows 0 … n−2, X
/// the rows 1 … n−1. The pairs that cross from one episode into the next are among them; one
/// copy of each column, where the exact pairs (slices_of) look every row up.
inline dataset neighbour_pairs(const dataset& data, const std::vector<variable>& templates) {
  dataset pairs(data.source());
  const std::vector<std::pair<std::size_t, std::size_t>> before{{0, data.rows() - 1}};
  const std::vector<std::pair<std::size_t, std::size_t>> now{{1, data.rows()}};
  for (const auto& v : templates) {
    const auto& column = data.discrete(v.name());
    pairs.add(column.select_runs(before).with_variable(renamed(v, slice_name(v.name(), -1))));
    pairs.add(column.select_runs(now).with_variable(v));
  }
  return pairs;
}

/// Takes out of the dense `counts`, counted over neighbour_pairs, the pairs that cross from one
/// episode into the next: pair s − 1 for each episode's first row s > 0, where it was counted
/// (no value of the family missing).
inline void remove_crossings(count_table& counts, const dataset& pairs, const episode_index& episodes) {
  const auto& child = pairs.discrete(counts.child().name());
  std::vector<const discrete_column*> parents;
  for (const auto& p : counts.parents()) parents.push_back(&pairs.discrete(p.name()));
  auto cells = counts.counts();
  const auto j = counts.child_cardinality();
  std::vector<std::size_t> codes(parents.size());
  for (std::size_t k = 1; k < episodes.episodes(); ++k) {
    const auto pair = episodes.starts[k] - 1;
    bool counted = child.missing() == 0 || !child.is_missing(pair);
    for (std::size_t i = 0; i < parents.size() && counted; ++i) {
      counted = parents[i]->missing() == 0 || !parents[i]->is_missing(pair);
      codes[i] = parents[i]->code(pair);
    }
    if (counted) --cells[counts.parent_radix().encode(codes) * j + child.code(pair)];
  }
}

}  // namespace detail

PGM_DECL dynamic_counts count_dynamic(const dynamic_structure& structure, const dataset& data,
                                      const episode_columns& columns, const count_options& counting) {
  if (data.rows() == 0) throw data_error(data.source() + ": there are no data rows to fit a dynamic network from");
  const auto episodes = index_episodes(data, columns);
  const auto& templates = structure.variables();
  detail::check_template_columns(data, templates);
  dynamic_counts counts;
  counts.episodes = episodes.episodes();
  counts.steps = data.rows();
  // In-order data are counted over every pair of neighbouring rows, less the pairs that cross
  // episodes; a sparse table (which keeps the configurations seen) over the exact pairs instead.
  std::optional<dataset> pairs;
  if (episodes.in_order()) pairs = detail::neighbour_pairs(data, templates);
  std::optional<slice_data> slices;
  const auto exact = [&]() -> const slice_data& {
    if (!slices) slices = slices_of(data, templates, episodes);
    return *slices;
  };
  const auto initial = detail::first_slice(data, templates, episodes);
  const auto n = templates.size();
  for (std::size_t i = 0; i < n; ++i) {
    const variable_id node = index_at<variable_id>(i);
    const variable_id now = index_at<variable_id>(n + i);
    counts.initial.push_back(count_node(structure.initial, node, initial, counting));
    if (pairs) {
      auto table = count_node(structure.transition, now, *pairs, counting);
      if (!table.is_sparse()) {
        detail::remove_crossings(table, *pairs, episodes);
        counts.transition.push_back(std::move(table));
        continue;
      }
    }
    counts.transition.push_back(count_node(structure.transition, now, exact().transitions, counting));
  }
  return counts;
}

PGM_DECL dynamic_network fit_dynamic(const dynamic_structure& structure, const dynamic_counts& counts,
                                     const dynamic_fit_options& options) {
  const auto& templates = structure.variables();
  if (counts.initial.size() != templates.size() || counts.transition.size() != templates.size()) {
    throw model_error("fitting a dynamic network of " + std::to_string(templates.size()) +
                      " template variables needs as many count tables for each slice");
  }
  for (const auto& [name, prior] : options.fit.node_priors) {
    if (!structure.initial.contains(name)) {
      throw model_error("a prior is given for '" + name + "', which is not a template variable of the network");
    }
  }
  fit_options first = options.fit;
  first.node_priors = options.initial_priors;
  auto initial = fit(structure.initial, std::span<const count_table>(counts.initial), first);
  std::vector<cpt<double>> tables;
  for (std::size_t i = 0; i < templates.size(); ++i) {
    const auto& table = counts.transition[i];
    const variable_id now = index_at<variable_id>(templates.size() + i);
    if (table.child() != structure.transition.at(now) ||
        table.parents() != structure.transition.parent_variables(now)) {
      throw model_error("the count table given for the transition of '" + templates[i].name() +
                        "' is not of its family in the network");
    }
    const auto own = options.fit.node_priors.find(templates[i].name());
    tables.push_back(estimate(table, own != options.fit.node_priors.end() ? own->second : options.fit.prior,
                              options.fit.estimation));
  }
  return dynamic_network(std::move(initial), std::move(tables));
}

PGM_DECL dynamic_network fit_dynamic(const dynamic_structure& structure, const dataset& data,
                                     const dynamic_fit_options& options) {
  return fit_dynamic(structure, count_dynamic(structure, data, options.columns, options.fit.counting), options);
}

}  // namespace pgm
