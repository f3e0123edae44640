#pragma once
/// \file
/// pgm's JSON model file: variables (states, interval edges, semantic tags), edges and,
/// optionally, tables. A file without tables is a structure (what `learn-structure` writes
/// and `fit --model` reads). Errors name the file and either the line and column (syntax) or
/// the JSON path of the offending value (content). Numbers are written as the shortest text
/// that reads back to the same double.
///
/// {
///   "format": "pgm-model", "version": 1,
///   "variables": [{"name": "xOff1", "states": ["0", "1"], "edges": [-3, 0, 3],
///                  "tags": {"quantity": "x-offset", "unit": "cm", "role": "cubeUp1"}}, …],
///   "edges": [["xOff1", "onTop1"], …],
///   "tables": [{"variable": "onTop1", "parents": ["xOff1"],
///               "values": [[0.1, 0.9], [0.8, 0.2]]}, …],  // one row per configuration
///   "statistics": {…}   // optional: the counts and priors (pgm/io/statistics_json.hpp)
/// }
///
/// A dynamic network (pgm/core/dynamic_network.hpp) says so too, and holds its first slice and
/// its transition, each as edges and tables; the transition's parents are named "X" (this slice)
/// or "X@-1" (the one before):
///
/// {
///   "format": "pgm-model", "version": 1, "kind": "dynamic",
///   "variables": [{"name": "x", "states": ["0", "1"]}, …],
///   "initial": {"edges": [["x", "y"]], "tables": [{"variable": "x", "parents": [], …}, …]},
///   "transition": {"edges": [["x@-1", "x"], ["x", "y"]], "tables": [{"variable": "x", "parents": ["x@-1"], …}, …]},
///   "statistics": {"initial": {…}, "transition": {…}}   // optional, as a static model's
/// }
///
/// A Markov network (a factor graph) says so with "kind" and holds factors instead of edges
/// and tables; a factor's values run over its scope's joint states, the last variable fastest:
///
/// {
///   "format": "pgm-model", "version": 1, "kind": "markov",
///   "variables": [{"name": "a", "states": ["0", "1"]}, …],
///   "factors": [{"scope": ["a", "b"], "values": [1, 2, 3, 4]}, …]   // φ(a0 b0), φ(a0 b1), …
/// }

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/dynamic_network.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/markov_network.hpp"
#include "pgm/core/mixed_radix.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/discretizer.hpp"
#include "pgm/detail/json_reader.hpp"
#include "pgm/io/statistics_json.hpp"
#include "pgm/learn/dynamic_statistics.hpp"
#include "pgm/learn/fit_statistics.hpp"

namespace pgm {

/// What a model file holds: a structure, and tables if it is a fitted network.
struct model_document {
  network_structure structure;
  std::optional<std::vector<cpt<double>>> tables;
  /// The counts and priors the tables were estimated from, when the fit kept them.
  std::optional<fit_statistics> statistics;

  /// The network; throws model_error if the file has no tables.
  [[nodiscard]] bayesian_network network() const {
    if (!tables) throw model_error("the model has a structure but no tables; fit it first");
    return bayesian_network(structure, *tables);
  }
};

namespace detail {

PGM_DECL nlohmann::json variable_to_json(const variable& v);

/// Throws model_error naming `what` when `text` is not UTF-8, which JSON cannot hold.
PGM_DECL void require_utf8(std::string_view text, const std::string& what);

/// A sparse table's entry: "given" (the parents' states of each stored configuration), "values"
/// (their columns) and "rest" (the column of every other configuration).
[[nodiscard]] PGM_DECL cpt<double> read_sparse_table(const json_reader& reader, const nlohmann::json& entry,
                                                     const std::string& path, const variable& child,
                                                     std::vector<variable> parents);

}  // namespace detail

[[nodiscard]] PGM_DECL nlohmann::json to_json(const network_structure& structure,
                                              const std::vector<cpt<double>>* tables = nullptr);

[[nodiscard]] inline nlohmann::json to_json(const bayesian_network& network) {
  return to_json(network.structure(), &network.tables());
}

/// Writes a Markov network as pgm's JSON model ("kind": "markov"), streamed: a factor to a line,
/// no document built in memory first, each number the shortest text that reads back the same.
PGM_DECL void write_markov_json(std::ostream& out, const markov_network& model);

/// Whether the text of a pgm JSON model declares a Markov network ("kind": "markov"); text that
/// is not such a model is left for its parser to name what is wrong.
[[nodiscard]] PGM_DECL bool declares_markov_network(std::string_view text);

/// The "kind" a pgm JSON model declares: "bayesian" (also when it declares none, or the text is
/// not a JSON object: the reader then says what is wrong), "markov" or "dynamic".
[[nodiscard]] PGM_DECL std::string declared_model_kind(std::string_view text);

/// A dynamic network as pgm's JSON model ("kind": "dynamic"), with the counts and priors it was
/// estimated from when given: "statistics": {"initial": {…}, "transition": {…}}, each as a
/// static model's (pgm/io/statistics_json.hpp), the transition's one family per template
/// variable.
[[nodiscard]] PGM_DECL nlohmann::json to_json(const dynamic_network& model,
                                              const dynamic_fit_statistics* statistics = nullptr);

/// Writes a dynamic network's JSON model to `path`, atomically (nothing is left half-written);
/// `before_replacing` runs once the new file is complete, before it replaces `path`, and may fail
/// the write (write_file_atomically).
PGM_DECL void write_dynamic_json(const dynamic_network& model, const std::filesystem::path& path,
                                 const std::function<void()>& before_replacing = {},
                                 const dynamic_fit_statistics* statistics = nullptr);

/// A dynamic network read from pgm's JSON model, with its statistics when the file keeps them.
struct dynamic_model_file {
  dynamic_network model;
  std::optional<dynamic_fit_statistics> statistics;
};

/// Reads a dynamic network; errors name the source and the JSON path of what is wrong.
[[nodiscard]] PGM_DECL dynamic_model_file parse_dynamic_model_json(std::string_view text, const std::string& source);

/// The network alone.
[[nodiscard]] PGM_DECL dynamic_network parse_dynamic_json(std::string_view text, const std::string& source);

namespace detail {

/// The "statistics" of a dynamic model file, over `model`'s families.
[[nodiscard]] PGM_DECL dynamic_fit_statistics parse_dynamic_statistics(const json_reader& reader,
                                                                       const nlohmann::json& value,
                                                                       const dynamic_network& model);

}  // namespace detail

/// A Markov network from pgm's JSON model; errors name the JSON path (an unknown variable in a
/// scope, a variable twice in one, values of the wrong number, negative or not finite).
[[nodiscard]] PGM_DECL markov_network parse_markov_json(std::string_view text, const std::string& source);

/// The network with the counts and priors it was estimated from.
[[nodiscard]] PGM_DECL nlohmann::json to_json(const bayesian_network& network, const fit_statistics& statistics);

/// Writes the network (and its statistics, when given) as pgm's JSON model, streamed: the same
/// text as to_json(...).dump(2) and a newline, without the document built in memory first (a
/// table of 10⁶ stored configurations as a JSON tree takes tens of bytes a number).
PGM_DECL void write_model_json(std::ostream& out, const bayesian_network& network,
                               const fit_statistics* statistics = nullptr);

[[nodiscard]] PGM_DECL model_document parse_model_json(std::string_view text, const std::string& source);

[[nodiscard]] inline model_document read_model_json(const std::filesystem::path& path) {
  return parse_model_json(pgm::read_file(path), path.string());
}

/// Writes `document` to `path` atomically; `before_replacing` as write_file_atomically's.
inline void write_model_json(const nlohmann::json& document, const std::filesystem::path& path,
                             const std::function<void()>& before_replacing = {}) {
  const auto text = document.dump(2) + "\n";
  pgm::write_file_atomically(
      path, [&](std::ostream& out) { out << text; }, before_replacing);
}

// ---- discretization files ------------------------------------------------------------------

[[nodiscard]] PGM_DECL nlohmann::json to_json(const discretization& d);

[[nodiscard]] PGM_DECL discretization parse_discretization_json(std::string_view text, const std::string& source);

[[nodiscard]] inline discretization read_discretization_json(const std::filesystem::path& path) {
  return parse_discretization_json(pgm::read_file(path), path.string());
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/io/impl/json_model.ipp"
#endif
