#pragma once
/// \file
/// Influence diagrams in files: XMLBIF (pgm/io/xmlbif.hpp, as aGrUM writes them) or pgm's JSON
/// model of "kind": "influence", chosen by the extension. The JSON form lists the chance and
/// decision variables as a network's are listed, the chance tables as a network's (one row per
/// configuration of the parents, the last parent fastest), what each decision observes, and the
/// utilities (one value per configuration of their parents):
///
/// {
///   "format": "pgm-model", "version": 1, "kind": "influence",
///   "variables": [{"name": "Oil", "states": ["dry", "wet", "soaking"]}, {"name": "Drill", …}, …],
///   "tables": [{"variable": "Oil", "parents": [], "values": [[0.5, 0.3, 0.2]]}, …],
///   "decisions": [{"variable": "Drill", "observes": ["Test", "Seismic"]}, …],
///   "utilities": [{"name": "Payoff", "parents": ["Drill", "Oil"], "values": [-70, 50, 200, 0, 0, 0]}, …]
/// }
///
/// Errors name the file and the JSON path of what is wrong.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "pgm/core/compilation.hpp"
#include "pgm/core/influence_diagram.hpp"

namespace pgm {

[[nodiscard]] PGM_DECL nlohmann::json to_json(const influence_diagram& diagram);

[[nodiscard]] PGM_DECL influence_diagram parse_influence_json(std::string_view text, const std::string& source);

/// Reads a .json influence diagram as pgm's JSON model, any other as XMLBIF.
[[nodiscard]] PGM_DECL influence_diagram read_influence_diagram(const std::filesystem::path& path);

/// Writes a .json path as pgm's JSON model, any other as XMLBIF; atomically.
PGM_DECL void write_influence_diagram(const influence_diagram& diagram, const std::filesystem::path& path);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/io/impl/influence_file.ipp"
#endif
