#pragma once
// The definitions of pgm/decide/prevent_over_time.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <cmath>

#include "pgm/core/error.hpp"
#include "pgm/core/mixed_radix.hpp"
#include "pgm/decide/prevent_over_time.hpp"
#include "pgm/inference/junction_tree_engine.hpp"
#include "pgm/inference/variable_elimination.hpp"

namespace pgm {

PGM_DECL prevention_over_time prevent_over_time(const dynamic_network& model,
                                                const prevention_over_time_request& request) {
  const auto& templates = model.variables();
  const auto success_id = model.initial().id(request.success.variable);
  const auto success_state = templates[success_id.value()].state(request.success.state);
  if (request.controllable.empty()) throw model_error("no controllable variable is named");
  for (const auto c : request.controllable) {
    if (c == success_id) {
      throw model_error("the success variable '" + request.success.variable +
                        "' is controllable; it is what is predicted");
    }
  }
  prevention_over_time answer;
  const auto observed_success = [&](const evidence_set& step) {
    return std::any_of(step.hard.begin(), step.hard.end(),
                       [&](const observation& o) { return o.variable == success_id; });
  };
  while (answer.step < request.steps.size() && observed_success(request.steps[answer.step])) ++answer.step;
  if (request.steps.size() > answer.step + 1) {
    throw model_error("the episode has steps past step " + std::to_string(answer.step) + ", the first whose '" +
                      request.success.variable + "' is not observed and so the step decided");
  }
  if (request.horizon != 0 && request.horizon <= answer.step) {
    throw model_error("the horizon of " + std::to_string(request.horizon) + " steps ends before step " +
                      std::to_string(answer.step) + ", the step decided");
  }
  answer.horizon = std::max(request.horizon, answer.step + 1);
  const auto unrolled = model.unroll(answer.horizon);
  const auto at = [&](variable_id v, std::size_t t) {
    return unrolled.id(templates[v.value()].name() + "@" + std::to_string(t));
  };

  // The episode as evidence on the unrolled network; the plan set apart.
  evidence_set episode;
  std::vector<std::size_t> plan(request.controllable.size(), 0);
  std::size_t planned = 0;
  for (std::size_t t = 0; t < request.steps.size(); ++t) {
    if (!request.steps[t].soft.empty() || !request.steps[t].intervened.empty()) {
      throw model_error("step " + std::to_string(t) + " of the episode holds soft evidence or an intervention");
    }
    for (const auto& o : request.steps[t].hard) {
      const auto c = std::find(request.controllable.begin(), request.controllable.end(), o.variable);
      if (t == answer.step && c != request.controllable.end()) {
        plan[static_cast<std::size_t>(c - request.controllable.begin())] = o.state.value();
        ++planned;
      } else {
        episode.hard.push_back({at(o.variable, t), o.state});
      }
    }
  }
  answer.planned = planned == request.controllable.size();
  if (planned != 0 && !answer.planned) {
    throw model_error("step " + std::to_string(answer.step) +
                      " gives states for some controllable variables but not all: give the whole plan or none");
  }
  std::vector<std::size_t> cards;
  for (const auto c : request.controllable) cards.push_back(templates[c.value()].cardinality());
  const mixed_radix radix(cards);
  if (radix.size() > max_prevention_candidates) {
    throw model_error("the controllable variables have " + std::to_string(radix.size()) +
                      " configurations, more than the " + std::to_string(max_prevention_candidates) + " tried");
  }

  // The controllable variables at step k cut from their parents, their tables uniform: there
  // P(S, e, C = c) = P(S, e | do(C = c)) / |C| for every setting c at once, so two propagations
  // (with and without the success steps S) judge them all.
  std::vector<variable_id> decided;
  for (const auto c : request.controllable) decided.push_back(at(c, answer.step));
  auto structure = unrolled.structure();
  auto tables = unrolled.tables();
  for (const auto id : decided) {
    for (const auto parent : unrolled.graph().parents(id)) {
      structure.remove_edge(unrolled.variables()[parent.value()].name(), unrolled.variables()[id.value()].name());
    }
    const auto& v = unrolled.variables()[id.value()];
    tables[id.value()] =
        cpt<double>(v, {}, std::vector<double>(v.cardinality(), 1.0 / static_cast<double>(v.cardinality())));
  }
  junction_tree_engine<bayesian_network> engine(bayesian_network(std::move(structure), std::move(tables)));
  evidence_set with_success = episode;
  for (std::size_t t = answer.step; t < answer.horizon; ++t)
    with_success.hard.push_back({at(success_id, t), success_state});
  const auto joint_of = [&](const evidence_set& given) {
    engine.set_evidence(given);
    try {
      return engine.joint(decided);
    } catch (const impossible_evidence&) {
      if (&given == &episode) throw impossible_evidence("the episode has probability 0 in the model");
      return posterior{};  // no setting makes every step succeed
    }
  };
  const auto seen = joint_of(episode);
  const auto succeeded = joint_of(with_success);
  // P(S | e, do(c)) = P(S, e, c) / P(e, c) in the cut network; a setting with P(e, c) = 0 is never chosen.
  const auto success_given = [&](const std::vector<std::size_t>& states) {
    const double base = seen.table.at(states);
    if (base <= 0.0 || succeeded.table.size() == 0) return 0.0;
    return succeeded.table.at(states) / base *
           std::exp(succeeded.log_evidence_probability - seen.log_evidence_probability);
  };
  // The answer's two numbers by variable elimination on the network as it is, the chosen
  // setting as an intervention: as exact as one propagation gives them.
  variable_elimination<bayesian_network> plain(unrolled);
  const auto directly = [&](const std::vector<std::size_t>* setting) {
    evidence_set given = episode;
    if (setting != nullptr) {
      for (std::size_t i = 0; i < decided.size(); ++i) {
        given.intervened.push_back({decided[i], index_at<state_index>((*setting)[i])});
      }
    }
    plain.set_evidence(given);
    const double log_episode = plain.log_probability_of_evidence();
    if (!std::isfinite(log_episode)) return 0.0;  // the setting rules the episode out
    given.hard = with_success.hard;
    plain.set_evidence(std::move(given));
    return std::exp(plain.log_probability_of_evidence() - log_episode);
  };
  answer.before = directly(answer.planned ? &plan : nullptr);
  std::vector<std::size_t> best = plan;
  double best_value = answer.planned ? success_given(plan) : -1.0;
  for (std::size_t c = 0; c < radix.size(); ++c) {
    const auto states = radix.decode(c);
    const auto value = success_given(states);
    if (value > best_value + 1e-12 * std::abs(best_value)) {
      best_value = value;
      best = states;
    }
  }
  answer.after = directly(&best);
  for (std::size_t i = 0; i < best.size(); ++i) {
    const auto& v = templates[request.controllable[i].value()];
    answer.best.emplace_back(v.name(), v.states()[best[i]]);
  }
  return answer;
}

}  // namespace pgm
