#pragma once
// The definitions of pgm/eval/experiment.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/eval/experiment.hpp"

namespace pgm::detail {

PGM_DECL std::uint64_t seed_of(std::string_view text) {
  std::uint64_t h = 1469598103934665603ULL;
  for (char c : text) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  return h;
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL prepared_prior prepare_prior(const scenario& s, const task_source& source, std::uint64_t base_seed,
                                      const std::function<void(const std::string&)>& note) {
  const auto facts = source.facts(s.prior_task, s.prior_node);
  const auto family = read_family(source.data(s.prior_task, s.prior_rows, detail::data_seed(base_seed, s.prior_task)),
                                  s.prior_node, facts.parents, s.bins, facts.tags);
  for (const auto& n : family.notes) note("prior: " + n);
  return {family.fit_all(), parse_correspondence(s.map)};
}

PGM_DECL prepared_target prepare_target(const scenario& s, std::size_t index, const task_source& source,
                                        const prepared_prior& prior, std::uint64_t base_seed, bool automatic_lines,
                                        const std::function<void(const std::string&)>& note) {
  const auto& t = s.targets.at(index);
  const auto facts = source.facts(t.task, s.target_node);
  prepared_target target{
      t.task,
      read_family(source.data(t.task, t.train_rows + t.ground_truth_rows, detail::data_seed(base_seed, t.task)),
                  s.target_node, facts.parents, s.bins, facts.tags),
      t.train_rows};
  for (const auto& n : target.family.notes) note(t.task + ": " + n);
  for (const auto& parent : target.family.parents)
    target.controllable.push_back(facts.controllable.contains(parent.name()));
  const auto& child = target.family.child;
  const auto success = facts.success_state.empty() ? std::nullopt : child.find_state(facts.success_state);
  if (!success) {
    throw data_error("task '" + t.task + "': '" + s.target_node + "' has no success state" +
                     (facts.success_state.empty() ? "" : " '" + facts.success_state + "'") +
                     " (its states: " + text::list_for_message(child.states()) + ")");
  }
  target.success_state = success->value();

  const auto structure = target.family.structure();
  for (const auto& strategy : s.strategies) {
    auto priors = transfer_priors(prior.network, structure, prior.map, transfer_registry::instance().at(strategy));
    target.priors.emplace(strategy, std::move(priors.at(s.target_node)));
  }
  const std::string proposed = s.strategies.back() + "+auto-map";
  if (automatic_lines) {
    // The proposed map, with the scenario's last strategy (its best in the paper).
    try {
      correspondence pinned;
      pinned.pinned = prior.map.pinned;
      pinned.transferred = prior.map.transferred;
      const auto proposal =
          propose_correspondence({&structure, nullptr}, {&prior.network.structure(), &prior.network}, pinned);
      note(t.task + ": proposed map " + to_string(proposal) +
           (to_string(proposal) == to_string(prior.map) ? " (the scenario's)" : " (the scenario's: " + s.map + ")"));
      auto priors =
          transfer_priors(prior.network, structure, proposal, transfer_registry::instance().at(s.strategies.back()));
      target.priors.emplace(proposed, std::move(priors.at(s.target_node)));
    } catch (const error& e) {
      note(t.task + ": no line for the proposed map: " + e.what());
    }
  }

  using map_choice = estimator_line::map_choice;
  target.lines.push_back({"mle", map_choice::scenario, std::nullopt, nullptr});
  double smallest_weight = INFINITY;
  for (double w : s.weights) {
    if (w > 0) smallest_weight = std::min(smallest_weight, w);
  }
  // In the order of the priors' names, as before the lines were typed.
  for (const auto& [name, prior_of_line] : target.priors) {
    const auto map = name == proposed ? map_choice::proposed : map_choice::scenario;
    const auto strategy = map == map_choice::proposed ? s.strategies.back() : name;
    for (double w : s.weights) {
      // The proposed map at the smallest weight only, to keep the plots readable.
      if (w == 0 || (map == map_choice::proposed && w != smallest_weight)) continue;
      target.lines.push_back({strategy, map, w, &prior_of_line.table()});
    }
    if (automatic_lines && map == map_choice::scenario) {
      target.lines.push_back({strategy, map, std::nullopt, &prior_of_line.table()});
    }
  }
  return target;
}

PGM_DECL std::vector<std::uint32_t> split_rows(std::size_t rows, std::size_t train_rows, std::uint64_t seed) {
  sim::random_stream random(seed, 0, sim::stream_purpose::split);
  std::vector<std::uint32_t> order(rows);
  std::iota(order.begin(), order.end(), 0U);
  for (std::size_t i = 0; i < train_rows && i < rows; ++i) {
    std::swap(order[i], order[i + random.below(rows - i)]);
  }
  return order;
}

namespace detail {

PGM_DECL move_costs costs_of_target(const prepared_target& target, const move_costs& costs,
                                    const std::function<void(const std::string&)>& note) {
  move_costs kept{.reward = costs.reward, .unit = costs.unit};
  for (const auto& cost : costs.cost) {
    const auto& name = cost.first;  // not a structured binding: the lambda below captures it (clang < 16)
    const auto& parents = target.family.parents;
    const auto p = std::find_if(parents.begin(), parents.end(), [&](const variable& v) { return v.name() == name; });
    if (p != parents.end() && target.controllable[static_cast<std::size_t>(p - parents.begin())] != 0) {
      kept.cost.emplace(cost);
    } else if (note) {
      note(target.task + ": the cost of moving '" + name + "' is left out: it is no controllable parent of '" +
           target.family.child.name() + "'");
    }
  }
  return kept;
}

}  // namespace detail

PGM_DECL std::vector<experiment_point> run_repetition(const scenario& s, const prepared_target& target,
                                                      std::size_t repetition, std::uint64_t base_seed,
                                                      const prevention_options& prevention) {
  std::vector<experiment_point> out;
  const auto& family = target.family;
  const auto order = split_rows(
      family.rows(), target.train_rows,
      detail::mix_seed(detail::mix_seed(base_seed, detail::seed_of(s.name + "/" + target.task)), repetition));
  auto all = family.empty_counts();
  family.add_counts(order, all);
  auto truth_counts = all;
  {
    auto train = family.empty_counts();
    family.add_counts(std::span(order).first(target.train_rows), train);
    for (std::size_t c = 0; c < truth_counts.counts().size(); ++c) truth_counts.counts()[c] -= train.counts()[c];
  }
  const auto truth = estimate_mle(truth_counts);
  std::vector<double> produced(truth.configurations());
  for (std::size_t u = 0; u < produced.size(); ++u) {
    produced[u] = static_cast<double>(truth_counts.total(index_at<config_index>(u)));
  }
  const auto controllable = std::make_unique<bool[]>(target.controllable.size());
  for (std::size_t p = 0; p < target.controllable.size(); ++p) controllable[p] = target.controllable[p] != 0;
  const std::span<const bool> controllable_parents(controllable.get(), target.controllable.size());
  auto emit = [&](const std::string& strategy, const std::string& weight, std::size_t rows, experiment_metric metric,
                  double value) {
    out.push_back({s.name, target.task, strategy, weight, rows, repetition, metric, value});
  };
  const double oracle =
      failure_prevention_rate(truth, truth, target.success_state, controllable_parents, produced, prevention);
  // With move costs, both rules' moves costed and the rule of highest expected utility scored.
  const auto score_by_costs = [&](const std::string& strategy, const std::string& weight, std::size_t rows,
                                  const cpt<double>& estimated) {
    if (!target.costs) return;
    const auto& costs = *target.costs;
    const auto by_epsilon = prevention_targets(estimated, target.success_state, controllable_parents, prevention);
    emit(strategy, weight, rows, experiment_metric::prevention_cost,
         prevention_outcome_of(by_epsilon, truth, target.success_state, controllable_parents, produced, costs).cost);
    std::vector<std::size_t> by_utility;
    for (const auto& move : best_moves(estimated, target.success_state, controllable_parents, costs)) {
      by_utility.push_back(move.target);
    }
    const auto outcome =
        prevention_outcome_of(by_utility, truth, target.success_state, controllable_parents, produced, costs);
    emit(strategy, weight, rows, experiment_metric::utility_prevention, outcome.success);
    emit(strategy, weight, rows, experiment_metric::utility_prevention_cost, outcome.cost);
  };
  auto counts = family.empty_counts();
  std::size_t counted = 0;
  for (std::size_t k = 0; k <= s.subsets; ++k) {
    const std::size_t end = k * target.train_rows / s.subsets;
    family.add_counts(std::span(order).subspan(counted, end - counted), counts);
    counted = end;
    emit("oracle", "0", end, experiment_metric::failure_prevention, oracle);
    score_by_costs("oracle", "0", end, truth);
    for (const auto& line : target.lines) {
      const auto strategy = line.strategy_label();
      const auto weight_label = line.weight_label();
      double w = line.weight.value_or(0.0);
      if (line.prior && !line.weight) {
        w = choose_prior_weight(counts, *line.prior).weight;
        emit(strategy, weight_label, end, experiment_metric::chosen_w, w);
      }
      const auto estimate_k = line.prior ? estimate(counts, weighted_prior{*line.prior, w}) : estimate_mle(counts);
      const auto difference = success_parameter_difference(estimate_k, truth, target.success_state);
      emit(strategy, weight_label, end, experiment_metric::max_difference, difference.max);
      emit(strategy, weight_label, end, experiment_metric::mean_difference, difference.mean);
      emit(
          strategy, weight_label, end, experiment_metric::failure_prevention,
          failure_prevention_rate(estimate_k, truth, target.success_state, controllable_parents, produced, prevention));
      score_by_costs(strategy, weight_label, end, estimate_k);
    }
  }
  return out;
}

PGM_DECL std::vector<experiment_point> run_experiment(const scenario& s, const task_source& source,
                                                      const experiment_options& options) {
  auto& group = options.across_processes ? processes() : lone_process();
  const std::size_t repetitions = options.repetitions ? options.repetitions : s.repetitions;
  if (repetitions > max_repetitions) {
    throw data_error(std::to_string(repetitions) + " repetitions are more than " + std::to_string(max_repetitions) +
                     ", pgm's limit (every point is kept until the tables are written; docs/limits.md)");
  }
  const std::size_t total = s.targets.size() * repetitions;
  const auto share = detail::process_share{group.rank(), group.size()}.of(total);
  // Over several processes a target's notes wait for the gather, to come out in target order
  // on process 0 (slot 0: the prior's; t + 1: target t's).
  std::vector<std::vector<std::string>> held(s.targets.size() + 1);
  std::size_t noting = 0;
  const std::function<void(const std::string&)> note = [&](const std::string& text) {
    if (group.size() > 1 && noting > 0) {
      held[noting].push_back(s.name + ": " + text);
    } else if (options.note) {
      options.note(s.name + ": " + text);
    }
  };
  auto prevention = options.prevention;
  prevention.epsilon = s.epsilon;
  const auto base_seed = detail::mix_seed(options.seed, 0);

  // Preparation, agreed on by all processes before any job runs: a failure is that of the first
  // job of the first target that fails (the prior's counts as job 0), as on one process.
  std::vector<std::optional<prepared_target>> targets(s.targets.size());
  std::exception_ptr failure;
  std::size_t failed_job = 0;
  try {
    if (share.empty() && group.rank() != 0) throw detail::nothing_to_prepare{};
    const auto prior = prepare_prior(s, source, base_seed, note);
    // Only the targets of this process's jobs.
    const std::size_t first_target = share.empty() ? 0 : share.begin / repetitions;
    const std::size_t end_target = share.empty() ? 0 : (share.end - 1) / repetitions + 1;
    for (std::size_t index = first_target; index < end_target; ++index) {
      failed_job = index * repetitions;
      noting = index + 1;
      targets[index].emplace(prepare_target(s, index, source, prior, base_seed, options.automatic_lines, note));
      if (options.costs) targets[index]->costs = detail::costs_of_target(*targets[index], *options.costs, note);
    }
  } catch (const detail::nothing_to_prepare&) {
  } catch (...) {
    failure = std::current_exception();
  }
  noting = 0;
  agree(group, failure, failed_job);

  // One task per (target, repetition); results land in their own slot, so order is fixed.
  std::vector<std::vector<experiment_point>> results(total);
  detail::parallel_options parallel{.threads = options.threads};
  if (options.progress) {
    // This process's block stands for the whole.
    parallel.progress = [&](std::size_t done) {
      options.progress(done == share.size() ? total : done * total / share.size(), total);
    };
  }
  detail::parallel_for_on(group, total, parallel, [&](detail::item_range jobs) {
    for (std::size_t job = jobs.begin; job < jobs.end; ++job) {
      results[job] = run_repetition(s, *targets[job / repetitions], job % repetitions, base_seed, prevention);
    }
  });
  // The first job of a target carries the target's notes to process 0.
  detail::gather_slots(
      group, total,
      [&](detail::byte_writer& out, std::size_t job) {
        const auto& notes = held[job / repetitions + 1];
        out.put<std::uint64_t>(job % repetitions == 0 ? notes.size() : 0);
        if (job % repetitions == 0) {
          for (const auto& n : notes) out.put(n);
        }
        out.put<std::uint64_t>(results[job].size());
        for (const auto& p : results[job]) {
          for (const auto* text : {&p.scenario, &p.target, &p.strategy, &p.weight}) out.put(*text);
          out.put<std::uint64_t>(p.rows);
          out.put<std::uint64_t>(p.repetition);
          out.put<std::uint8_t>(static_cast<std::uint8_t>(p.metric));
          out.put(p.value);
        }
      },
      [&](detail::byte_reader& in, std::size_t job) {
        auto& notes = held[job / repetitions + 1];
        for (auto n = in.get<std::uint64_t>(); n > 0; --n) notes.push_back(in.get_string());
        auto& out = results[job];
        out.resize(in.get<std::uint64_t>());
        for (auto& p : out) {
          for (auto* text : {&p.scenario, &p.target, &p.strategy, &p.weight}) *text = in.get_string();
          p.rows = in.get<std::uint64_t>();
          p.repetition = in.get<std::uint64_t>();
          p.metric = static_cast<experiment_metric>(in.get<std::uint8_t>());
          p.value = in.get<double>();
        }
      });
  std::vector<experiment_point> points;
  if (group.rank() != 0) return points;
  if (group.size() > 1 && options.note) {
    for (std::size_t slot = 1; slot < held.size(); ++slot) {
      for (const auto& text : held[slot]) options.note(text);
    }
  }
  for (auto& r : results)
    points.insert(points.end(), std::make_move_iterator(r.begin()), std::make_move_iterator(r.end()));
  return points;
}

PGM_DECL std::vector<aggregated_point> aggregate(const std::vector<experiment_point>& points) {
  struct accumulator {
    std::size_t first_seen;
    double sum = 0, sum_squares = 0;
    std::size_t n = 0;
  };
  using key = std::tuple<std::string, std::string, std::string, std::string, std::size_t, experiment_metric>;
  std::map<key, accumulator> groups;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    auto [it, fresh] =
        groups.try_emplace(key{p.scenario, p.target, p.strategy, p.weight, p.rows, p.metric}, accumulator{i});
    it->second.sum += p.value;
    it->second.sum_squares += p.value * p.value;
    ++it->second.n;
  }
  std::vector<std::pair<std::size_t, aggregated_point>> ordered;
  for (const auto& [k, a] : groups) {
    const double mean = a.sum / static_cast<double>(a.n);
    const double variance =
        a.n > 1 ? std::max(0.0, (a.sum_squares - static_cast<double>(a.n) * mean * mean) / static_cast<double>(a.n - 1))
                : 0.0;
    ordered.push_back({a.first_seen,
                       {std::get<0>(k), std::get<1>(k), std::get<2>(k), std::get<3>(k), std::get<4>(k), std::get<5>(k),
                        mean, std::sqrt(variance), a.n}});
  }
  std::sort(ordered.begin(), ordered.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<aggregated_point> result;
  for (auto& [i, p] : ordered) result.push_back(std::move(p));
  return result;
}

}  // namespace pgm
