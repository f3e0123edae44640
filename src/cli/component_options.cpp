#include "cli/component_options.hpp"

#include <limits>

#include "cli/common.hpp"
#include "pgm/core/text.hpp"

namespace pgm::cli {

std::string choices_help(const std::vector<std::string>& listing) {
  return "one of " + text::join(listing) + " (the options at their defaults); NAME[KEY=VALUE,...] sets an option";
}

std::string described(const std::string& name, const option_values& options) {
  if (options.empty()) return name;
  std::vector<std::string> settings;
  for (std::size_t i = 0; i < options.declarations().size(); ++i) {
    const auto& value = options.values()[i];
    settings.push_back(options.declarations()[i].name + " " +
                       (std::holds_alternative<double>(value) ? text::format_short(std::get<double>(value))
                                                              : format_option_value(value)));
  }
  return name + " (" + text::join(settings) + ")";
}

void add_score_options(CLI::App& cmd, score_arguments& args) {
  cmd.add_option("--score", args.score,
                 "The decomposable score, as bnlearn's score() defines it: " + choices_help(scores().listing()) +
                     "; 'bde' is bdeu")
      ->check(component_check(scores()))
      ->capture_default_str();
  cmd.add_option("--iss", args.iss, "Shorthand for --score bdeu[iss=N]: bdeu's imaginary sample size, a number > 0")
      ->check(number_between(0, std::numeric_limits<double>::infinity(), true, true));
}

family_score chosen_score(const score_arguments& args) {
  if (!args.iss) return make_score(args.score);
  const auto spec = parse_component_spec(args.score, "score");
  for (const auto& [key, value] : spec.settings) {
    if (key == "iss") throw error("--iss and --score " + args.score + " both set iss; give it once");
  }
  const auto choice = scores().choose(args.score);
  if (!choice.options.declares("iss")) {
    throw error("--iss sets the imaginary sample size of a score that has one (bdeu); " + choice.name + " has none");
  }
  std::string settings;
  for (const auto& [key, value] : spec.settings) settings += key + "=" + value + ",";
  return make_score(choice.name + "[" + settings + "iss=" + text::format_double(*args.iss) + "]");
}

}  // namespace pgm::cli
