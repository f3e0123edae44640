#pragma once
// The definitions of pgm/core/component_options.hpp: inline in a header-only build, compiled once
// into libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <concepts>
#include <optional>
#include <type_traits>

#include "pgm/core/assert.hpp"
#include "pgm/core/component_options.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/unknown_name.hpp"

namespace pgm {
namespace detail {

/// " > 0", " from 1 to 100", " >= 0 and < 1": the range of a number or a count.
[[nodiscard]] inline std::string range_text(const option_declaration& option) {
  const bool low = std::isfinite(option.minimum);
  const bool high = std::isfinite(option.maximum);
  const auto bound = [&](double value) {
    return option.type == option_type::count ? std::to_string(static_cast<std::size_t>(value))
                                             : text::format_double(value);
  };
  if (low && high && option.minimum_included && option.maximum_included) {
    return " from " + bound(option.minimum) + " to " + bound(option.maximum);
  }
  std::string range;
  if (low) range += (option.minimum_included ? " >= " : " > ") + bound(option.minimum);
  if (low && high) range += " and";
  if (high) range += (option.maximum_included ? " <= " : " < ") + bound(option.maximum);
  return range;
}

[[nodiscard]] inline bool in_range(const option_declaration& option, double value) {
  const bool above = option.minimum_included ? value >= option.minimum : value > option.minimum;
  const bool below = option.maximum_included ? value <= option.maximum : value < option.maximum;
  return above && below;
}

/// The value `text` gives `option`, or nothing when it fails the option's type or check.
[[nodiscard]] inline std::optional<option_value> read_option_value(const option_declaration& option,
                                                                   std::string_view text) {
  switch (option.type) {
    case option_type::number: {
      const auto value = text::parse_double(text);
      if (!value || !std::isfinite(*value) || !in_range(option, *value)) return std::nullopt;
      return option_value(*value);
    }
    case option_type::count: {
      if (option.unlimited_allowed && text == "unlimited") return option_value(std::numeric_limits<std::size_t>::max());
      std::size_t value = 0;
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
      if (error != std::errc{} || end != text.data() + text.size() || !in_range(option, static_cast<double>(value))) {
        return std::nullopt;
      }
      return option_value(value);
    }
    case option_type::flag:
      if (text == "true" || text == "1") return option_value(true);
      if (text == "false" || text == "0") return option_value(false);
      return std::nullopt;
    case option_type::word:
      if (std::find(option.words.begin(), option.words.end(), text) == option.words.end()) return std::nullopt;
      return option_value(std::string(text));
    case option_type::component:
      option.check_choice(text);  // throws the registry's own message
      return option_value(std::string(text));
  }
  return std::nullopt;
}

}  // namespace detail

PGM_DECL std::string option_declaration::expected() const {
  switch (type) {
    case option_type::number:
      return "a number" + detail::range_text(*this);
    case option_type::count:
      return "a whole number" + detail::range_text(*this) + (unlimited_allowed ? ", or unlimited" : "");
    case option_type::flag:
      return "true or false";
    case option_type::word:
      return "one of " + text::join(words);
    case option_type::component: {
      const auto what = kind();
      const bool vowel = !what.empty() && std::string_view("aeiou").find(what[0]) != std::string_view::npos;
      return (vowel ? "an " : "a ") + what + ", one of " + text::join(choices());
    }
  }
  return {};
}

PGM_DECL option_declaration number_option(std::string name, double default_value, std::string help) {
  return {.name = std::move(name),
          .type = option_type::number,
          .default_text = text::format_double(default_value),
          .help = std::move(help)};
}

PGM_DECL option_declaration count_option(std::string name, std::size_t default_value, std::string help) {
  const bool unlimited = default_value == std::numeric_limits<std::size_t>::max();
  return {.name = std::move(name),
          .type = option_type::count,
          .default_text = format_option_value(default_value),
          .help = std::move(help),
          .minimum = 0.0,
          .unlimited_allowed = unlimited};
}

PGM_DECL option_declaration flag_option(std::string name, bool default_value, std::string help) {
  return {.name = std::move(name),
          .type = option_type::flag,
          .default_text = default_value ? "true" : "false",
          .help = std::move(help)};
}

PGM_DECL option_declaration word_option(std::string name, std::string default_value, std::vector<std::string> words,
                                        std::string help) {
  PGM_ASSERT(std::find(words.begin(), words.end(), default_value) != words.end(),
             "a word option's default is one of its words");
  return {.name = std::move(name),
          .type = option_type::word,
          .default_text = std::move(default_value),
          .help = std::move(help),
          .words = std::move(words)};
}

PGM_DECL component_spec parse_component_spec(std::string_view text, std::string_view kind) {
  const auto refuse = [&](std::size_t at, const std::string& what) -> model_error {
    return model_error("the " + std::string(kind) + " '" + std::string(text) +
                       "' is not NAME or NAME[KEY=VALUE,...]: " + what + " at column " + std::to_string(at + 1));
  };
  // Trims [first, last) of `text`, returning the piece and where it starts.
  const auto piece = [&](std::size_t first, std::size_t last) {
    while (first < last && std::isspace(static_cast<unsigned char>(text[first]))) ++first;
    while (last > first && std::isspace(static_cast<unsigned char>(text[last - 1]))) --last;
    return std::pair{std::string(text.substr(first, last - first)), first};
  };
  component_spec spec;
  const auto open = text.find('[');
  const auto [name, name_at] = piece(0, open == std::string_view::npos ? text.size() : open);
  if (name.empty()) throw refuse(name_at, "expected a name");
  const auto bad = name.find_first_of("]=,");
  if (bad != std::string::npos) throw refuse(name_at + bad, "unexpected '" + std::string(1, name[bad]) + "'");
  spec.name = name;
  if (open == std::string_view::npos) return spec;

  // The settings' ends: each ',' and the closing ']' outside a value's own brackets.
  std::vector<std::size_t> ends;
  std::size_t depth = 1;
  std::size_t close = text.size();
  for (std::size_t at = open + 1; at < text.size() && close == text.size(); ++at) {
    if (text[at] == '[') ++depth;
    if (text[at] == ']' && --depth == 0) close = at;
    if ((text[at] == ',' && depth == 1) || at == close) ends.push_back(at);
  }
  if (close == text.size()) throw refuse(text.size(), "expected ']'");
  const auto [after, after_at] = piece(close + 1, text.size());
  if (!after.empty()) throw refuse(after_at, "unexpected text after ']'");
  if (piece(open + 1, close).first.empty()) return spec;
  std::size_t first = open + 1;
  for (const auto last : ends) {
    const auto equals = text.find('=', first);
    const auto nested = text.find('[', first);
    if (equals == std::string_view::npos || equals >= last || nested < equals) {
      throw refuse(first, "expected KEY=VALUE");
    }
    const auto [key, key_at] = piece(first, equals);
    const auto [value, value_at] = piece(equals + 1, last);
    if (key.empty()) throw refuse(key_at, "expected an option's name before '='");
    if (value.empty()) throw refuse(value_at, "expected a value for '" + key + "'");
    for (const auto& [seen, unused] : spec.settings) {
      if (seen == key) throw refuse(key_at, "'" + key + "' is set twice");
    }
    spec.settings.emplace_back(key, value);
    first = last + 1;
  }
  return spec;
}

PGM_DECL option_values::option_values(std::vector<option_declaration> declarations)
    : declarations_(std::move(declarations)) {
  values_.reserve(declarations_.size());
  for (const auto& option : declarations_) {
    auto value = detail::read_option_value(option, option.default_text);
    PGM_ASSERT(value.has_value(), "an option's default passes its own check");
    values_.push_back(std::move(*value));
  }
}

PGM_DECL void option_values::set(std::string_view key, std::string_view value, std::string_view kind,
                                 std::string_view name) {
  const auto owner = "the " + std::string(kind) + " '" + std::string(name) + "'";
  const auto at = position(key);
  if (at == declarations_.size()) {
    if (declarations_.empty()) throw model_error(owner + " takes no options, got '" + std::string(key) + "'");
    std::vector<std::string> known;
    for (const auto& option : declarations_) known.push_back(option.name);
    throw unknown_name(std::string(name) + " option", std::string(key), known);
  }
  const auto& option = declarations_[at];
  const auto refusal = option_value_refusal(option, value);
  if (!refusal.empty()) throw model_error("option " + option.name + " of " + owner + refusal);
  values_[at] = *detail::read_option_value(option, value);
}

PGM_DECL std::string option_value_refusal(const option_declaration& option, std::string_view text) {
  try {
    if (detail::read_option_value(option, text)) return {};
  } catch (const error& refused) {
    return std::string(": ") + refused.what();
  }
  return " must be " + option.expected() + ", got " +
         (option.type == option_type::number ? text::quoted_number(text) : "'" + std::string(text) + "'");
}

PGM_DECL std::size_t option_values::position(std::string_view key) const noexcept {
  const auto it = std::find_if(declarations_.begin(), declarations_.end(),
                               [&](const option_declaration& option) { return option.name == key; });
  return static_cast<std::size_t>(it - declarations_.begin());
}

PGM_DECL const option_value& option_values::at(std::string_view key, option_type type) const {
  // A component's own mistake, but one a user's component can make: refused in every build.
  const auto at = position(key);
  if (at == declarations_.size() || declarations_[at].type != type) {
    throw model_error("a component read the option '" + std::string(key) + "', which it did not declare as read");
  }
  return values_[at];
}

PGM_DECL double option_values::number(std::string_view key) const {
  return std::get<double>(at(key, option_type::number));
}

PGM_DECL std::size_t option_values::count(std::string_view key) const {
  return std::get<std::size_t>(at(key, option_type::count));
}

PGM_DECL bool option_values::flag(std::string_view key) const { return std::get<bool>(at(key, option_type::flag)); }

PGM_DECL const std::string& option_values::word(std::string_view key) const {
  return std::get<std::string>(at(key, option_type::word));
}

PGM_DECL const std::string& option_values::component(std::string_view key) const {
  return std::get<std::string>(at(key, option_type::component));
}

PGM_DECL std::string format_option_value(const option_value& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using type = std::decay_t<decltype(v)>;
        if constexpr (std::same_as<type, double>) {
          return text::format_double(v);
        } else if constexpr (std::same_as<type, std::size_t>) {
          return v == std::numeric_limits<std::size_t>::max() ? "unlimited" : std::to_string(v);
        } else if constexpr (std::same_as<type, bool>) {
          return v ? "true" : "false";
        } else {
          return v;
        }
      },
      value);
}

PGM_DECL std::string option_values::text() const {
  std::string result;
  for (std::size_t i = 0; i < declarations_.size(); ++i) {
    if (i > 0) result += ',';
    result += declarations_[i].name + "=" + format_option_value(values_[i]);
  }
  return result;
}

PGM_DECL std::string spec_text(std::string_view name, const option_values& values) {
  if (values.empty()) return std::string(name);
  return std::string(name) + "[" + values.text() + "]";
}

}  // namespace pgm
