#pragma once
// The definitions of pgm/learn/dynamic_em.hpp: inline in a header-only build, compiled once into
// libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <span>
#include <utility>

#include "pgm/core/text.hpp"
#include "pgm/data/episodes.hpp"
#include "pgm/detail/parallel_for.hpp"
#include "pgm/inference/junction_tree_engine.hpp"
#include "pgm/inference/sampling.hpp"
#include "pgm/learn/dynamic_em.hpp"
#include "pgm/learn/estimate.hpp"

namespace pgm {

PGM_DECL std::string summary_of(const dynamic_em_result& em) {
  return "EM: " + std::to_string(em.iterations) + " iterations" +
         (em.converged ? " (converged)" : " (stopped at the iteration limit)") + ", log-likelihood " +
         text::format_double(em.log_likelihood) + ", " + std::to_string(em.patterns) + " distinct episodes (" +
         std::to_string(em.incomplete_patterns) + " with a missing value)" +
         (em.restart > 0 ? ", from start " + std::to_string(em.restart + 1) : "");
}

namespace detail {

/// EM over episodes: see pgm/learn/dynamic_em.hpp.
class dynamic_em_runner {
  static constexpr std::uint32_t absent = std::numeric_limits<std::uint32_t>::max();

  /// A table's family as template variables: the child first, then the parents in the table's
  /// order, each read `back` steps before the child's (0 or 1).
  struct member {
    std::size_t index = 0;
    std::size_t back = 0;
  };

  /// Episodes of one length with the same observed values: codes[t·n + i] is template variable
  /// i at step t (`absent` where missing or latent).
  struct pattern {
    std::size_t length = 0;
    std::vector<std::uint32_t> codes;
    double episodes = 0.0;
  };

  /// The tables of one slice kind: the first slice's (t = 0) or the transition's (t ≥ 1).
  struct slice_tables {
    std::vector<std::vector<member>> families;
    std::vector<std::vector<double>> alpha;
    std::vector<bool> latent;
    std::vector<expected_count_table> fixed;
  };

  struct expectation {
    std::vector<expected_count_table> initial, transition;
    double log_likelihood = 0.0;
  };

  /// A network unrolled over one length, compiled, and where each template variable of each
  /// step is in it.
  struct unrolled {
    junction_tree_engine<> engine;
    std::vector<variable_id> ids;  // [t·n + i]
  };

 public:
  dynamic_em_runner(const dynamic_structure& structure, const dataset& data, const dynamic_fit_options& options,
                    const dynamic_em_options& em)
      : structure_(&structure), options_(&options), em_(&em), n_(structure.variables().size()) {
    const auto episodes = index_episodes(data, options.columns);
    episodes_ = episodes.episodes();
    steps_ = data.rows();
    read_patterns(data, episodes);
    describe_tables();
    for (std::size_t p = 0; p < patterns_.size(); ++p) {
      bool complete = true;
      for (std::size_t t = 0; t < patterns_[p].length; ++t) {
        for (std::size_t i = 0; i < n_; ++i) {
          auto& tables = t == 0 ? initial_ : transition_;
          if (family_observed(p, t, tables.families[i])) {
            tables.fixed[i].counts()[cell_of(tables.fixed[i], p, t, tables.families[i])] += patterns_[p].episodes;
          } else {
            complete = false;
          }
        }
      }
      if (!complete) incomplete_.push_back(p);
    }
    has_latent_ = std::any_of(latent_.begin(), latent_.end(), [](bool b) { return b; });
  }

  [[nodiscard]] dynamic_em_result run() const {
    dynamic_em_result best;
    bool have_best = false;
    const std::size_t starts = has_latent_ && !em_->start ? std::max<std::size_t>(1, em_->em.restarts) : 1;
    for (std::size_t restart = 0; restart < starts; ++restart) {
      auto result = run_from(start(restart), restart);
      if (!have_best || result.objective > best.objective) {
        best = std::move(result);
        have_best = true;
      }
    }
    best.episodes = episodes_;
    best.steps = steps_;
    best.patterns = patterns_.size();
    best.incomplete_patterns = incomplete_.size();
    return best;
  }

 private:
  void read_patterns(const dataset& data, const episode_index& episodes) {
    std::vector<const discrete_column*> columns(n_, nullptr);
    latent_.assign(n_, false);
    for (std::size_t i = 0; i < n_; ++i) {
      const auto& v = structure_->variables()[i];
      if (!data.contains(v.name())) {
        latent_[i] = true;
        continue;
      }
      const auto& column = data.discrete(v.name());
      if (column.var().states() != v.states()) {
        throw data_error(data.source() + ": column '" + v.name() + "' has the states {" +
                         text::list_for_message(column.var().states()) + "} but the model expects {" +
                         text::list_for_message(v.states()) + "}");
      }
      columns[i] = &column;
    }
    std::map<std::vector<std::uint32_t>, std::size_t> seen;
    for (std::size_t k = 0; k < episodes.episodes(); ++k) {
      const auto length = episodes.length(k);
      std::vector<std::uint32_t> codes(length * n_, absent);
      for (std::size_t t = 0; t < length; ++t) {
        const auto row = episodes.row(episodes.starts[k] + t);
        for (std::size_t i = 0; i < n_; ++i) {
          if (columns[i] && !columns[i]->is_missing(row)) codes[t * n_ + i] = columns[i]->code(row);
        }
      }
      const auto [at, inserted] = seen.emplace(std::move(codes), patterns_.size());
      if (inserted) patterns_.push_back({length, at->first, 0.0});
      patterns_[at->second].episodes += 1.0;
    }
  }

  void describe_tables() {
    const auto& templates = structure_->variables();
    for (std::size_t i = 0; i < n_; ++i) {
      const variable_id first = index_at<variable_id>(i);
      const variable_id now = index_at<variable_id>(n_ + i);
      std::vector<member> initial{{i, 0}};
      for (const auto parent : structure_->initial.parents(first)) initial.push_back({parent.value(), 0});
      std::vector<member> transition{{i, 0}};
      for (const auto parent : structure_->transition.parents(now)) {
        // The two-slice network's first n variables are the previous slice's.
        transition.push_back(parent.value() < n_ ? member{parent.value(), 1} : member{parent.value() - n_, 0});
      }
      add_table(initial_, std::move(initial), structure_->initial.at(first),
                structure_->initial.parent_variables(first), prior_of(options_->initial_priors, templates[i].name()));
      add_table(transition_, std::move(transition), structure_->transition.at(now),
                structure_->transition.parent_variables(now), prior_of(options_->fit.node_priors, templates[i].name()));
    }
  }

  [[nodiscard]] const parameter_prior& prior_of(const std::map<std::string, parameter_prior, std::less<>>& own,
                                                const std::string& name) const {
    const auto found = own.find(name);
    return found != own.end() ? found->second : options_->fit.prior;
  }

  void add_table(slice_tables& tables, std::vector<member> family, const variable& child,
                 const std::vector<variable>& parents, const parameter_prior& prior) const {
    std::size_t cells = child.cardinality();
    for (const auto& parent : parents) cells = saturating_multiply(cells, parent.cardinality());
    if (cells > max_table_cells) {
      throw table_too_large("EM holds every table dense, and the table of '" + child.name() + "' with " +
                            std::to_string(parents.size()) + " parents has more than " +
                            std::to_string(max_table_cells) +
                            " cells, pgm's limit (docs/limits.md): fit it without --missing em, or with fewer parents");
    }
    tables.latent.push_back(
        std::any_of(family.begin(), family.end(), [&](const member& m) { return latent_[m.index]; }));
    tables.families.push_back(std::move(family));
    tables.alpha.push_back(pseudo_counts_of(prior, child, parents));
    tables.fixed.emplace_back(child, parents);
  }

  [[nodiscard]] bool family_observed(std::size_t p, std::size_t t, const std::vector<member>& family) const {
    return std::all_of(family.begin(), family.end(),
                       [&](const member& m) { return patterns_[p].codes[(t - m.back) * n_ + m.index] != absent; });
  }

  [[nodiscard]] std::size_t cell_of(const expected_count_table& table, std::size_t p, std::size_t t,
                                    const std::vector<member>& family) const {
    std::vector<std::size_t> values;
    for (const auto& m : family) values.push_back(patterns_[p].codes[(t - m.back) * n_ + m.index]);
    return detail::cell_of(table, values);
  }

  /// The estimation options with dense tables: the E-step reads every value of each table.
  [[nodiscard]] estimate_options dense_estimation() const {
    auto options = options_->fit.estimation;
    options.sparse = false;
    return options;
  }

  [[nodiscard]] dynamic_network maximize(const std::vector<expected_count_table>& initial,
                                         const std::vector<expected_count_table>& transition) const {
    const auto& templates = structure_->variables();
    std::vector<cpt<double>> first, later;
    for (std::size_t i = 0; i < n_; ++i) {
      first.push_back(
          estimate(initial[i], prior_of(options_->initial_priors, templates[i].name()), dense_estimation()));
      later.push_back(
          estimate(transition[i], prior_of(options_->fit.node_priors, templates[i].name()), dense_estimation()));
    }
    return {bayesian_network(structure_->initial, std::move(first)), std::move(later)};
  }

  /// The available-case estimate with one pseudo-count more per cell, random tables for the
  /// families of latent variables.
  [[nodiscard]] dynamic_network start(std::size_t restart) const {
    if (em_->start) return *em_->start;
    std::mt19937_64 random(em_->em.seed ^ (0x9E3779B97F4A7C15ULL * (restart + 1)));
    const auto smoothed = [&](const slice_tables& tables) {
      std::vector<cpt<double>> out;
      for (std::size_t i = 0; i < n_; ++i) {
        auto alpha = tables.alpha[i];
        for (auto& a : alpha) a += 1.0;
        auto table = estimate(tables.fixed[i], pseudo_counts_prior{std::move(alpha)}, dense_estimation());
        if (tables.latent[i]) table = randomized(table, random);
        out.push_back(std::move(table));
      }
      return out;
    };
    auto first = smoothed(initial_);
    auto later = smoothed(transition_);
    return {bayesian_network(structure_->initial, std::move(first)), std::move(later)};
  }

  /// Each column 0.5 + U[0, 1), normalized.
  [[nodiscard]] static cpt<double> randomized(const cpt<double>& table, std::mt19937_64& random) {
    std::vector<double> values(table.values().begin(), table.values().end());
    const auto j = table.child_cardinality();
    for (std::size_t u = 0; u < table.configurations(); ++u) {
      double sum = 0.0;
      for (std::size_t x = 0; x < j; ++x) sum += values[u * j + x] = 0.5 + uniform01(random);
      for (std::size_t x = 0; x < j; ++x) values[u * j + x] /= sum;
    }
    return {table.child(), table.parents(), std::move(values)};
  }

  [[nodiscard]] dynamic_em_result run_from(dynamic_network model, std::size_t restart) const {
    dynamic_em_result result;
    result.restart = restart;
    double previous = 0.0;
    for (std::size_t iteration = 0;; ++iteration) {
      auto expected = expect(model);
      const double objective = expected.log_likelihood + prior_term(model);
      if (em_->em.on_step) em_->em.on_step({restart, iteration, expected.log_likelihood, objective});
      result.iterations = iteration;
      result.log_likelihood = expected.log_likelihood;
      result.objective = objective;
      result.initial = std::move(expected.initial);
      result.transition = std::move(expected.transition);
      if (iteration > 0 && std::abs(objective - previous) <= em_->em.tolerance * std::abs(previous)) {
        result.converged = true;
        break;
      }
      if (iteration == em_->em.max_iterations) break;
      previous = objective;
      model = maximize(result.initial, result.transition);
    }
    result.model = std::move(model);
    return result;
  }

  /// Σ α ln θ over every cell of both slices' tables with α > 0.
  [[nodiscard]] double prior_term(const dynamic_network& model) const {
    double sum = 0.0;
    const auto add = [&](const cpt<double>& table, const std::vector<double>& alpha) {
      const auto values = table.values();
      for (std::size_t c = 0; c < alpha.size(); ++c) {
        if (alpha[c] > 0.0) sum += alpha[c] * std::log(values[c]);
      }
    };
    for (std::size_t i = 0; i < n_; ++i) {
      add(model.initial().tables()[i], initial_.alpha[i]);
      add(model.transition_tables()[i], transition_.alpha[i]);
    }
    return sum;
  }

  [[nodiscard]] const cpt<double>& table_of(const dynamic_network& model, std::size_t t, std::size_t i) const {
    return t == 0 ? model.initial().tables()[i] : model.transition_tables()[i];
  }

  /// The E-step under `model`: the fixed counts plus each incomplete pattern's expected counts.
  [[nodiscard]] expectation expect(const dynamic_network& model) const {
    std::map<std::size_t, unrolled> networks;
    for (const auto p : incomplete_) {
      const auto length = patterns_[p].length;
      if (networks.contains(length)) continue;
      auto network = model.unroll(length);
      std::vector<variable_id> ids;
      for (std::size_t t = 0; t < length; ++t) {
        for (const auto& v : model.variables()) ids.push_back(network.id(slice_name(v.name(), static_cast<long>(t))));
      }
      // Every family of an episode is asked under one evidence: propagating once serves them
      // all, so the engine does not weigh eliminating each instead.
      networks.emplace(
          length,
          unrolled{junction_tree_engine<>(std::move(network), junction_tree_options{.prune = false}), std::move(ids)});
    }
    const std::size_t blocks = std::min<std::size_t>(64, (incomplete_.size() + 7) / 8);
    std::vector<expectation> sums(blocks);
    parallel_options parallel;
    parallel.threads = em_->em.threads;
    parallel.min_items_per_thread = 1;
    parallel_for(blocks, parallel, [&](item_range range) {
      for (std::size_t b = range.begin; b < range.end; ++b) {
        sums[b].initial = empty_like(initial_.fixed);
        sums[b].transition = empty_like(transition_.fixed);
        // Each block from fresh engines, so that its sums do not depend on which thread ran
        // which blocks before it (pgm/inference/junction_tree_engine.hpp, fresh()).
        std::map<std::size_t, junction_tree_engine<>> engines;
        const std::size_t begin = incomplete_.size() * b / blocks;
        const std::size_t end = incomplete_.size() * (b + 1) / blocks;
        for (std::size_t k = begin; k < end; ++k) {
          const auto p = incomplete_[k];
          const auto& net = networks.at(patterns_[p].length);
          auto engine = engines.find(patterns_[p].length);
          if (engine == engines.end()) engine = engines.emplace(patterns_[p].length, net.engine.fresh()).first;
          add_pattern(engine->second, net, p, sums[b]);
        }
      }
    });
    expectation total{initial_.fixed, transition_.fixed, complete_log_likelihood(model)};
    for (const auto& block : sums) {
      add_counts(total.initial, block.initial);
      add_counts(total.transition, block.transition);
      total.log_likelihood += block.log_likelihood;
    }
    return total;
  }

  [[nodiscard]] static std::vector<expected_count_table> empty_like(const std::vector<expected_count_table>& tables) {
    std::vector<expected_count_table> out;
    for (const auto& table : tables) out.emplace_back(table.child(), table.parents());
    return out;
  }

  /// ln P of the patterns without a missing value, straight from the tables.
  [[nodiscard]] double complete_log_likelihood(const dynamic_network& model) const {
    double sum = 0.0;
    std::size_t next_incomplete = 0;
    for (std::size_t p = 0; p < patterns_.size(); ++p) {
      if (next_incomplete < incomplete_.size() && incomplete_[next_incomplete] == p) {
        ++next_incomplete;
        continue;
      }
      double log_p = 0.0;
      for (std::size_t t = 0; t < patterns_[p].length; ++t) {
        const auto& tables = t == 0 ? initial_ : transition_;
        for (std::size_t i = 0; i < n_; ++i) {
          log_p += std::log(table_of(model, t, i).values()[cell_of(tables.fixed[i], p, t, tables.families[i])]);
        }
      }
      sum += patterns_[p].episodes * log_p;
    }
    return sum;
  }

  void add_pattern(junction_tree_engine<>& engine, const unrolled& net, std::size_t p, expectation& into) const {
    const auto& codes = patterns_[p].codes;
    const double episodes = patterns_[p].episodes;
    evidence_set observed;
    for (std::size_t k = 0; k < codes.size(); ++k) {
      if (codes[k] != absent) observed.hard.push_back({net.ids[k], state_index(codes[k])});
    }
    engine.set_evidence(std::move(observed));
    const double log_evidence = engine.log_probability_of_evidence();
    if (!std::isfinite(log_evidence)) {
      throw data_error(
          "EM: an episode of the data has probability 0 under the current tables (a value or a step the tables rule "
          "out)");
    }
    into.log_likelihood += episodes * log_evidence;
    // Every incomplete family of every step: its missing members' joint, all in one pass.
    std::vector<std::pair<std::size_t, std::size_t>> asked;  // (t, i)
    std::vector<std::vector<variable_id>> scopes;
    for (std::size_t t = 0; t < patterns_[p].length; ++t) {
      const auto& tables = t == 0 ? initial_ : transition_;
      for (std::size_t i = 0; i < n_; ++i) {
        if (family_observed(p, t, tables.families[i])) continue;
        asked.emplace_back(t, i);
        auto& hidden = scopes.emplace_back();
        for (const auto& m : tables.families[i]) {
          const auto at = (t - m.back) * n_ + m.index;
          if (codes[at] == absent) hidden.push_back(net.ids[at]);
        }
      }
    }
    const auto joints = engine.joints(scopes);
    for (std::size_t k = 0; k < asked.size(); ++k) {
      const auto [t, i] = asked[k];
      const auto& tables = t == 0 ? initial_ : transition_;
      add_family(p, t, tables.families[i], joints[k], (t == 0 ? into.initial : into.transition)[i]);
    }
  }

  /// P(the family's missing members at step t | the episode), spread over its cells.
  void add_family(std::size_t p, std::size_t t, const std::vector<member>& family,
                  const std::vector<double>& probabilities, expected_count_table& into) const {
    const auto& codes = patterns_[p].codes;
    std::vector<std::size_t> member_values, hidden_slots, cardinalities;
    for (std::size_t k = 0; k < family.size(); ++k) {
      const auto at = (t - family[k].back) * n_ + family[k].index;
      member_values.push_back(codes[at] == absent ? 0 : codes[at]);
      if (codes[at] == absent) {
        hidden_slots.push_back(k);
        cardinalities.push_back(structure_->variables()[family[k].index].cardinality());
      }
    }
    auto cells = into.counts();
    for (std::size_t index = 0; index < probabilities.size(); ++index) {
      std::size_t rest = index;
      for (std::size_t h = hidden_slots.size(); h-- > 0;) {
        member_values[hidden_slots[h]] = rest % cardinalities[h];
        rest /= cardinalities[h];
      }
      cells[detail::cell_of(into, member_values)] += patterns_[p].episodes * probabilities[index];
    }
  }

  const dynamic_structure* structure_;
  const dynamic_fit_options* options_;
  const dynamic_em_options* em_;
  std::size_t n_;
  std::size_t episodes_ = 0;
  std::size_t steps_ = 0;
  /// Template variables in no column.
  std::vector<bool> latent_;
  std::vector<pattern> patterns_;
  slice_tables initial_, transition_;
  bool has_latent_ = false;
  /// The patterns with a missing value, in order.
  std::vector<std::size_t> incomplete_;
};

}  // namespace detail

PGM_DECL dynamic_em_result dynamic_expectation_maximization(const dynamic_structure& structure, const dataset& data,
                                                            const dynamic_fit_options& options,
                                                            const dynamic_em_options& em) {
  if (em.em.kind == em_kind::hard) throw model_error("hard EM is not available for dynamic networks; soft EM is");
  if (!std::isfinite(em.em.tolerance) || em.em.tolerance < 0.0) {
    throw model_error("the EM tolerance must be a finite number >= 0, got " + text::format_double(em.em.tolerance));
  }
  for (const auto* priors : {&options.fit.node_priors, &options.initial_priors}) {
    for (const auto& [name, prior] : *priors) {
      if (!structure.initial.contains(name)) {
        throw model_error("a prior is given for '" + name + "', which is not a template variable of the network");
      }
    }
  }
  if (data.rows() == 0) throw data_error(data.source() + ": there are no data rows to fit a dynamic network from");
  if (em.start && structure_of(*em.start) != structure) {
    throw model_error("the dynamic network EM is to start from has another structure than the one fitted");
  }
  return detail::dynamic_em_runner(structure, data, options, em).run();
}

}  // namespace pgm
