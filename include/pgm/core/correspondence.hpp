#pragma once
/// \file
/// A correspondence map between the variables of a prior task T′ and a target task T (paper
/// Sec. III-B): the transferred node pairs (`onTop2 = onTop1`), *identical* variables (same
/// name, or overridden with `xOffset == xOff1`), *related* ones (`xOff2 ~ xOff1`: the same
/// quantity on another object), and prior parents that no strategy assigns, pinned to a value
/// (`yOff1 @ 0`) or marginalized (`yOff1 @ *`). Target names are on the left, prior names on
/// the right.

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"

namespace pgm {

/// What to do with a prior parent that a strategy leaves unassigned.
struct prior_pin {
  /// A state label or a number on the variable's scale; empty: marginalize with the prior
  /// network's distribution of the variable.
  std::string value;
  [[nodiscard]] bool marginalize() const noexcept { return value.empty(); }
  friend bool operator==(const prior_pin&, const prior_pin&) = default;
};

struct correspondence {
  /// Target node → prior node whose table is transferred.
  std::map<std::string, std::string, std::less<>> transferred;
  /// Target variable → prior variable that means the same; variables with equal names match
  /// without an entry.
  std::map<std::string, std::string, std::less<>> identical;
  /// Target variable → prior variable of the same quantity on another object.
  std::map<std::string, std::string, std::less<>> related;
  /// Prior variable → its value wherever a strategy does not assign it.
  std::map<std::string, prior_pin, std::less<>> pinned;

  /// The prior variable identical to a target variable: an override, else the same name.
  [[nodiscard]] std::string identical_to(std::string_view target) const {
    const auto it = identical.find(target);
    return it == identical.end() ? std::string(target) : it->second;
  }
  [[nodiscard]] PGM_DECL std::optional<std::string> related_to(std::string_view target) const;

  friend bool operator==(const correspondence&, const correspondence&) = default;
};

/// Parses "onTop2=onTop1, xOff2~xOff1, xOffset==xOff1, yOff1@0, yOff2@*". Throws model_error
/// naming the malformed entry.
[[nodiscard]] PGM_DECL correspondence parse_correspondence(std::string_view text);

/// The map in the syntax parse_correspondence reads.
[[nodiscard]] PGM_DECL std::string to_string(const correspondence& map);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/correspondence.ipp"
#endif
