#pragma once
/// \file
/// Options declared once, as data. A component chosen by name (a score, an independence test,
/// …) declares each of its options here — name, type, the library's default, a line of help
/// and the check a value must pass — and a user's choice is written `name[key=value,…]`, as
/// libDAI writes `BP[tol=1e-9]`. The registry (pgm/core/component_registry.hpp) reads a choice
/// against the declarations, and the program's help and the docs list the same declarations,
/// so a default is written in one place only.

#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "pgm/core/compilation.hpp"

namespace pgm {

enum class option_type {
  number,  ///< a finite double
  count,   ///< a whole number >= 0
  flag,    ///< true or false
  word,    ///< one of a list of words
  /// a component of another registry, itself written NAME[KEY=VALUE,...]: mmhc's test
  component,
};

struct option_declaration {
  std::string name;
  option_type type = option_type::number;
  /// The library's default, as it is written in a choice.
  std::string default_text;
  std::string help;
  /// The range a number or a count must lie in.
  double minimum = -std::numeric_limits<double>::infinity();
  bool minimum_included = true;
  double maximum = std::numeric_limits<double>::infinity();
  bool maximum_included = true;
  /// A count may also be "unlimited", read as the largest std::size_t.
  bool unlimited_allowed = false;
  /// A word's allowed values.
  std::vector<std::string> words;
  /// A component option's registry: the check that throws its message for a choice it refuses,
  /// what it calls a component ("independence test") and its listing, for messages. Looked up
  /// when needed, since a learner may choose among learners while their registry is being built.
  std::function<void(std::string_view)> check_choice;
  std::function<std::string()> kind;
  std::function<std::vector<std::string>()> choices;

  option_declaration greater_than(double bound) && {
    minimum = bound;
    minimum_included = false;
    return std::move(*this);
  }
  option_declaration at_least(double bound) && {
    minimum = bound;
    minimum_included = true;
    return std::move(*this);
  }
  option_declaration at_most(double bound) && {
    maximum = bound;
    maximum_included = true;
    return std::move(*this);
  }
  option_declaration less_than(double bound) && {
    maximum = bound;
    maximum_included = false;
    return std::move(*this);
  }

  /// What a value must be: "a number > 0", "a whole number from 1 to 100", "true or false",
  /// "one of none, yates", "an independence test: one of chi2[...], g2[...]".
  [[nodiscard]] PGM_DECL std::string expected() const;
};

[[nodiscard]] PGM_DECL option_declaration number_option(std::string name, double default_value, std::string help);
/// A default of the largest std::size_t is "unlimited", which the option then accepts.
[[nodiscard]] PGM_DECL option_declaration count_option(std::string name, std::size_t default_value, std::string help);
[[nodiscard]] PGM_DECL option_declaration flag_option(std::string name, bool default_value, std::string help);
[[nodiscard]] PGM_DECL option_declaration word_option(std::string name, std::string default_value,
                                                      std::vector<std::string> words, std::string help);

using option_value = std::variant<double, std::size_t, bool, std::string>;

/// Why `text` is no value of `option`, written to follow the option's name: " must be a number
/// > 0, got '0'", or ": " and the registry's message for a component it refuses; empty when
/// `text` is a value of it.
[[nodiscard]] PGM_DECL std::string option_value_refusal(const option_declaration& option, std::string_view text);

/// A choice as the user wrote it: a name and its `key=value` settings in order.
struct component_spec {
  std::string name;
  std::vector<std::pair<std::string, std::string>> settings;
};

/// Reads "name" or "name[key=value,…]" (spaces around each part ignored), where a value may be a
/// choice of its own in brackets ("mmhc[test=g2[correction=yates],alpha=0.05]"). `kind` names
/// what is chosen in messages ("score"). Throws model_error saying at which column the text stops
/// making sense and what was expected there.
[[nodiscard]] PGM_DECL component_spec parse_component_spec(std::string_view text, std::string_view kind);

/// A component's options: each declared one at its default unless set.
class option_values {
 public:
  option_values() = default;
  /// Every option at its declared default.
  PGM_DECL explicit option_values(std::vector<option_declaration> declarations);

  /// Sets `key` from its text. `kind` and `name` name the component in messages ("score",
  /// "bdeu"). Throws unknown_name for an option not declared, model_error for a value that
  /// fails the declaration's check.
  PGM_DECL void set(std::string_view key, std::string_view value, std::string_view kind, std::string_view name);

  [[nodiscard]] PGM_DECL double number(std::string_view key) const;
  [[nodiscard]] PGM_DECL std::size_t count(std::string_view key) const;
  [[nodiscard]] PGM_DECL bool flag(std::string_view key) const;
  [[nodiscard]] PGM_DECL const std::string& word(std::string_view key) const;
  /// A component option's choice as it was written ("g2[correction=yates]").
  [[nodiscard]] PGM_DECL const std::string& component(std::string_view key) const;

  [[nodiscard]] bool declares(std::string_view key) const noexcept { return position(key) < declarations_.size(); }
  [[nodiscard]] const std::vector<option_declaration>& declarations() const noexcept { return declarations_; }
  [[nodiscard]] const std::vector<option_value>& values() const noexcept { return values_; }
  [[nodiscard]] bool empty() const noexcept { return declarations_.empty(); }

  /// "iss=1", every option as set, in declaration order: what reads back to these values.
  [[nodiscard]] PGM_DECL std::string text() const;

 private:
  [[nodiscard]] PGM_DECL std::size_t position(std::string_view key) const noexcept;
  [[nodiscard]] PGM_DECL const option_value& at(std::string_view key, option_type type) const;

  std::vector<option_declaration> declarations_;
  std::vector<option_value> values_;
};

/// An option's value as it is written in a choice; the largest count is "unlimited".
[[nodiscard]] PGM_DECL std::string format_option_value(const option_value& value);

/// "bdeu[iss=1]", or "bic" for a component without options.
[[nodiscard]] PGM_DECL std::string spec_text(std::string_view name, const option_values& values);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/component_options.ipp"
#endif
