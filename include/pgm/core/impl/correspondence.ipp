#pragma once
// The definitions of pgm/core/correspondence.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/core/correspondence.hpp"

namespace pgm {

PGM_DECL std::optional<std::string> correspondence::related_to(std::string_view target) const {
  const auto it = related.find(target);
  if (it == related.end()) return std::nullopt;
  return it->second;
}

PGM_DECL correspondence parse_correspondence(std::string_view text) {
  correspondence map;
  std::size_t position = 0;
  for (const auto& raw : text::split(text, ',')) {
    ++position;
    const std::string entry(text::trim(raw));
    auto fail = [&](const std::string& why) -> void {
      throw model_error("map entry " + std::to_string(position) + " ('" + entry + "') " + why +
                        "; expected 'target=prior', 'target~prior', 'target==prior' or "
                        "'prior@value'");
    };
    auto pair_at = [&](std::size_t at, std::size_t width) {
      std::string left(text::trim(std::string_view(entry).substr(0, at)));
      std::string right(text::trim(std::string_view(entry).substr(at + width)));
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
    // A pair before a pin: a target name may hold '@' (a dynamic network's previous slice,
    // 'xOff@-1~xOff1'), a pin's value holds no '=' or '~'.
    if (identical_at != std::string::npos) {
      insert(map.identical, pair_at(identical_at, 2), "identical");
    } else if (related_at != std::string::npos) {
      insert(map.related, pair_at(related_at, 1), "related");
    } else if (transferred_at != std::string::npos) {
      insert(map.transferred, pair_at(transferred_at, 1), "transferred");
    } else if (pin_at != std::string::npos) {
      auto [variable, value] = pair_at(pin_at, 1);
      if (!map.pinned.emplace(variable, prior_pin{value == "*" ? std::string() : value}).second) {
        fail("pins '" + variable + "' twice");
      }
    } else {
      fail("has no '=', '~', '==' or '@'");
    }
  }
  if (map.transferred.empty()) {
    throw model_error("the map names no transferred node: add 'target=prior', e.g. 'onTop2=onTop1'");
  }
  return map;
}

PGM_DECL std::string to_string(const correspondence& map) {
  std::vector<std::string> entries;
  for (const auto& [t, p] : map.transferred) entries.push_back(t + "=" + p);
  for (const auto& [t, p] : map.identical) entries.push_back(t + "==" + p);
  for (const auto& [t, p] : map.related) entries.push_back(t + "~" + p);
  for (const auto& [p, pin] : map.pinned) entries.push_back(p + "@" + (pin.marginalize() ? "*" : pin.value));
  return text::join(entries, ",");
}

}  // namespace pgm
