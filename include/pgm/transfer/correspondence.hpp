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

#include "pgm/core/error.hpp"
#include "pgm/detail/text.hpp"

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
  [[nodiscard]] std::optional<std::string> related_to(std::string_view target) const {
    const auto it = related.find(target);
    if (it == related.end()) return std::nullopt;
    return it->second;
  }

  friend bool operator==(const correspondence&, const correspondence&) = default;
};

/// Parses "onTop2=onTop1, xOff2~xOff1, xOffset==xOff1, yOff1@0, yOff2@*". Throws model_error
/// naming the malformed entry.
[[nodiscard]] inline correspondence parse_correspondence(std::string_view text) {
  correspondence map;
  std::size_t position = 0;
  for (const auto& raw : detail::split(text, ',')) {
    ++position;
    const std::string entry(detail::trim(raw));
    auto fail = [&](const std::string& why) -> void {
      throw model_error("map entry " + std::to_string(position) + " ('" + entry + "') " + why +
                        "; expected 'target=prior', 'target~prior', 'target==prior' or "
                        "'prior@value'");
    };
    auto pair_at = [&](std::size_t at, std::size_t width) {
      std::string left(detail::trim(std::string_view(entry).substr(0, at)));
      std::string right(detail::trim(std::string_view(entry).substr(at + width)));
      if (left.empty() || right.empty()) fail("lacks a name");
      return std::pair{std::move(left), std::move(right)};
    };
    auto insert = [&](auto& into, std::pair<std::string, std::string> names, const char* kind) {
      if (!into.emplace(names.first, names.second).second) {
        fail("gives '" + names.first + "' a second " + kind + " counterpart");
      }
    };
    if (entry.empty()) fail("is empty");
    const auto pin_at = entry.find('@');
    const auto identical_at = entry.find("==");
    const auto related_at = entry.find('~');
    const auto transferred_at = entry.find('=');
    if (pin_at != std::string::npos) {
      auto [variable, value] = pair_at(pin_at, 1);
      if (!map.pinned.emplace(variable, prior_pin{value == "*" ? std::string() : value}).second) {
        fail("pins '" + variable + "' twice");
      }
    } else if (identical_at != std::string::npos) {
      insert(map.identical, pair_at(identical_at, 2), "identical");
    } else if (related_at != std::string::npos) {
      insert(map.related, pair_at(related_at, 1), "related");
    } else if (transferred_at != std::string::npos) {
      insert(map.transferred, pair_at(transferred_at, 1), "transferred");
    } else {
      fail("has no '=', '~', '==' or '@'");
    }
  }
  if (map.transferred.empty()) {
    throw model_error("the map names no transferred node: add 'target=prior', e.g. 'onTop2=onTop1'");
  }
  return map;
}

/// The map in the syntax parse_correspondence reads.
[[nodiscard]] inline std::string to_string(const correspondence& map) {
  std::vector<std::string> entries;
  for (const auto& [t, p] : map.transferred) entries.push_back(t + "=" + p);
  for (const auto& [t, p] : map.identical) entries.push_back(t + "==" + p);
  for (const auto& [t, p] : map.related) entries.push_back(t + "~" + p);
  for (const auto& [p, pin] : map.pinned) entries.push_back(p + "@" + (pin.marginalize() ? "*" : pin.value));
  return detail::join(entries, ",");
}

}  // namespace pgm
