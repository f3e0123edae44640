#pragma once
// Command-line options that choose a registered component (pgm/core/component_registry.hpp),
// written NAME or NAME[KEY=VALUE,...]: their help lists each component with its declared
// defaults, a bad choice is refused while the arguments are parsed with the registry's
// message, and a shorthand option (--iss N) sets one option of the choice.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "pgm/core/component_registry.hpp"
#include "pgm/core/error.hpp"
#include "pgm/learn/independence_test_registry.hpp"
#include "pgm/learn/score_registry.hpp"

namespace pgm::cli {

/// "one of aic[k=1], bdeu[iss=1], bic (the options at their defaults); NAME[KEY=VALUE,...]
/// sets an option": the end of a help text.
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

/// `flag` choosing from `registry` into `text`, its help `what` and the registry's listing.
template <class Product>
CLI::Option* add_component_option(CLI::App& cmd, const std::string& flag, std::string& text, const std::string& what,
                                  const component_registry<Product>& registry) {
  return cmd.add_option(flag, text, what + ": " + choices_help(registry.listing()))
      ->check(component_check(registry))
      ->capture_default_str();
}

/// The option `key` that `component` of `registry` declares.
template <class Product>
[[nodiscard]] option_declaration declared_option(const component_registry<Product>& registry,
                                                 const std::string& component, const std::string& key) {
  const auto entry = registry.find(component).value();
  for (const auto& option : entry.options) {
    if (option.name == key) return option;
  }
  throw error("the " + registry.kind() + " " + component + " declares no option " + key);
}

/// `flag`, which sets one declared option of a component: the declared default shown in its
/// help, its value checked as declared while the arguments are parsed. Read its value with
/// given_value.
[[nodiscard]] CLI::Option* add_declared_option(CLI::App& cmd, const std::string& flag,
                                               const option_declaration& declaration, const std::string& help);

/// The text given to `option`, if it was given.
[[nodiscard]] std::optional<std::string> given_value(const CLI::Option& option);

/// The component `text` chooses, with the shorthand options given (--iss N for bdeu[iss=N],
/// each labelled by its flag) set on it. A shorthand that cannot be set, or whose value its
/// option refuses, is a usage error naming its flag.
template <class Product>
[[nodiscard]] Product chosen_with(const component_registry<Product>& registry, std::string text,
                                  const std::vector<component_setting>& shorthands) {
  for (const auto& given : shorthands) {
    if (!given.value) continue;
    try {
      text = registry.with_setting(text, given.key, *given.value);
    } catch (const error& refused) {
      throw CLI::ValidationError(given.label, refused.what());
    }
  }
  return registry.make(text);
}

/// "bdeu (iss 10)", "bic": a component and its options for people, numbers to 6 digits.
[[nodiscard]] std::string described(const std::string& name, const option_values& options);

template <class Signature>
[[nodiscard]] std::string described(const chosen_function<Signature>& component) {
  return described(component.name(), component.options());
}

/// --score, with --iss as the shorthand of a score's iss option.
struct score_arguments {
  std::string score = family_score().name();
  std::optional<double> iss;
};

void add_score_options(CLI::App& cmd, score_arguments& args);

/// The score the arguments choose. Throws error for --iss given to a score without an iss
/// option, or given besides the brackets' iss.
[[nodiscard]] family_score chosen_score(const score_arguments& args);

}  // namespace pgm::cli
