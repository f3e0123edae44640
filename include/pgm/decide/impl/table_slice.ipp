#pragma once
// The definitions of pgm/decide/table_slice.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/decide/table_slice.hpp"

namespace pgm::detail {

PGM_DECL std::vector<double> cell_rows(const expected_count_table& counts, const variable& x, const variable& y,
                                       const std::vector<std::pair<std::string, state_index>>& fixed) {
  const auto& parents = counts.parents();
  const auto position = [&](const std::string& name) {
    return static_cast<std::size_t>(
        std::find_if(parents.begin(), parents.end(), [&](const variable& p) { return p.name() == name; }) -
        parents.begin());
  };
  const auto px = position(x.name()), py = position(y.name());
  std::vector<std::optional<std::size_t>> wanted(parents.size());
  for (const auto& [name, state] : fixed) {
    if (const auto p = position(name); p < parents.size()) wanted[p] = state.value();
  }
  std::vector<double> rows(x.cardinality() * y.cardinality(), 0.0);
  std::vector<std::size_t> digits(parents.size());
  for (std::size_t u = 0; u < counts.configurations(); ++u) {
    counts.parent_radix().decode(u, digits);
    bool matches = true;
    for (std::size_t p = 0; p < parents.size() && matches; ++p) matches = !wanted[p] || *wanted[p] == digits[p];
    if (matches) rows[digits[py] * x.cardinality() + digits[px]] += counts.total(config_index(u));
  }
  return rows;
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL table_slice slice_table(const bayesian_network& network, const table_slice_request& request,
                                 const fit_statistics* statistics) {
  const auto target = node_of(network, request.node);
  const auto& node = network.at(request.node);
  const auto& parent_ids = network.graph().parents(target);
  std::vector<std::string> parent_names;
  for (auto id : parent_ids) parent_names.push_back(network.structure().at(id).name());
  const auto position_of = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(parent_names.begin(), parent_names.end(), name) - parent_names.begin());
  };
  const auto is_parent = [&](const std::string& name) { return position_of(name) < parent_names.size(); };
  for (const auto* axis : {&request.x, &request.y}) {
    if (!is_parent(*axis)) {
      throw model_error("'" + *axis + "' is not a parent of '" + request.node +
                        "' (its parents: " + (parent_names.empty() ? "none" : text::join(parent_names)) + ")");
    }
  }
  if (request.x == request.y) throw model_error("the two axes are both '" + request.x + "'");
  std::vector<observation> observed;
  std::vector<std::pair<std::string, state_index>> fixed;
  for (const auto& [name, value] : request.given) {
    if (name == request.node || name == request.x || name == request.y) {
      throw model_error("'" + name + "' is an axis or the node itself, so it cannot be given");
    }
    const auto state = state_of(network.at(name), value);
    observed.push_back({node_of(network, name), state});
    fixed.emplace_back(name, state);
  }
  if (!request.average) {
    std::vector<std::string> open;
    for (const auto& name : parent_names) {
      const bool set = name == request.x || name == request.y ||
                       std::any_of(fixed.begin(), fixed.end(), [&](const auto& f) { return f.first == name; });
      if (!set) open.push_back(name);
    }
    if (!open.empty()) {
      throw model_error("'" + request.node + "' has more parents than the two axes: give " + text::join(open) +
                        " a state each (e.g. " + open.front() + "=" +
                        (network.at(open.front()).has_intervals() ? "@" : "") +
                        network.at(open.front()).states().front() + "), or average over them");
    }
  }
  table_slice result;
  result.node = &node;
  result.x = &network.at(request.x);
  result.y = &network.at(request.y);
  result.state = request.state ? node.state(*request.state).value() : node.cardinality() - 1;
  const auto nx = result.x->cardinality(), ny = result.y->cardinality(), j = node.cardinality();
  result.probability.resize(nx * ny);
  const bool only_parents_given =
      std::all_of(fixed.begin(), fixed.end(), [&](const auto& f) { return is_parent(f.first); });
  if (only_parents_given && fixed.size() + 2 == parent_names.size()) {
    // Every parent set: the cells are the table's own entries, read without inference.
    const auto& table = network.table(target);
    std::vector<std::size_t> digits(parent_names.size());
    for (const auto& [name, state] : fixed) digits[position_of(name)] = state.value();
    const auto px = position_of(request.x), py = position_of(request.y);
    for (std::size_t i = 0; i < nx; ++i) {
      for (std::size_t k = 0; k < ny; ++k) {
        digits[px] = i;
        digits[py] = k;
        result.probability[k * nx + i] = table(index_at<state_index>(result.state), table.configuration(digits));
      }
    }
  } else {
    junction_tree_engine engine(borrowed(network));
    const std::vector<std::string> axes{request.x, request.y};
    const auto table = success_table(engine, request.node, axes, observed);
    for (std::size_t i = 0; i < nx; ++i) {
      for (std::size_t k = 0; k < ny; ++k) {
        result.probability[k * nx + i] = table.values()[(i * ny + k) * j + result.state];
      }
    }
  }
  if (statistics) result.rows = detail::cell_rows(statistics->counts.at(target.value()), *result.x, *result.y, fixed);
  return result;
}

}  // namespace pgm
