#pragma once
// --reward, --move-cost and --per: prevention as a decision (pgm/decide/prevent_by_utility.hpp),
// declared once for `pgm prevent` and `pgm experiment`.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "pgm/decide/prevent_by_utility.hpp"

namespace pgm::cli {

struct move_cost_arguments {
  std::optional<double> reward;
  std::string move_cost;
  std::string per = "steps";
};

/// Adds the three options; `reward_help` says what --reward does in this command. --move-cost
/// and --per need --reward.
void add_move_cost_options(CLI::App& cmd, move_cost_arguments& args, const std::string& reward_help);

/// The costs the options give, or none without --reward. Throws model_error for a --move-cost
/// that is not NAME=COST,... or names a variable twice.
[[nodiscard]] std::optional<move_costs> move_costs_of(const move_cost_arguments& args);

/// "bin step" or "unit moved".
[[nodiscard]] std::string cost_unit_label(const move_costs& costs);

}  // namespace pgm::cli
