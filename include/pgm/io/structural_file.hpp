#pragma once
/// \file
/// Structural models (pgm/core/structural_model.hpp) in pgm's JSON model, "kind": "structural".
/// The variables are listed as a network's; each equation gives the variable's parents, its
/// noise's distribution and the function, a row per configuration of the parents (the last
/// parent fastest) holding the state taken at each noise state:
///
/// {
///   "format": "pgm-model", "version": 1, "kind": "structural",
///   "variables": [{"name": "X", "states": ["0", "1"]}, {"name": "Y", "states": ["0", "1"]}],
///   "equations": [
///     {"variable": "X", "parents": [], "noise": [0.4, 0.6], "values": [["0", "1"]]},
///     {"variable": "Y", "parents": ["X"], "noise": [0.2, 0.5, 0.3],
///      "values": [["0", "0", "1"], ["0", "1", "1"]]}
///   ]
/// }
///
/// Y is 1 at the third noise state whatever X is, and at the second only when X is 1. Errors
/// name the file and the JSON path of what is wrong.

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <string_view>

#include "pgm/core/compilation.hpp"
#include "pgm/core/structural_model.hpp"

namespace pgm {

/// The document, its keys in the order above.
[[nodiscard]] PGM_DECL nlohmann::ordered_json to_json(const structural_model& model);

/// Writes the document a variable and an equation to a line.
PGM_DECL void write_structural_json(std::ostream& out, const structural_model& model);

[[nodiscard]] PGM_DECL structural_model parse_structural_json(std::string_view text, const std::string& source);

/// Whether `path` holds a structural model: a pgm JSON model (.json, .json.gz) of that kind.
[[nodiscard]] PGM_DECL bool holds_structural_model(const std::filesystem::path& path);

/// Reads a structural model from pgm's JSON model.
[[nodiscard]] PGM_DECL structural_model read_structural_model(const std::filesystem::path& path);

/// Writes pgm's JSON model of `model`, atomically; `before_replacing` runs once all is written.
PGM_DECL void write_structural_model(const structural_model& model, const std::filesystem::path& path,
                                     const std::function<void()>& before_replacing = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/io/impl/structural_file.ipp"
#endif
