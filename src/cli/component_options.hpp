#pragma once
// Command-line options that choose a registered component (pgm/core/component_registry.hpp),
// written NAME or NAME[KEY=VALUE,...]: their help lists each component with its declared
// defaults, and a bad choice is refused while the arguments are parsed, with the registry's
// message.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "pgm/core/component_registry.hpp"
#include "pgm/learn/score_registry.hpp"

namespace pgm::cli {

/// "one of aic[k=1], bdeu[iss=1], bic; NAME[KEY=VALUE,...] sets an option": the end of a help text.
[[nodiscard]] std::string choices_help(const std::vector<std::string>& listing);

/// Refuses a text the registry cannot choose from, with its message.
template <class Product>
[[nodiscard]] CLI::Validator component_check(const component_registry<Product>& registry) {
  return CLI::Validator(
      [&registry](std::string& text) -> std::string {
        try {
          static_cast<void>(registry.choose(text));
          return {};
        } catch (const error& refused) {
          return refused.what();
        }
      },
      "NAME[KEY=VALUE,...]");
}

/// "bdeu (iss 10)", "bic": a component and its options for people, numbers to 6 digits.
[[nodiscard]] std::string described(const std::string& name, const option_values& options);

[[nodiscard]] inline std::string described(const family_score& score) {
  return described(score.name(), score.options());
}

/// --score, with --iss as the shorthand of a score's iss option.
struct score_arguments {
  std::string score = family_score().text();
  std::optional<double> iss;
};

void add_score_options(CLI::App& cmd, score_arguments& args);

/// The score the arguments choose. Throws error for --iss given to a score without an iss
/// option, or given besides the brackets' iss.
[[nodiscard]] family_score chosen_score(const score_arguments& args);

}  // namespace pgm::cli
