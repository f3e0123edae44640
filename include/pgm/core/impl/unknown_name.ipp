#pragma once
// The definitions of pgm/core/unknown_name.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/core/unknown_name.hpp"

namespace pgm {

PGM_DECL unknown_name::unknown_name(std::string kind, std::string name, std::vector<std::string> known,
                                    const std::string& where)
    : error(message(kind, name, known, where)),
      kind_(std::move(kind)),
      name_(std::move(name)),
      known_(std::move(known)),
      suggestion_(text::closest_name(name_, known_)) {}

PGM_DECL std::string unknown_name::message(const std::string& kind, const std::string& name,
                                           const std::vector<std::string>& known, const std::string& where) {
  const auto near = text::closest_name(name, known);
  return "unknown " + kind + " '" + name + "'" + (near ? "; did you mean '" + *near + "'?" : "") +
         " (known: " + text::list_for_message(known, 40) + (where.empty() ? "" : "; " + where) + ")";
}

}  // namespace pgm
