#pragma once
/// \file
/// Failure prevention as a decision: instead of moving to the nearest configuration above ε,
/// choose the move of highest expected utility, a reward R for success (0 for failure) less
/// what moving costs, per bin step or per unit moved, adding up over the variables (one without
/// a cost moves for free). The plan is an influence diagram (pgm/core/influence_diagram.hpp):
/// each controllable variable a decision taken after seeing the earlier ones, the success
/// variable a chance node given them (the other parents as planned), a utility on success and
/// one cost per variable. Every decision sees the ones before and only success is uncertain,
/// so its optimum is the best configuration of the plan's slice (those that differ from it in
/// controllable parents only): best_move scans the slice, and the tests check it against
/// solve_decisions on prevention_diagram.

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/influence_diagram.hpp"
#include "pgm/decide/explain.hpp"

namespace pgm {

struct move_costs {
  /// Bin steps or units, as the ε-rule measures its distance ("steps", "units": parse_distance).
  using per = prevention_options::distance;
  /// The utility of success; failure is worth 0.
  double reward = 1;
  /// Cost per bin step (or unit) of each controllable variable; a variable not named is free.
  std::map<std::string, double, std::less<>> cost;
  per unit = per::steps;
};

struct utility_move {
  std::size_t target = 0;  ///< u*, in the success table's numbering
  double expected_utility = 0;
  double success_probability = 0;
  double cost = 0;
};

namespace detail {

/// The moves within one slice: the controllable parents' states numbered in mixed radix (in
/// parent order), each one's cost of moving between every two states precomputed.
class slice_mover {
 public:
  /// Throws model_error as best_move does.
  PGM_DECL slice_mover(const cpt<double>& table, std::size_t success_state, std::span<const bool> controllable,
                       const move_costs& costs);

  /// The table's configurations in u's slice, by local number.
  PGM_DECL void members_of(std::size_t u, std::vector<std::size_t>& members) const;

  /// u's local number in its slice.
  [[nodiscard]] PGM_DECL std::size_t local_of(std::size_t u) const;

  /// The best move from the member numbered `from`.
  [[nodiscard]] PGM_DECL utility_move best_from(std::size_t from, const std::vector<std::size_t>& members) const;

 private:
  const cpt<double>& table_;  ///< dense
  std::size_t success_state_;
  double reward_;
  std::vector<std::size_t> moved_;  ///< the controllable parents
  std::vector<std::size_t> cards_;
  std::vector<std::vector<double>> cost_between_;  ///< per moved parent, [from · card + to]
  std::vector<std::uint32_t> digits_;              ///< [local · moved + k]: the k-th moved parent's state
  std::vector<std::size_t> offset_;                ///< per local number, its configuration less the slice's base
};

}  // namespace detail

/// The influence diagram of moving from configuration u of a success table (its controllable
/// parents marked). Throws model_error for a negative or non-finite cost or reward, a cost of a
/// variable that is not controllable, or a cost per unit of a variable without interval edges.
[[nodiscard]] PGM_DECL influence_diagram prevention_diagram(const cpt<double>& table, std::size_t success_state,
                                                            std::size_t configuration,
                                                            std::span<const bool> controllable,
                                                            const move_costs& costs);

/// The move of highest expected utility from u. Among equally good moves (within 1e-12), the
/// one that moves fewest variables, then the lowest index: a plan stays where no move gains.
[[nodiscard]] PGM_DECL utility_move best_move(const cpt<double>& table, std::size_t success_state,
                                              std::size_t configuration, std::span<const bool> controllable,
                                              const move_costs& costs);

/// best_move from every configuration of `table`, each slice's members found once: for
/// scoring the rule over a whole table (prevention_outcome_of).
[[nodiscard]] PGM_DECL std::vector<utility_move> best_moves(const cpt<double>& table, std::size_t success_state,
                                                            std::span<const bool> controllable,
                                                            const move_costs& costs);

/// How a rule's moves fare by the truth, as weighted means over the configurations u (the
/// weights as failure_prevention_rate's): success, truth's P(success | u*); cost, what moving
/// from u to u* costs; utility, reward · success − cost.
struct prevention_outcome {
  double success = 0;
  double cost = 0;
  double utility = 0;
};

/// `targets` holds u* for every configuration u of `truth` (prevention_targets, or best_moves'
/// targets). Throws model_error for targets or weights of the wrong size, a target that moves
/// an uncontrollable parent, weights as failure_prevention_rate refuses, or costs as best_move
/// refuses.
[[nodiscard]] PGM_DECL prevention_outcome prevention_outcome_of(std::span<const std::size_t> targets,
                                                                const cpt<double>& truth, std::size_t success_state,
                                                                std::span<const bool> controllable,
                                                                std::span<const double> configuration_weights,
                                                                const move_costs& costs);

/// The best move for a plan prevention has settled (its success table and configuration), and
/// its explanation (ε only says whether each end is predicted to succeed).
struct utility_prevention {
  utility_move move;
  explanation why;
};

[[nodiscard]] PGM_DECL utility_prevention prevent_by_utility(const prevention_plan& plan,
                                                             std::span<const std::string> controllable,
                                                             const move_costs& costs);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/decide/impl/prevent_by_utility.ipp"
#endif
