#pragma once
/// \file
/// `unknown_name`: the one error for a name that is none of the known ones — a transfer
/// strategy, an inference engine, an independence test, a score, a file format, a task, a
/// scenario, a metric. Its message says what was looked for, the closest known name when one
/// is near, and every known name, the same way everywhere:
/// "unknown independence test 'chi'; did you mean 'chi2'? (known: chi2, g2)".

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"

namespace pgm {

class unknown_name : public error {
 public:
  /// `kind` is what the name was to name ("independence test"); `known` the names it could be,
  /// in the order to list them; `where`, if not empty, is added to the message in parentheses
  /// after the list (e.g. the folders a task was looked for in).
  PGM_DECL unknown_name(std::string kind, std::string name, std::vector<std::string> known,
                        const std::string& where = {});

  [[nodiscard]] const std::string& kind() const noexcept { return kind_; }
  [[nodiscard]] const std::string& name() const noexcept { return name_; }
  [[nodiscard]] const std::vector<std::string>& known() const noexcept { return known_; }
  /// The known name `name()` was most likely meant to be, if one is close.
  [[nodiscard]] const std::optional<std::string>& suggestion() const noexcept { return suggestion_; }

 private:
  PGM_DECL static std::string message(const std::string& kind, const std::string& name,
                                      const std::vector<std::string>& known, const std::string& where);

  std::string kind_;
  std::string name_;
  std::vector<std::string> known_;
  std::optional<std::string> suggestion_;
};

/// A user-facing choice (an enum) and the list of its values, each spelled by its `to_string`,
/// found by argument-dependent lookup beside the enum: what the parse_… and known_… functions
/// of every choice are made of.
template <class Choice, std::size_t N>
[[nodiscard]] std::vector<std::string> names_of(const std::array<Choice, N>& values) {
  std::vector<std::string> names;
  names.reserve(N);
  for (const auto value : values) names.emplace_back(to_string(value));
  return names;
}

/// The value of `values` spelled `text`; throws unknown_name for `kind` listing them otherwise.
template <class Choice, std::size_t N>
[[nodiscard]] Choice parse_choice(const std::string& kind, std::string_view text, const std::array<Choice, N>& values) {
  for (const auto value : values) {
    if (text == to_string(value)) return value;
  }
  throw unknown_name(kind, std::string(text), names_of(values));
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/unknown_name.ipp"
#endif
