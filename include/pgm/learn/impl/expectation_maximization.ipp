#pragma once
// The definitions of pgm/learn/expectation_maximization.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/expectation_maximization.hpp"

namespace pgm {

PGM_DECL std::string summary_of(const em_result& em) {
  return "EM: " + std::to_string(em.iterations) + " iterations" +
         (em.converged ? " (converged)" : " (stopped at the iteration limit)") + ", log-likelihood " +
         text::format_double(em.log_likelihood) + ", " + std::to_string(em.patterns) + " distinct rows (" +
         std::to_string(em.incomplete_patterns) + " with a missing value)" +
         (em.restart > 0 ? ", from start " + std::to_string(em.restart + 1) : "");
}

PGM_DECL std::vector<double> pseudo_counts_of(const parameter_prior& prior, const variable& child,
                                              const std::vector<variable>& parents) {
  std::size_t configurations = 1;
  for (const auto& p : parents) configurations *= p.cardinality();
  return prior.pseudo_counts(child, parents).spelled_out(child.cardinality() * configurations);
}

}  // namespace pgm

namespace pgm::detail {

PGM_DECL observed_patterns patterns_of(const network_structure& structure, const dataset& data) {
  const std::size_t n = structure.size();
  std::vector<const discrete_column*> columns(n, nullptr);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& v = structure.variables()[i];
    if (!data.contains(v.name())) continue;  // latent
    const auto& column = data.discrete(v.name());
    if (column.var().states() != v.states()) {
      throw data_error((data.source().empty() ? std::string() : data.source() + ": ") + "column '" + v.name() +
                       "' has the states {" + text::list_for_message(column.var().states()) +
                       "} but the network expects {" + text::list_for_message(v.states()) + "}");
    }
    columns[i] = &column;
  }
  std::vector<std::uint32_t> all(data.rows() * n, observed_patterns::absent);
  for (std::size_t i = 0; i < n; ++i) {
    if (!columns[i]) continue;
    for (std::size_t row = 0; row < data.rows(); ++row) {
      if (!columns[i]->is_missing(row)) all[row * n + i] = columns[i]->code(row);
    }
  }
  std::vector<std::size_t> order(data.rows());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto row_of = [&](std::size_t row) { return std::span<const std::uint32_t>(all.data() + row * n, n); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto x = row_of(a);
    const auto y = row_of(b);
    return std::lexicographical_compare(x.begin(), x.end(), y.begin(), y.end());
  });
  observed_patterns patterns;
  patterns.nodes = n;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto row = row_of(order[k]);
    if (k > 0 && std::equal(row.begin(), row.end(), row_of(order[k - 1]).begin())) {
      patterns.rows.back() += 1.0;
      continue;
    }
    patterns.codes.insert(patterns.codes.end(), row.begin(), row.end());
    patterns.rows.push_back(1.0);
  }
  return patterns;
}

PGM_DECL std::vector<std::vector<variable_id>> family_members(const network_structure& structure) {
  std::vector<std::vector<variable_id>> families;
  for (std::size_t i = 0; i < structure.size(); ++i) {
    const variable_id node = index_at<variable_id>(i);
    std::vector<variable_id> members{node};
    for (auto parent : structure.parents(node)) members.push_back(parent);
    families.push_back(std::move(members));
  }
  return families;
}

PGM_DECL std::size_t cell_of(const expected_count_table& table, std::span<const std::size_t> values) {
  std::size_t configuration = 0;
  for (std::size_t k = 1; k < values.size(); ++k) {
    configuration += values[k] * table.parent_radix().stride(k - 1);
  }
  return configuration * table.child_cardinality() + values[0];
}

PGM_DECL std::vector<expected_count_table> empty_counts(const network_structure& structure) {
  std::vector<expected_count_table> counts;
  for (std::size_t i = 0; i < structure.size(); ++i) {
    const variable_id node = index_at<variable_id>(i);
    counts.emplace_back(structure.at(node), structure.parent_variables(node));
  }
  return counts;
}

PGM_DECL void add_counts(std::vector<expected_count_table>& to, const std::vector<expected_count_table>& from) {
  for (std::size_t i = 0; i < to.size(); ++i) {
    auto cells = to[i].counts();
    const auto more = from[i].counts();
    for (std::size_t c = 0; c < cells.size(); ++c) cells[c] += more[c];
  }
}

PGM_DECL double prior_term(const bayesian_network& network, const std::vector<std::vector<double>>& alpha) {
  double sum = 0.0;
  for (std::size_t i = 0; i < network.size(); ++i) {
    const auto values = network.tables()[i].values();
    for (std::size_t c = 0; c < values.size(); ++c) {
      if (alpha[i][c] > 0.0) sum += alpha[i][c] * std::log(values[c]);
    }
  }
  return sum;
}

}  // namespace pgm::detail
