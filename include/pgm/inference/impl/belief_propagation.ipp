#pragma once
// The definitions of pgm/inference/belief_propagation.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>

#include "pgm/inference/belief_propagation.hpp"

namespace pgm::detail {

namespace belief_propagation_internal {

constexpr double minus_infinity = -std::numeric_limits<double>::infinity();

/// ln Σ exp(values); −∞ for an empty or all −∞ span.
inline double log_sum_exp(std::span<const double> values) {
  double top = minus_infinity;
  for (const double v : values) top = std::max(top, v);
  if (top == minus_infinity) return minus_infinity;
  double sum = 0.0;
  for (const double v : values) sum += std::exp(v - top);
  return top + std::log(sum);
}

/// Shifts `values` so that their exponentials sum to one; leaves them if all are −∞ and says so.
inline bool normalize_logs(std::span<double> values) {
  const double total = log_sum_exp(values);
  if (total == minus_infinity) return false;
  for (double& v : values) v -= total;
  return true;
}

/// The largest change between two normalized log messages, in probability.
inline double change(std::span<const double> a, std::span<const double> b) {
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, std::abs(std::exp(a[i]) - std::exp(b[i])));
  return largest;
}

/// The factor graph with its messages: edge e = (factor, k-th variable of its scope).
class factor_graph_messages {
 public:
  factor_graph_messages(const std::vector<std::size_t>& cards,
                        const std::vector<factor_of<log_sum_product<double>>>& factors, const bp_options& options)
      : cards_(cards), factors_(factors), options_(options) {
    edges_of_factor_.resize(factors.size());
    edges_of_variable_.resize(cards.size());
    for (std::size_t f = 0; f < factors.size(); ++f) {
      const auto& scope = factors[f].scope();
      for (std::size_t k = 0; k < scope.size(); ++k) {
        const auto e = edges_.size();
        edges_.push_back({f, k, scope[k].value(), offset_});
        offset_ += cards[scope[k].value()];
        edges_of_factor_[f].push_back(e);
        edges_of_variable_[scope[k].value()].push_back(e);
      }
    }
    // Uniform messages to start with.
    to_variable_.resize(offset_);
    to_factor_.resize(offset_);
    for (const auto& e : edges_) {
      const double uniform = -std::log(static_cast<double>(cards[e.variable]));
      std::fill_n(to_variable_.begin() + static_cast<std::ptrdiff_t>(e.offset), cards[e.variable], uniform);
      std::fill_n(to_factor_.begin() + static_cast<std::ptrdiff_t>(e.offset), cards[e.variable], uniform);
    }
    candidate_.resize(offset_);
  }

  /// Runs the schedule; returns whether it converged, the iterations and the last residual.
  void run(bp_result& result) {
    if (options_.schedule == bp_schedule::parallel) {
      run_parallel(result);
    } else {
      run_residual(result);
    }
  }

  [[nodiscard]] bool contradicted() const noexcept { return contradicted_; }

  /// Every variable's belief, as probabilities.
  [[nodiscard]] std::vector<std::vector<double>> beliefs() {
    std::vector<std::vector<double>> result(cards_.size());
    for (std::size_t v = 0; v < cards_.size(); ++v) {
      std::vector<double> logs(cards_[v], 0.0);
      for (const auto e : edges_of_variable_[v]) {
        for (std::size_t x = 0; x < cards_[v]; ++x) logs[x] += to_variable_[edges_[e].offset + x];
      }
      if (!normalize_logs(logs)) contradicted_ = true;
      for (const double l : logs) result[v].push_back(std::exp(l));
    }
    return result;
  }

  /// −F_Bethe from the current messages.
  [[nodiscard]] double bethe_log_partition() {
    double total = 0.0;
    std::vector<double> belief;
    for (std::size_t f = 0; f < factors_.size(); ++f) {
      const auto values = factors_[f].values();
      belief.assign(values.begin(), values.end());
      for_each_cell(f, [&](std::size_t cell, std::span<const std::size_t> states) {
        for (std::size_t k = 0; k < states.size(); ++k) {
          belief[cell] += to_factor_[edges_[edges_of_factor_[f][k]].offset + states[k]];
        }
      });
      if (!normalize_logs(belief)) return minus_infinity;
      for (std::size_t i = 0; i < belief.size(); ++i) {
        if (belief[i] == minus_infinity) continue;
        total += std::exp(belief[i]) * (values[i] - belief[i]);
      }
    }
    for (std::size_t v = 0; v < cards_.size(); ++v) {
      std::vector<double> logs(cards_[v], 0.0);
      for (const auto e : edges_of_variable_[v]) {
        for (std::size_t x = 0; x < cards_[v]; ++x) logs[x] += to_variable_[edges_[e].offset + x];
      }
      if (!normalize_logs(logs)) return minus_infinity;
      double entropy_term = 0.0;
      for (const double l : logs) {
        if (l != minus_infinity) entropy_term += std::exp(l) * l;
      }
      const auto degree = static_cast<double>(edges_of_variable_[v].size());
      total += (degree - 1.0) * entropy_term;
    }
    return total;
  }

 private:
  struct edge {
    std::size_t factor;
    std::size_t position;  ///< in the factor's scope
    std::size_t variable;
    std::size_t offset;  ///< of its messages in to_variable_ and to_factor_
  };

  /// Calls visit(cell, states) for every cell of factor f with the states of its scope.
  template <class Visit>
  void for_each_cell(std::size_t f, Visit&& visit) const {
    const auto& factor_cards = factors_[f].cardinalities();
    std::vector<std::size_t> states(factor_cards.size(), 0);
    const auto size = factors_[f].size();
    for (std::size_t cell = 0; cell < size; ++cell) {
      visit(cell, std::span<const std::size_t>(states));
      for (std::size_t k = states.size(); k-- > 0;) {
        if (++states[k] < factor_cards[k]) break;
        states[k] = 0;
      }
    }
  }

  /// The message from variable v to edge e's factor: the product of v's other incoming messages.
  void variable_to_factor(std::size_t e) {
    const auto& own = edges_[e];
    const auto card = cards_[own.variable];
    double* out = to_factor_.data() + own.offset;
    std::fill_n(out, card, 0.0);
    for (const auto other : edges_of_variable_[own.variable]) {
      if (other == e) continue;
      const double* in = to_variable_.data() + edges_[other].offset;
      for (std::size_t x = 0; x < card; ++x) out[x] += in[x];
    }
    if (!normalize_logs(std::span<double>(out, card))) contradicted_ = true;
  }

  /// Factor f's new messages to each of its variables, from the messages into it, into
  /// candidate_ (damped); returns the largest change they would make.
  double factor_to_variables(std::size_t f) {
    const auto& edges = edges_of_factor_[f];
    const auto values = factors_[f].values();
    // Each cell's value with every incoming message; a variable's own message is taken out again
    // where it is finite, and the cell recomputed where it is not.
    cell_total_.assign(values.begin(), values.end());
    for_each_cell(f, [&](std::size_t cell, std::span<const std::size_t> states) {
      for (std::size_t k = 0; k < states.size(); ++k)
        cell_total_[cell] += to_factor_[edges_[edges[k]].offset + states[k]];
    });
    double largest = 0.0;
    for (std::size_t k = 0; k < edges.size(); ++k) {
      const auto& e = edges_[edges[k]];
      const auto card = cards_[e.variable];
      double* out = candidate_.data() + e.offset;
      std::fill_n(out, card, minus_infinity);
      const double* own = to_factor_.data() + e.offset;
      for_each_cell(f, [&](std::size_t cell, std::span<const std::size_t> states) {
        const auto x = states[k];
        double v = 0.0;
        if (own[x] != minus_infinity) {
          v = cell_total_[cell] - own[x];
        } else {
          v = values[cell];
          for (std::size_t j = 0; j < states.size(); ++j) {
            if (j != k) v += to_factor_[edges_[edges[j]].offset + states[j]];
          }
        }
        out[x] = log_sum_product<double>::plus(out[x], v);
      });
      if (!normalize_logs(std::span<double>(out, card))) {
        contradicted_ = true;
        std::copy_n(to_variable_.data() + e.offset, card, out);
        continue;
      }
      if (options_.damping > 0.0) {
        const double* old = to_variable_.data() + e.offset;
        for (std::size_t x = 0; x < card; ++x) {
          if (out[x] != minus_infinity && old[x] != minus_infinity) {
            out[x] = options_.damping * old[x] + (1.0 - options_.damping) * out[x];
          }
        }
        normalize_logs(std::span<double>(out, card));
      }
      largest = std::max(largest, change(std::span<const double>(out, card),
                                         std::span<const double>(to_variable_.data() + e.offset, card)));
    }
    return largest;
  }

  void commit(std::size_t f) {
    for (const auto e : edges_of_factor_[f]) {
      std::copy_n(candidate_.data() + edges_[e].offset, cards_[edges_[e].variable],
                  to_variable_.data() + edges_[e].offset);
    }
  }

  /// The residual schedule looks at the clock once per this many updates, or per iteration
  /// (one update per factor) when that is fewer.
  static constexpr std::size_t time_check_updates = 256;

  [[nodiscard]] bool past_time_limit() const {
    const std::chrono::duration<double> spent = std::chrono::steady_clock::now() - started_;
    return spent.count() > options_.time_limit_seconds;
  }

  void run_parallel(bp_result& result) {
    for (result.iterations = 0; result.iterations < options_.max_iterations;) {
      for (std::size_t e = 0; e < edges_.size(); ++e) variable_to_factor(e);
      double largest = 0.0;
      for (std::size_t f = 0; f < factors_.size(); ++f) largest = std::max(largest, factor_to_variables(f));
      for (std::size_t f = 0; f < factors_.size(); ++f) commit(f);
      ++result.iterations;
      result.residual = largest;
      if (largest <= options_.tolerance) {
        result.converged = true;
        break;
      }
      if (past_time_limit()) {
        result.timed_out = true;
        break;
      }
    }
    for (std::size_t e = 0; e < edges_.size(); ++e) variable_to_factor(e);
  }

  void run_residual(bp_result& result) {
    const auto m = factors_.size();
    std::vector<double> residual(m, 0.0);
    using entry = std::pair<double, std::size_t>;
    std::priority_queue<entry> queue;
    for (std::size_t e = 0; e < edges_.size(); ++e) variable_to_factor(e);
    for (std::size_t f = 0; f < m; ++f) {
      residual[f] = factor_to_variables(f);
      queue.emplace(residual[f], f);
    }
    const std::size_t budget = options_.max_iterations * std::max<std::size_t>(m, 1);
    std::size_t updates = 0;
    std::vector<char> touched(m, 0);
    std::vector<std::size_t> neighbours;
    result.residual = 0.0;
    while (!queue.empty()) {
      const auto [r, f] = queue.top();
      if (r != residual[f]) {  // an older entry of a factor whose residual has changed
        queue.pop();
        continue;
      }
      result.residual = r;
      if (r <= options_.tolerance) {
        result.converged = true;
        break;
      }
      if (updates == budget) break;
      if (updates % std::min(time_check_updates, m) == 0 && updates > 0 && past_time_limit()) {
        result.timed_out = true;
        break;
      }
      queue.pop();
      ++updates;
      // Recomputed in place: a factor's own messages in candidate_ are those of its last
      // evaluation, which its residual describes.
      commit(f);
      residual[f] = 0.0;
      queue.emplace(0.0, f);
      neighbours.clear();
      for (const auto e : edges_of_factor_[f]) {
        for (const auto other : edges_of_variable_[edges_[e].variable]) {
          if (edges_[other].factor == f) continue;
          variable_to_factor(other);
          const auto g = edges_[other].factor;
          if (!touched[g]) {
            touched[g] = 1;
            neighbours.push_back(g);
          }
        }
      }
      for (const auto g : neighbours) {
        touched[g] = 0;
        residual[g] = factor_to_variables(g);
        queue.emplace(residual[g], g);
      }
    }
    if (queue.empty()) result.converged = true;
    result.iterations = (updates + m - 1) / std::max<std::size_t>(m, 1);
    for (std::size_t e = 0; e < edges_.size(); ++e) variable_to_factor(e);
  }

  const std::vector<std::size_t>& cards_;
  const std::vector<factor_of<log_sum_product<double>>>& factors_;
  bp_options options_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  std::vector<edge> edges_;
  std::vector<std::vector<std::size_t>> edges_of_factor_;
  std::vector<std::vector<std::size_t>> edges_of_variable_;
  std::size_t offset_ = 0;
  std::vector<double> to_variable_;
  std::vector<double> to_factor_;
  std::vector<double> candidate_;
  std::vector<double> cell_total_;
  bool contradicted_ = false;
};

}  // namespace belief_propagation_internal

PGM_DECL bp_result run_belief_propagation(const std::vector<std::size_t>& cardinalities,
                                          const std::vector<factor_of<log_sum_product<double>>>& factors,
                                          const bp_options& options) {
  using namespace belief_propagation_internal;
  bp_result result;
  for (const auto& f : factors) {
    if (total_of<log_sum_product<double>>(f) == minus_infinity) {
      result.log_partition = minus_infinity;
      return result;
    }
  }
  factor_graph_messages graph(cardinalities, factors, options);
  graph.run(result);
  result.marginals = graph.beliefs();
  result.log_partition = graph.contradicted() ? minus_infinity : graph.bethe_log_partition();
  return result;
}

}  // namespace pgm::detail
