#include "cli/component_options.hpp"

#include <limits>

#include "cli/common.hpp"
#include "pgm/core/text.hpp"

namespace pgm::cli {

std::string choices_help(const std::vector<std::string>& listing) {
  return "one of " + text::join(listing) + " (the options at their defaults); NAME[KEY=VALUE,...] sets an option";
}

std::string with_shorthand(const std::string& text, const component_choice& choice, const std::string& key,
                           const std::string& value) {
  const auto spec = parse_component_spec(text, "choice");
  for (const auto& [set, unused] : spec.settings) {
    if (set == key) throw error("sets " + key + ", which '" + text + "' sets already; give it once");
  }
  if (!choice.options.declares(key)) throw error("sets the option " + key + ", which " + choice.name + " has not");
  std::string settings;
  for (const auto& [set, set_value] : spec.settings) settings += set + "=" + set_value + ",";
  return choice.name + "[" + settings + key + "=" + value + "]";
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
  add_component_option(cmd, "--score", args.score,
                       "The decomposable score, as bnlearn's score() defines it ('bde' is bdeu)", scores());
  cmd.add_option("--iss", args.iss, "Shorthand for --score bdeu[iss=N]: bdeu's imaginary sample size, a number > 0")
      ->check(number_between(0, std::numeric_limits<double>::infinity(), true, true));
}

family_score chosen_score(const score_arguments& args) {
  const auto iss = args.iss ? std::optional(text::format_double(*args.iss)) : std::nullopt;
  return chosen_with(scores(), args.score, {{"--iss", "iss", iss}});
}

}  // namespace pgm::cli
