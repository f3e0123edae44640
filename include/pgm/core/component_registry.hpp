#pragma once
/// \file
/// Components by name, each with its declared options (pgm/core/component_options.hpp):
/// `registry.make("bdeu[iss=10]")` finds "bdeu", sets iss on top of its declared defaults and
/// builds the component. The scores (pgm/learn/score_registry.hpp) are kept in one; a user's
/// component joins its registry with one line.

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/component_options.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/detail/named_registry.hpp"

namespace pgm {

/// A component as the registry builds it: its name and its options as they were set.
struct component_choice {
  std::string name;
  option_values options;

  /// "bdeu[iss=10]": what reads back to this choice.
  [[nodiscard]] std::string text() const { return spec_text(name, options); }
};

template <class Product>
class component_registry {
 public:
  struct entry {
    /// One line for help texts.
    std::string summary;
    std::vector<option_declaration> options;
    std::function<Product(const component_choice&)> make;
  };

  /// `kind` names an entry in messages ("score").
  explicit component_registry(std::string kind) : kind_(std::move(kind)), entries_(kind_) {}

  /// Adds a component; an empty or taken name is a model_error.
  void add(std::string name, entry component) {
    if (aliases_.find(name)) throw model_error("a " + kind_ + " named '" + name + "' is registered already");
    entries_.add(std::move(name), std::move(component));
  }

  /// Lets `alias` stand for the component `name` (bnlearn's "bde" for "bdeu").
  void add_alias(std::string alias, std::string name) {
    if (entries_.find(alias)) throw model_error("a " + kind_ + " named '" + alias + "' is registered already");
    aliases_.add(std::move(alias), std::move(name));
  }

  /// The choice `text` ("name" or "name[key=value,…]") makes: the component's canonical name
  /// and every option, declared defaults overridden by the settings. Throws unknown_name for an
  /// unknown component or option, model_error for a malformed text or a value that fails its
  /// declaration's check.
  [[nodiscard]] component_choice choose(std::string_view text) const {
    auto spec = parse_component_spec(text, kind_);
    if (const auto target = aliases_.find(spec.name)) spec.name = *target;
    const auto component = entries_.find(spec.name);
    if (!component) throw unknown_name(kind_, spec.name, names());
    component_choice choice{spec.name, option_values(component->options)};
    for (const auto& [key, value] : spec.settings) choice.options.set(key, value, kind_, spec.name);
    return choice;
  }

  /// The component `text` chooses.
  [[nodiscard]] Product make(std::string_view text) const {
    const auto choice = choose(text);
    return entries_.find(choice.name)->make(choice);
  }

  /// The components' names, sorted, aliases left out.
  [[nodiscard]] std::vector<std::string> names() const { return entries_.names(); }

  /// Every name the registry accepts, aliases included: for a command line's allowed values.
  [[nodiscard]] std::vector<std::string> accepted_names() const {
    auto accepted = names();
    for (auto& alias : aliases_.names()) accepted.push_back(std::move(alias));
    return accepted;
  }

  [[nodiscard]] std::optional<entry> find(std::string_view name) const { return entries_.find(name); }

  /// Each component as it is chosen with its defaults, "bdeu[iss=1]": for help texts.
  [[nodiscard]] std::vector<std::string> listing() const {
    std::vector<std::string> lines;
    for (const auto& name : names()) lines.push_back(spec_text(name, option_values(entries_.find(name)->options)));
    return lines;
  }

 private:
  std::string kind_;
  detail::named_registry<entry> entries_;
  detail::named_registry<std::string> aliases_{"alias"};
};

}  // namespace pgm
