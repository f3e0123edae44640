#pragma once
// The definitions of pgm/decide/prevent_over_time.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <cmath>

#include "pgm/core/error.hpp"
#include "pgm/core/mixed_radix.hpp"
#include "pgm/decide/prevent_over_time.hpp"
#include "pgm/inference/junction_tree_engine.hpp"

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

  junction_tree_engine<bayesian_network> engine(unrolled);
  // P(success at steps k … T−1 | episode, do(setting)), as a ratio of evidence probabilities.
  const auto success_given = [&](const std::vector<observation>& setting) {
    evidence_set given = episode;
    given.intervened = setting;
    engine.set_evidence(given);
    const auto log_episode = engine.log_probability_of_evidence();
    if (!std::isfinite(log_episode)) {
      throw impossible_evidence("the episode has probability 0 in the model" +
                                std::string(setting.empty() ? "" : " under this setting"));
    }
    for (std::size_t t = answer.step; t < answer.horizon; ++t) given.hard.push_back({at(success_id, t), success_state});
    engine.set_evidence(std::move(given));
    return std::exp(engine.log_probability_of_evidence() - log_episode);
  };
  const auto setting_of = [&](const std::vector<std::size_t>& states) {
    std::vector<observation> setting;
    for (std::size_t i = 0; i < states.size(); ++i) {
      setting.push_back(
          {at(request.controllable[i], answer.step), state_index(static_cast<state_index::rep>(states[i]))});
    }
    return setting;
  };
  answer.before = success_given(answer.planned ? setting_of(plan) : std::vector<observation>{});
  std::vector<std::size_t> best = plan;
  double best_value = answer.planned ? answer.before : -1.0;
  for (std::size_t c = 0; c < radix.size(); ++c) {
    const auto states = radix.decode(c);
    const auto value = success_given(setting_of(states));
    if (value > best_value + 1e-12 * std::abs(best_value)) {
      best_value = value;
      best = states;
    }
  }
  answer.after = best_value;
  for (std::size_t i = 0; i < best.size(); ++i) {
    const auto& v = templates[request.controllable[i].value()];
    answer.best.emplace_back(v.name(), v.states()[best[i]]);
  }
  return answer;
}

}  // namespace pgm
