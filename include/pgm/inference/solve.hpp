#pragma once
/// \file
/// The UAI competitions' four tasks on any `GraphicalModel` (a Markov network, a Bayesian
/// network), exact:
///
/// | task | answer | function |
/// |---|---|---|
/// | PR | ln Z(e): the partition function with the evidence (P(e) for a Bayesian network) | `log_partition` |
/// | MAR | every variable's marginal given the evidence (a point mass on an observed one) | `all_marginals` |
/// | MAP | a most probable joint state of every variable given the evidence | `most_probable_assignment` |
/// | MMAP | a most probable joint state of the query variables, the others summed out | `marginal_map` |
///
/// Engines: `jt` compiles a junction tree once and propagates (PR, MAR and MAP from one tree;
/// MMAP, whose sums must come before its maxima, is eliminated in a constrained order); `ve`
/// eliminates afresh for each answer. Both predict the size of their tables from the
/// triangulation before allocating any, and refuse past `memory_limit_bytes`, naming both.
/// `bp`, loopy belief propagation (belief_propagation.hpp), answers PR (the Bethe estimate) and
/// MAR approximately on any model, and `gibbs` (factor_gibbs.hpp) MAR by sampling; `auto` is `jt`
/// when its tree fits in memory, else `bp`, and the report says which ran, whether it is exact,
/// and whether bp converged.
///
/// Why log space when it is needed, and only then: a model's values need not be probabilities, so
/// Z may be 10^300 and beyond (the competition's Grids) or a product may underflow on the way to a
/// Z that does not. The functions bound every partial product from the factors' largest and
/// smallest positive values before they start: within a double's range they work in
/// probabilities (fast, exact to rounding), past its top in logarithms, and past its bottom in
/// probabilities while the floating-point flags say no value left the range, else in logarithms.

#include <array>
#include <cfenv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/graphical_model.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/inference/belief_propagation.hpp"
#include "pgm/inference/evidence_reduction.hpp"
#include "pgm/inference/exact.hpp"
#include "pgm/inference/factor.hpp"
#include "pgm/inference/factor_gibbs.hpp"
#include "pgm/inference/junction_tree.hpp"
#include "pgm/inference/propagation.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/inference/semiring.hpp"
#include "pgm/inference/triangulation.hpp"
#include "pgm/inference/variable_elimination.hpp"

namespace pgm {

/// The engines the tasks run on: exact (jt, ve) or approximate (bp), or auto.
enum class solve_engine { automatic, jt, ve, bp, gibbs };

inline constexpr std::array all_solve_engines{solve_engine::automatic, solve_engine::jt, solve_engine::ve,
                                              solve_engine::bp, solve_engine::gibbs};

[[nodiscard]] constexpr std::string_view to_string(solve_engine engine) noexcept {
  switch (engine) {
    case solve_engine::automatic:
      return "auto";
    case solve_engine::jt:
      return "jt";
    case solve_engine::ve:
      return "ve";
    case solve_engine::bp:
      return "bp";
    case solve_engine::gibbs:
      return "gibbs";
  }
  return "?";
}

/// "auto", "jt", "ve", "bp" or "gibbs"; throws unknown_name otherwise.
[[nodiscard]] inline solve_engine parse_solve_engine(std::string_view text) {
  return parse_choice("engine", text, all_solve_engines);
}

[[nodiscard]] inline std::vector<std::string> known_solve_engines() { return names_of(all_solve_engines); }

struct solve_options {
  solve_engine engine = solve_engine::automatic;
  elimination_heuristic heuristic = elimination_heuristic::min_fill;
  /// The elimination order's search: the greedy order and this many seeded restarts.
  order_search search{.restarts = 32, .seed = 1, .work_per_cell = 8.0};
  /// The competition's budget: 4 GiB.
  std::size_t memory_limit_bytes = std::size_t{4096} << 20;
  /// What `bp` runs with.
  bp_options bp;
  /// What `gibbs` runs with.
  factor_gibbs_options gibbs;
};

/// How an answer was computed, for the user to read.
struct solve_report {
  /// The engine that answered ("jt", "ve", "bp").
  std::string engine;
  bool exact = true;
  /// Whether the work ran in logarithms (see the file comment).
  bool log_space = false;
  /// The triangulation's largest table and all its tables together, in cells.
  std::size_t largest_table_cells = 0;
  std::size_t total_cells = 0;
  /// For bp: whether it converged, after how many iterations, and its last residual.
  bool converged = true;
  std::size_t iterations = 0;
  double residual = 0.0;
  /// For bp and gibbs: whether the time limit stopped them (their answer is what they had).
  bool timed_out = false;
  /// Why auto chose the engine it ran, when it was not jt.
  std::string note;
};

namespace detail {

/// What one cell of a junction tree costs while propagating: the clique's base table, its table
/// with evidence, and the product a message is folded from, in doubles.
inline constexpr std::size_t bytes_per_tree_cell = 3 * sizeof(double);

/// Whether the partial products and sums of `model`'s factors might leave a double's normal range,
/// from bounds on all of them at once: above, Π max(1, largest value) times the number of joint
/// states, against 10^300; below, Π min(1, smallest positive value), against 10^-300 (zeros are
/// exact in any representation).
struct range_bounds {
  bool may_overflow = false;
  bool may_underflow = false;
};

template <GraphicalModel M>
[[nodiscard]] range_bounds range_bounds_of(const M& model) {
  constexpr double bound = 300.0 * 2.302585092994046;  // ln 10^300
  double high = 0.0;
  double low = 0.0;
  for (const auto& v : model.variables()) high += std::log(static_cast<double>(v.cardinality()));
  for (std::size_t f = 0; f < model.factor_count(); ++f) {
    const auto& table = model.factor(f);
    double largest = 0.0;
    double smallest = std::numeric_limits<double>::infinity();
    for (const double value : table.values()) {
      largest = std::max(largest, value);
      if (value > 0.0) smallest = std::min(smallest, value);
    }
    if (largest > 1.0) high += std::log(largest);
    if (smallest < 1.0) low += std::log(smallest);
  }
  return {high > bound, low < -bound};
}

/// The junction tree of `model` within the memory limit; throws memory_limit_exceeded naming the
/// tree's size, its largest table and the limit. Nothing for the bp engine, nor for auto past the
/// limit where bp can answer (`bp_answers`), with the report's note saying why.
template <GraphicalModel M>
[[nodiscard]] std::shared_ptr<const junction_tree> tree_within(const M& model, const solve_options& options,
                                                               solve_report& report, bool bp_answers = true) {
  if (options.engine == solve_engine::bp || options.engine == solve_engine::gibbs) return nullptr;
  const auto cells = options.memory_limit_bytes / bytes_per_tree_cell;
  // Compiled without a bound first: the triangulation only lists cliques, it allocates no table.
  auto tree = std::make_shared<const junction_tree>(
      model, junction_tree_options{options.heuristic, std::numeric_limits<std::size_t>::max(), false, options.search});
  report.largest_table_cells = tree->largest_clique_cells();
  report.total_cells = tree->total_cells();
  if (tree->total_cells() > cells) {
    if (options.engine == solve_engine::automatic && bp_answers) {
      report.note = "auto chose bp: the junction tree needs " + std::to_string(tree->total_cells()) +
                    " cells, more than the memory limit of " + std::to_string(options.memory_limit_bytes >> 20) +
                    " MiB holds";
      return nullptr;
    }
    throw memory_limit_exceeded(
        "exact inference needs a junction tree of " + std::to_string(tree->total_cells()) + " cells (" +
        std::to_string(tree->total_cells() / (std::size_t{1} << 20) * bytes_per_tree_cell) +
        " MiB; its largest table " + std::to_string(tree->largest_clique_cells()) +
        " cells), more than the memory limit of " + std::to_string(options.memory_limit_bytes >> 20) +
        " MiB; raise the limit, search longer for an elimination order, or use an approximate engine (bp)");
  }
  return tree;
}

/// The cells of the tables marginal MAP's constrained elimination creates: the variables
/// neither queried nor observed first, then the query, each greedily, on the graph of the factors
/// with the evidence entered. Throws memory_limit_exceeded past the limit.
template <GraphicalModel M>
void check_marginal_map_size(const M& model, std::span<const variable_id> query, const evidence_set& observed,
                             const solve_options& options, solve_report& report) {
  const auto cards = cardinalities_of(model);
  std::vector<char> role(model.size(), 0);  // 0 summed, 1 maximized, 2 fixed
  for (auto id : query) role[id.value()] = 1;
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (observed.fixes(index_at<variable_id>(i))) role[i] = 2;
  }
  std::vector<std::vector<variable_id>> scopes;
  for (auto scope : scopes_of(model)) {
    std::erase_if(scope, [&](variable_id v) { return role[v.value()] == 2; });
    scopes.push_back(std::move(scope));
  }
  auto graph = interaction_graph_of(model.size(), scopes);
  std::unique_ptr<bool[]> summed(new bool[model.size()]());
  for (std::size_t i = 0; i < model.size(); ++i) summed[i] = role[i] == 0;
  const auto first =
      greedy_elimination(graph, cards, options.heuristic, std::span<const bool>(summed.get(), model.size()));
  // What the sums leave: the maximized variables, joined where a summed variable's clique joined them.
  for (const auto& clique : first.cliques) {
    for (std::size_t a = 0; a < clique.size(); ++a) {
      for (std::size_t b = a + 1; b < clique.size(); ++b) {
        if (role[clique[a]] == 1 && role[clique[b]] == 1 && !boost::edge(clique[a], clique[b], graph).second) {
          boost::add_edge(clique[a], clique[b], graph);
        }
      }
    }
  }
  std::unique_ptr<bool[]> maximized(new bool[model.size()]());
  for (std::size_t i = 0; i < model.size(); ++i) maximized[i] = role[i] == 1;
  const auto second =
      greedy_elimination(graph, cards, options.heuristic, std::span<const bool>(maximized.get(), model.size()));
  report.total_cells = saturating_add(elimination_cells(first, cards), elimination_cells(second, cards));
  report.largest_table_cells = 0;
  for (const auto* e : {&first, &second}) {
    for (const auto& clique : e->cliques) {
      std::size_t cells = 1;
      for (auto v : clique) cells = saturating_multiply(cells, cards[v]);
      report.largest_table_cells = std::max(report.largest_table_cells, cells);
    }
  }
  // Elimination keeps about two tables of a step's size at a time, not a whole tree.
  if (saturating_multiply(report.largest_table_cells, 2 * sizeof(double)) > options.memory_limit_bytes) {
    throw memory_limit_exceeded(
        "marginal MAP eliminates the summed variables before the query's, which needs a table of " +
        std::to_string(report.largest_table_cells) + " cells (" + std::to_string(report.total_cells) +
        " in all), more than the memory limit of " + std::to_string(options.memory_limit_bytes >> 20) + " MiB");
  }
}

/// Runs bp and says so in the report.
template <GraphicalModel M>
[[nodiscard]] bp_result approximate(const M& model, const evidence_set& observed, const solve_options& options,
                                    solve_report& report) {
  auto result = belief_propagation(model, observed, options.bp);
  report.engine = "bp";
  report.exact = false;
  report.log_space = true;
  report.converged = result.converged;
  report.iterations = result.iterations;
  report.residual = result.residual;
  report.timed_out = result.timed_out;
  return result;
}

template <Semiring S>
[[nodiscard]] double natural_log_of(typename S::value_type value) {
  if constexpr (stores_logarithms<S>) {
    return static_cast<double>(value);
  } else {
    return std::log(static_cast<double>(value));
  }
}

/// Watches the floating-point status flags of this thread while it lives: whether any result since
/// it began overflowed, underflowed (a tiny result that lost digits, or a positive one flushed to
/// zero) or was undefined. The flags it finds are restored when it ends.
class range_watch {
 public:
  static constexpr int flags = FE_OVERFLOW | FE_UNDERFLOW | FE_INVALID;
  range_watch() {
    std::fegetexceptflag(&saved_, flags);
    std::feclearexcept(flags);
  }
  range_watch(const range_watch&) = delete;
  range_watch& operator=(const range_watch&) = delete;
  ~range_watch() { std::fesetexceptflag(&saved_, flags); }
  [[nodiscard]] bool left_the_range() const noexcept { return std::fetestexcept(flags) != 0; }

 private:
  std::fexcept_t saved_{};
};

/// Runs `work<S>()` in probabilities or in logarithms, for the sum semirings (Max false) or the
/// max ones. Probabilities when `model` cannot leave a double's range (range_bounds_of); where it
/// might overflow, logarithms (Z may be 10^300 and beyond). Where it might only underflow, the
/// bound, a product of worst cases, is far from what most models reach (the competition's CSP
/// and Segmentation never come near it): probabilities still, with the floating-point flags
/// watched, and logarithms again only if a value did leave the range. `work` must be safe to run
/// twice; an impossible_evidence it throws counts only if the range held.
template <bool Max, GraphicalModel M, class Work>
decltype(auto) in_fitting_semiring(const M& model, solve_report& report, Work&& work) {
  using plain = std::conditional_t<Max, max_product<double>, sum_product<double>>;
  using logs = std::conditional_t<Max, log_max_product<double>, log_sum_product<double>>;
  const auto bounds = range_bounds_of(model);
  report.log_space = bounds.may_overflow;
  if (report.log_space) return work.template operator()<logs>();
  if (!bounds.may_underflow) return work.template operator()<plain>();
  {
    const range_watch watch;
    try {
      auto answer = work.template operator()<plain>();
      if (!watch.left_the_range()) return answer;
    } catch (const impossible_evidence&) {
      if (!watch.left_the_range()) throw;
    }
  }
  report.log_space = true;
  return work.template operator()<logs>();
}

/// `model` with `observed` entered into its factors (evidence_reduction.hpp) where the engine is
/// exact or chosen by auto: bp and gibbs run on the model as given.
template <GraphicalModel M>
[[nodiscard]] std::optional<evidence_reduced_model> reduced_for(const M& model, const evidence_set& observed,
                                                                const solve_options& options) {
  if (options.engine == solve_engine::bp || options.engine == solve_engine::gibbs) return std::nullopt;
  return reduce_by_evidence(model, observed);
}

/// Each fixed variable's marginal in `marginals` as a point mass on its state.
template <GraphicalModel M>
void set_point_masses(const M& model, std::span<const observation> fixed, std::vector<std::vector<double>>& marginals) {
  for (const auto& o : fixed) {
    marginals[o.variable.value()].assign(model.variables()[o.variable.value()].cardinality(), 0.0);
    marginals[o.variable.value()][o.state.value()] = 1.0;
  }
}

/// A probability vector from unnormalized values in S, given their ⊕-total; a point mass on
/// `observed` when it is set.
template <Semiring S>
[[nodiscard]] std::vector<double> normalized(std::span<const typename S::value_type> values,
                                             typename S::value_type total) {
  std::vector<double> result;
  result.reserve(values.size());
  for (const auto v : values) {
    if constexpr (stores_logarithms<S>) {
      result.push_back(std::exp(static_cast<double>(v - total)));
    } else {
      result.push_back(static_cast<double>(v / total));
    }
  }
  return result;
}

}  // namespace detail

/// ln Z(e): the partition function of `model` with the evidence entered (its probability, for
/// a Bayesian network); −∞ when the evidence is impossible.
template <GraphicalModel M>
[[nodiscard]] double log_partition(const M& model, const evidence_set& observed, const solve_options& options = {},
                                   solve_report* report = nullptr) {
  solve_report local;
  auto& r = report ? *report : local;
  if (options.engine == solve_engine::gibbs) {
    throw model_error("gibbs answers MAR; the partition function needs jt, ve or bp");
  }
  if (const auto reduced = detail::reduced_for(model, observed, options)) {
    if (reduced->impossible) return -std::numeric_limits<double>::infinity();
    return log_partition(reduced->model, {}, options, &r) + reduced->log_constant;
  }
  const auto tree = detail::tree_within(model, options, r);
  if (!tree) {
    try {
      return detail::approximate(model, observed, options, r).log_partition;
    } catch (const impossible_evidence&) {
      return -std::numeric_limits<double>::infinity();
    }
  }
  return detail::in_fitting_semiring<false>(model, r, [&]<Semiring S>() {
    if (options.engine == solve_engine::ve) {
      r.engine = "ve";
      return detail::natural_log_of<S>(total_of<S>(joint_in<S>(model, {}, observed, options.heuristic)));
    }
    r.engine = "jt";
    propagation<S> engine(tree, model);
    engine.set_evidence(observed);
    return detail::natural_log_of<S>(engine.total());
  });
}

/// Every variable's marginal given the evidence, in id order; an observed variable's is a point
/// mass on its state. Throws impossible_evidence when the evidence has probability 0.
template <GraphicalModel M>
[[nodiscard]] std::vector<std::vector<double>> all_marginals(const M& model, const evidence_set& observed,
                                                             const solve_options& options = {},
                                                             solve_report* report = nullptr) {
  solve_report local;
  auto& r = report ? *report : local;
  if (const auto reduced = detail::reduced_for(model, observed, options)) {
    std::vector<std::vector<double>> free;
    if (reduced->impossible) detail::throw_impossible(model, observed);
    try {
      free = all_marginals(reduced->model, {}, options, &r);
    } catch (const impossible_evidence&) {
      detail::throw_impossible(model, observed);
    }
    std::vector<std::vector<double>> result(model.size());
    for (std::size_t k = 0; k < free.size(); ++k) result[reduced->original[k].value()] = std::move(free[k]);
    detail::set_point_masses(model, observed.hard, result);
    return result;
  }
  const auto tree = detail::tree_within(model, options, r);
  std::vector<std::vector<double>> result(model.size());
  std::vector<variable_id> free;
  for (std::size_t i = 0; i < model.size(); ++i) {
    const variable_id id = index_at<variable_id>(i);
    if (!observed.fixes(id)) free.push_back(id);
  }
  if (options.engine == solve_engine::gibbs) {
    auto sampled = factor_gibbs(model, observed, options.gibbs);
    r.engine = "gibbs";
    r.exact = false;
    r.converged = sampled.stuck_draws == 0;
    r.iterations = sampled.sweeps;
    r.timed_out = sampled.timed_out;
    if (sampled.stuck_draws > 0) {
      r.note = std::to_string(sampled.stuck_draws) +
               " draws met a conditional with no positive state (zeros in the factors) and were drawn uniformly";
    }
    return std::move(sampled.marginals);
  }
  if (!tree) return detail::approximate(model, observed, options, r).marginals;
  detail::in_fitting_semiring<false>(model, r, [&]<Semiring S>() {
    using value_type = typename S::value_type;
    if (options.engine == solve_engine::ve) {
      r.engine = "ve";
      for (const auto id : free) {
        const variable_id one[] = {id};
        const auto joint = joint_in<S>(model, one, observed, options.heuristic);
        const auto total = total_of<S>(joint);
        if (total == S::zero()) detail::throw_impossible(model, observed);
        result[id.value()] = detail::normalized<S>(joint.values(), total);
      }
      return 0;
    }
    r.engine = "jt";
    propagation<S> engine(tree, model);
    engine.set_evidence(observed);
    const auto tables = engine.marginals(free);
    for (std::size_t k = 0; k < free.size(); ++k) {
      auto total = S::zero();
      for (const auto v : tables[k]) total = S::plus(total, v);
      if (total == S::zero()) detail::throw_impossible(model, observed);
      result[free[k].value()] = detail::normalized<S>(std::span<const value_type>(tables[k]), total);
    }
    if (free.empty() && engine.total() == S::zero()) detail::throw_impossible(model, observed);
    return 0;
  });
  detail::set_point_masses(model, observed.hard, result);
  detail::set_point_masses(model, observed.intervened, result);
  return result;
}

/// A most probable joint state of every variable given the evidence (observed ones in their
/// observed state), in id order. Throws impossible_evidence when the evidence has probability 0.
template <GraphicalModel M>
[[nodiscard]] std::vector<std::size_t> most_probable_assignment(const M& model, const evidence_set& observed,
                                                                const solve_options& options = {},
                                                                solve_report* report = nullptr) {
  solve_report local;
  auto& r = report ? *report : local;
  if (options.engine == solve_engine::bp || options.engine == solve_engine::gibbs) {
    throw model_error(std::string(to_string(options.engine)) +
                      " answers MAR (bp PR too); the most probable assignment needs jt or ve");
  }
  if (const auto reduced = detail::reduced_for(model, observed, options)) {
    std::vector<std::size_t> free;
    if (reduced->impossible) detail::throw_impossible(model, observed);
    try {
      free = most_probable_assignment(reduced->model, {}, options, &r);
    } catch (const impossible_evidence&) {
      detail::throw_impossible(model, observed);
    }
    std::vector<std::size_t> states(model.size(), 0);
    for (std::size_t k = 0; k < free.size(); ++k) states[reduced->original[k].value()] = free[k];
    for (const auto& o : observed.hard) states[o.variable.value()] = o.state.value();
    return states;
  }
  const auto tree = detail::tree_within(model, options, r, false);
  return detail::in_fitting_semiring<true>(model, r, [&]<Semiring S>() {
    std::vector<std::size_t> states(model.size(), 0);
    if (options.engine == solve_engine::ve) {
      r.engine = "ve";
      std::vector<variable_id> free;
      for (std::size_t i = 0; i < model.size(); ++i) {
        const variable_id id = index_at<variable_id>(i);
        if (!observed.fixes(id)) free.push_back(id);
      }
      const auto [chosen, value] = maximum_in<S>(model, free, observed, options.heuristic);
      if (value == S::zero()) detail::throw_impossible(model, observed);
      for (std::size_t k = 0; k < free.size(); ++k) states[free[k].value()] = chosen[k];
    } else {
      r.engine = "jt";
      propagation<S> engine(tree, model);
      engine.set_evidence(observed);
      const auto best = engine.maximize();
      if (best.value == S::zero()) detail::throw_impossible(model, observed);
      states = best.states;
    }
    for (const auto& o : observed.hard) states[o.variable.value()] = o.state.value();
    for (const auto& o : observed.intervened) states[o.variable.value()] = o.state.value();
    return states;
  });
}

/// A most probable joint state of `query` (in that order) given the evidence, every other
/// variable summed out: eliminated in a constrained order, sums first, then maxima. Throws
/// impossible_evidence when the evidence has probability 0.
template <GraphicalModel M>
[[nodiscard]] std::vector<std::size_t> marginal_map(const M& model, std::span<const variable_id> query,
                                                    const evidence_set& observed, const solve_options& options = {},
                                                    solve_report* report = nullptr) {
  solve_report local;
  auto& r = report ? *report : local;
  if (options.engine == solve_engine::bp || options.engine == solve_engine::gibbs) {
    throw model_error(std::string(to_string(options.engine)) + " answers MAR (bp PR too); marginal MAP needs jt or ve");
  }
  detail::check_marginal_map_size(model, query, observed, options, r);
  r.engine = "ve";
  std::vector<variable_id> free;
  for (const auto id : query) {
    if (!observed.fixes(id)) free.push_back(id);
  }
  return detail::in_fitting_semiring<true>(model, r, [&]<Semiring S>() {
    const auto [chosen, value] = maximum_in<S>(model, free, observed, options.heuristic);
    if (value == S::zero()) detail::throw_impossible(model, observed);
    std::vector<std::size_t> states;
    std::size_t k = 0;
    for (const auto id : query) {
      std::size_t state = 0;
      bool fixed = false;
      for (const auto& o : observed.hard) {
        if (o.variable == id) {
          state = o.state.value();
          fixed = true;
        }
      }
      states.push_back(fixed ? state : chosen[k++]);
    }
    return states;
  });
}

}  // namespace pgm
