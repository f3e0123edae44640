#include "cli/move_cost_options.hpp"

#include <limits>

#include "cli/common.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"

namespace pgm::cli {

void add_move_cost_options(CLI::App& cmd, move_cost_arguments& args, const std::string& reward_help) {
  auto* reward = cmd.add_option("--reward", args.reward, reward_help)
                     ->check(number_between(0, std::numeric_limits<double>::infinity(), false, true));
  cmd.add_option("--move-cost", args.move_cost,
                 "With --reward: the cost of moving each variable per bin step (or unit, --per units), e.g. "
                 "\"xOff2=2,yOff2=2\"; a controllable variable not named moves for free")
      ->needs(reward);
  cmd.add_option("--per", args.per, "With --reward: costs per bin step (steps) or per unit moved (units)")
      ->check(CLI::IsMember(known_distances()))
      ->needs(reward)
      ->capture_default_str();
}

std::optional<move_costs> move_costs_of(const move_cost_arguments& args) {
  if (!args.reward) return std::nullopt;
  move_costs costs{.reward = *args.reward, .unit = parse_distance(args.per)};
  if (args.move_cost.empty()) return costs;
  for (const auto& piece : split_list(args.move_cost, "--move-cost")) {
    const auto eq = piece.find('=');
    const auto number = eq == std::string::npos ? std::nullopt : text::parse_double(piece.substr(eq + 1));
    if (!number) throw model_error("--move-cost: expected NAME=COST, found '" + piece + "'");
    if (!costs.cost.emplace(piece.substr(0, eq), *number).second) {
      throw model_error("--move-cost names '" + piece.substr(0, eq) + "' twice");
    }
  }
  return costs;
}

std::string cost_unit_label(const move_costs& costs) {
  return costs.unit == move_costs::per::units ? "unit moved" : "bin step";
}

}  // namespace pgm::cli
