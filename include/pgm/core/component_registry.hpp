#pragma once
/// \file
/// Components by name, each with its declared options (pgm/core/component_options.hpp):
/// `registry.make("bdeu[iss=10]")` finds "bdeu", sets iss on top of its declared defaults and
/// builds the component. The scores (pgm/learn/score_registry.hpp) and the independence tests
/// (pgm/learn/independence_test_registry.hpp) are kept in one each; a user's component joins
/// its registry with one line.

#include <concepts>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
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

/// A component that is a function, with the choice that made it: what a registry of scores or
/// independence tests builds. Copies share the function, which may be called from several
/// threads at once.
template <class Signature>
class chosen_function;

template <class Result, class... Arguments>
class chosen_function<Result(Arguments...)> {
 public:
  using function_type = std::function<Result(Arguments...)>;

  chosen_function(function_type call, component_choice choice)
      : call_(std::make_shared<const function_type>(std::move(call))), choice_(std::move(choice)) {}

  Result operator()(Arguments... arguments) const { return (*call_)(std::forward<Arguments>(arguments)...); }

  [[nodiscard]] const std::string& name() const noexcept { return choice_.name; }
  [[nodiscard]] const option_values& options() const noexcept { return choice_.options; }
  /// "bdeu[iss=10]": what chooses this component again.
  [[nodiscard]] std::string text() const { return choice_.text(); }

 private:
  std::shared_ptr<const function_type> call_;
  component_choice choice_;
};

/// An option given apart from a component's text, as the program's `--alpha 0.05` or Python's
/// `alpha=0.05`: `label` names it in messages; no value, not given.
struct component_setting {
  std::string label;
  std::string key;
  std::optional<std::string> value;
};

template <class Product>
class component_registry {
 public:
  using product_type = Product;

  struct entry {
    /// One line for help texts.
    std::string summary;
    std::vector<option_declaration> options;
    std::function<Product(const component_choice&)> make;
  };

  /// `kind` names an entry in messages ("score").
  explicit component_registry(std::string kind) : kind_(std::move(kind)), entries_(kind_) {}

  /// What one component is called in messages: "score".
  [[nodiscard]] const std::string& kind() const noexcept { return kind_; }

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

  /// `text` with `key`=`value` added: "bdeu" gives "bdeu[iss=10]". Throws model_error when
  /// `text` sets `key` already or its component has no option `key`, and what choose throws.
  [[nodiscard]] std::string with_setting(std::string_view text, std::string_view key, std::string_view value) const {
    const auto spec = parse_component_spec(text, kind_);
    const auto choice = choose(text);
    std::string settings;
    for (const auto& [set, set_value] : spec.settings) {
      if (set == key)
        throw model_error("sets " + std::string(key) + ", which '" + std::string(text) +
                          "' sets already; give it once");
      settings += set + "=" + set_value + ",";
    }
    if (!choice.options.declares(key)) {
      throw model_error("sets the option " + std::string(key) + ", which the " + kind_ + " " + choice.name +
                        " has not");
    }
    auto result = spec.name + "[" + settings + std::string(key) + "=" + std::string(value) + "]";
    static_cast<void>(choose(result));
    return result;
  }

  /// `text` with each given setting set on it. Throws model_error, after the setting's label,
  /// for one that with_setting refuses.
  [[nodiscard]] std::string with_settings(std::string_view text, const std::vector<component_setting>& settings) const {
    std::string chosen(text);
    for (const auto& setting : settings) {
      if (!setting.value) continue;
      try {
        chosen = with_setting(chosen, setting.key, *setting.value);
      } catch (const error& why) {
        throw model_error(setting.label + ": " + why.what());
      }
    }
    return chosen;
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

/// An option whose value is a component of the registry `registry()` returns, written as that
/// registry reads it: mmhc's `test=g2[correction=yates]`. The registry is looked up only when a
/// value is read, so a component may choose among its own kind (hc's `start=pc`).
template <class Product>
[[nodiscard]] option_declaration component_option(std::string name, component_registry<Product>& (*registry)(),
                                                  std::string default_choice, std::string help) {
  return {.name = std::move(name),
          .type = option_type::component,
          .default_text = std::move(default_choice),
          .help = std::move(help),
          .check_choice = [registry](std::string_view text) { static_cast<void>(registry().choose(text)); },
          .kind = [registry] { return registry().kind(); },
          .choices = [registry] { return registry().listing(); }};
}

/// The entry of a component type T in a registry of Products: T's declared options (none when
/// it declares none) and how a Product is made of T built from them.
template <class Product, class T>
[[nodiscard]] typename component_registry<Product>::entry component_entry(std::string summary) {
  if constexpr (requires { T::options(); }) {
    static_assert(std::constructible_from<T, const option_values&>,
                  "a component that declares options is constructible from the option_values they are read into");
    return {std::move(summary), T::options(),
            [](const component_choice& choice) { return Product(T(choice.options), choice); }};
  } else {
    static_assert(std::default_initializable<T>, "a component without options is default-constructible");
    return {std::move(summary), {}, [](const component_choice& choice) { return Product(T{}, choice); }};
  }
}

/// Adds T to the registry `Registry()` returns when the program starts; each registry names it
/// for its own kind: `static const pgm::register_score<S> registered("name", "summary");`.
template <auto Registry, class T>
struct component_registration {
  component_registration(std::string name, std::string summary) {
    auto& registry = Registry();
    using product = typename std::remove_reference_t<decltype(registry)>::product_type;
    registry.add(std::move(name), component_entry<product, T>(std::move(summary)));
  }
};

}  // namespace pgm
