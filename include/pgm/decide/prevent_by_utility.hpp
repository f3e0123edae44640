#pragma once
/// \file
/// Failure prevention as a decision: instead of moving to the nearest configuration above ε,
/// choose the move of highest expected utility, a reward R for success (0 for failure) less
/// what moving costs, per bin step or per unit moved, adding up over the variables (one without
/// a cost moves for free). The plan is an influence diagram (pgm/core/influence_diagram.hpp):
/// each controllable variable a decision taken after seeing the earlier ones, the success
/// variable a chance node given them (the other parents as planned), a utility on success and
/// one cost per variable; solve_decisions gives the move.

#include <cstddef>
#include <map>
#include <memory>
#include <span>
#include <string>

#include "pgm/core/compilation.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/influence_diagram.hpp"
#include "pgm/decide/explain.hpp"

namespace pgm {

struct move_costs {
  enum class per { steps, units };
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

/// The influence diagram of moving from configuration u of a success table (its controllable
/// parents marked). Throws model_error for a negative or non-finite cost or reward, a cost of a
/// variable that is not controllable, or a cost per unit of a variable without interval edges.
[[nodiscard]] PGM_DECL influence_diagram prevention_diagram(const cpt<double>& table, std::size_t success_state,
                                                            std::size_t configuration,
                                                            std::span<const bool> controllable,
                                                            const move_costs& costs);

/// The move of highest expected utility from u. Among equally good moves, the one that moves
/// fewest variables (a variable stays where moving it gains nothing).
[[nodiscard]] PGM_DECL utility_move best_move(const cpt<double>& table, std::size_t success_state,
                                              std::size_t configuration, std::span<const bool> controllable,
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
