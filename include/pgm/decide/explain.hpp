#pragma once
/// \file
/// Explanation of a predicted failure: the controllable variables responsible are those the
/// prevention target moves, and the explanation is that smallest change, per variable, from
/// state (interval) to state, with the move in the variable's units where it has intervals.
/// `plan_prevention` does the whole chain for a network and a planned assignment.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"
#include "pgm/decide/assignment.hpp"
#include "pgm/decide/predict.hpp"
#include "pgm/decide/prevent.hpp"
#include "pgm/decide/success_table.hpp"

namespace pgm {

/// A closed-open interval [lower, upper) of a discretized variable, in its units.
struct interval {
  double lower;
  double upper;
  [[nodiscard]] double midpoint() const noexcept { return 0.5 * (lower + upper); }
  friend bool operator==(const interval&, const interval&) = default;
};

/// One controllable variable in an explanation: where it is and where prevention puts it.
struct variable_change {
  std::string variable;
  std::string unit;  ///< from the variable's semantic tags, may be empty
  std::size_t from_state;
  std::size_t to_state;
  std::string from_label;
  std::string to_label;
  std::optional<interval> from_interval;  ///< for interval variables
  std::optional<interval> to_interval;
  /// Difference of the midpoints (to − from) in the variable's units, where it has any.
  std::optional<double> move;
  [[nodiscard]] bool moves() const noexcept { return from_state != to_state; }
};

struct explanation {
  std::string success_variable;
  std::string success_state;
  double epsilon = 0.8;
  std::size_t configuration = 0;         ///< u, in the success table's numbering
  std::size_t target = 0;                ///< u*
  double predicted = 0.0;                ///< estimated P(success | u)
  double target_predicted = 0.0;         ///< estimated P(success | u*)
  std::size_t steps = 0;                 ///< bin steps from u to u*
  std::optional<double> distance_units;  ///< Euclidean midpoint distance, when all moved variables have midpoints
  /// Every controllable parent, in table order; those that move are the responsible ones.
  std::vector<variable_change> changes;

  [[nodiscard]] bool failure_predicted() const noexcept { return predicted < epsilon; }
  /// Whether the target is predicted to succeed (> ε); if not, it is only the best there is.
  [[nodiscard]] bool target_succeeds() const noexcept { return target_predicted > epsilon; }
  [[nodiscard]] PGM_DECL std::vector<variable_change> responsible() const;
};

namespace detail {

inline std::optional<interval> interval_of(const variable& v, std::size_t state) {
  if (!v.has_intervals()) return std::nullopt;
  return interval{v.edges()[state], v.edges()[state + 1]};
}

}  // namespace detail

/// The explanation for configuration u of a success table (see prevention_target for u*).
[[nodiscard]] PGM_DECL explanation explain(const cpt<double>& table, std::size_t success_state,
                                           std::size_t configuration, std::span<const bool> controllable,
                                           const prevention_options& options = {});

/// The explanation of moving from configuration u to `target` (only controllable variables
/// differ), however the target was chosen.
[[nodiscard]] PGM_DECL explanation explain_move(const cpt<double>& table, std::size_t success_state,
                                                std::size_t configuration, std::size_t target,
                                                std::span<const bool> controllable, double epsilon);

/// What prevention decides for one planned assignment on a network.
struct prevention_plan {
  /// The success table the decision used: P(success | controllable ∪ assigned parents), the
  /// node's own table when those are exactly its parents.
  cpt<double> table;
  explanation why;
};

/// Predicts, explains and prevents for `planned` on the engine's network. The decision table's
/// parents are the controllable variables and the assigned parents of the success variable,
/// and it holds P(success | do(controllable), the other assigned variables): prevention sets
/// the controllable variables, it does not observe them (intervened_success_table). When the
/// table's parents are exactly the success variable's (the usual case) no inference runs;
/// otherwise `engine` answers, its evidence restored afterwards. Every controllable variable
/// must be assigned, and every parent unless `marginalize_missing`.
template <InferenceEngine Engine>
[[nodiscard]] prevention_plan plan_prevention(Engine& engine, const success_event& success, const assignment& planned,
                                              std::span<const std::string> controllable,
                                              const prevention_options& options = {},
                                              const prediction_options& prediction = {}) {
  const auto& network = engine.network();
  detail::check_epsilon(options.epsilon);
  const auto target = node_of(network, success.variable);
  const auto state = network.at(success.variable).state(success.state);
  if (planned.contains(success.variable)) {
    throw model_error("the success variable '" + success.variable + "' is assigned; it is what is predicted");
  }
  if (controllable.empty())
    throw model_error("no variable is controllable, so nothing can be changed: name at least one");
  for (const auto& name : controllable) {
    static_cast<void>(node_of(network, name));
    if (name == success.variable) throw model_error("the success variable '" + name + "' cannot be controllable");
    if (!planned.contains(name)) {
      throw model_error("no value is given for the controllable variable '" + name +
                        "'; prevention moves it from there");
    }
  }
  const auto missing = unassigned_parents(network, success, planned);
  if (!missing.empty() && !prediction.marginalize_missing) detail::throw_missing(success, missing);

  // Decision variables: the success node's assigned parents in table order, then any
  // controllable variable that is not a parent.
  std::vector<std::string> given;
  for (const auto& p : network.table(target).parents()) {
    if (planned.contains(p.name())) given.push_back(p.name());
  }
  for (const auto& name : controllable) {
    if (std::find(given.begin(), given.end(), name) == given.end()) given.push_back(name);
  }
  std::vector<observation> rest;
  for (const auto& o : resolve(network, planned)) {
    const auto& name = network.variables()[o.variable.value()].name();
    if (std::find(given.begin(), given.end(), name) == given.end()) rest.push_back(o);
  }
  // Given the parents, non-descendants carry no information; only keep the observations that can.
  std::vector<observation> informative;
  const bool all_parents = missing.empty();
  for (const auto& o : rest) {
    const observation one[] = {o};
    if (!all_parents || detail::observes_descendant(network, target, one)) informative.push_back(o);
  }
  auto table = intervened_success_table(engine, success.variable, given, controllable, informative);
  std::vector<std::size_t> codes;
  std::vector<bool> flags;
  for (const auto& p : table.parents()) {
    codes.push_back(state_of(p, planned.find(p.name())->second).value());
    flags.push_back(std::find(controllable.begin(), controllable.end(), p.name()) != controllable.end());
  }
  const auto u = table.configuration(codes).value();
  // std::vector<bool> has no contiguous storage; the span needs real bools.
  const std::unique_ptr<bool[]> mask(new bool[flags.size()]);
  for (std::size_t i = 0; i < flags.size(); ++i) mask[i] = flags[i];
  auto why = explain(table, state.value(), u, std::span<const bool>(mask.get(), flags.size()), options);
  return {std::move(table), std::move(why)};
}

/// The same with variable elimination on `network`.
[[nodiscard]] PGM_DECL prevention_plan plan_prevention(const bayesian_network& network, const success_event& success,
                                                       const assignment& planned,
                                                       std::span<const std::string> controllable,
                                                       const prevention_options& options = {},
                                                       const prediction_options& prediction = {});

/// The variables prevention may move when the user names none: every parent of the success
/// variable, in table order.
[[nodiscard]] PGM_DECL std::vector<std::string> default_controllable(const bayesian_network& network,
                                                                     const success_event& success);

/// The value prevention suggests for each controllable variable of `why`: an unchanged one
/// keeps the number planned for it; an interval variable otherwise goes to the middle of its
/// target interval; any other variable to its target state's label.
[[nodiscard]] PGM_DECL assignment suggested_values(const explanation& why, const assignment& planned);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/decide/impl/explain.ipp"
#endif
