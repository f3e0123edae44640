#include "cli/transfer_arguments.hpp"

#include <cmath>
#include <iostream>

#include "cli/common.hpp"
#include "pgm/core/text.hpp"

namespace pgm::cli {

void add_transfer_options(CLI::App& command, transfer_arguments& args, bool with_weight) {
  command.add_option("--prior-model", args.prior_model,
                     "The prior task's fitted network T′ (" + network_file_kinds() + ")");
  command
      .add_option("--strategy", args.strategy,
                  "How to read the prior: direct, cross, minimal (eq. 9) or a registered strategy's name")
      ->capture_default_str();
  command.add_option("--map", args.map,
                     "Correspondences, target left: \"onTop2=onTop1,xOff2~xOff1,yOff2~yOff1\" (= transferred node, "
                     "~ related, == identical, P@v pins the prior's P to value v, P@* marginalizes it), or auto");
  if (with_weight) {
    command
        .add_option("--w-prior", args.w_prior, "Prior weight w of eq. 8 (≥ 0), or auto (highest marginal likelihood)")
        ->capture_default_str();
  }
  command.add_option("--success", args.success, "The success state of the transferred node (Minimal-Replacement)")
      ->capture_default_str();
  command.add_option("--match", args.matching, "Differently discretized states: midpoint or overlap")
      ->check(CLI::IsMember(known_state_matchings()))
      ->capture_default_str();
}

transfer_settings settings_of(const transfer_arguments& args) {
  transfer_settings settings;
  settings.strategy = args.strategy;
  settings.map = args.map;
  settings.success = args.success;
  settings.matching = parse_state_matching(args.matching);
  if (args.w_prior == "auto") {
    settings.weight.reset();
  } else {
    settings.weight = text::parse_double(args.w_prior);
    if (!settings.weight || !std::isfinite(*settings.weight) || *settings.weight < 0) {
      throw error("--w-prior must be a number ≥ 0 or auto, got " + text::quoted_number(args.w_prior));
    }
  }
  return settings;
}

void require_map(const transfer_arguments& args) {
  if (args.map.empty())
    throw error("--prior-model needs --map, e.g. --map \"onTop2=onTop1,xOff2~xOff1\" or --map auto");
}

correspondence resolve_map(const transfer_arguments& args, const bayesian_network& prior,
                           const network_structure& target) {
  require_map(args);
  const auto map = resolve_correspondence(args.map, prior, target);
  if (args.map == "auto") note("--map auto: " + to_string(map));
  return map;
}

std::map<std::string, transferred_prior, std::less<>> resolve_priors(const transfer_arguments& args,
                                                                     const bayesian_network& prior,
                                                                     const network_structure& target,
                                                                     const correspondence& map) {
  return transfer_priors(prior, target, map, settings_of(args));
}

}  // namespace pgm::cli
