#include "cli/component_options.hpp"

#include <limits>

#include "cli/common.hpp"
#include "pgm/core/text.hpp"

namespace pgm::cli {

std::string choices_help(const std::vector<std::string>& listing) {
  return "one of " + text::join(listing) + " (the options at their defaults); NAME[KEY=VALUE,...] sets an option";
}

CLI::Option* add_declared_option(CLI::App& cmd, const std::string& flag, const option_declaration& declaration,
                                 const std::string& help) {
  const auto type = declaration.type == option_type::number  ? "FLOAT"
                    : declaration.type == option_type::count ? "UINT"
                                                             : "TEXT";
  return cmd.add_option(flag, help)
      ->type_name(type)
      ->default_str(declaration.default_text)
      ->check(CLI::Validator(
          [declaration](std::string& text) {
            const auto refusal = option_value_refusal(declaration, text);
            // " must be ..." or ": <the registry's message>", after the flag CLI11 puts first.
            return refusal.empty() ? refusal : refusal.substr(refusal.find_first_not_of(": "));
          },
          declaration.expected()));
}

std::optional<std::string> given_value(const CLI::Option& option) {
  if (option.count() == 0) return std::nullopt;
  return option.results().back();
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
