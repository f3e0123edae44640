#pragma once
/// \file
/// A fitted network's counts and priors (pgm/learn/fit_statistics.hpp) in pgm's JSON model
/// file, under the key "statistics", so that `pgm update` can add new data to them:
///
/// "statistics": {
///   "rows": 1000, "empty": "uniform",
///   "families": [{"variable": "onTop1",
///                 "counts": [[12, 3], [0, 7]],          // one row per parent configuration
///                 "prior": {"kind": "bdeu", "ess": 1}}, …]   // one per node, in node order
/// }
///
/// A prior is {"kind": "none"}, {"kind": "dirichlet", "alpha": a}, {"kind": "k2"},
/// {"kind": "bdeu", "ess": s}, {"kind": "pseudo-counts", "alpha": rows} or, transferred (eq. 8),
/// {"kind": "weighted", "w": w, "table": rows}. Numbers are written as the shortest text that
/// reads back to the same double, so a file read back estimates the same tables to the last bit.

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/detail/json_reader.hpp"
#include "pgm/learn/fit_statistics.hpp"
#include "pgm/learn/parameter_prior_registry.hpp"

namespace pgm {
namespace detail {

/// Values laid out configuration by configuration, `width` to a row.
[[nodiscard]] PGM_DECL nlohmann::json rows_of(std::span<const double> values, std::size_t width);

[[nodiscard]] PGM_DECL nlohmann::json prior_to_json(const parameter_prior& prior, const expected_count_table& family);

/// `rows` read as one value per cell of `family`, each finite and >= 0.
[[nodiscard]] PGM_DECL std::vector<double> cells_of(const json_reader& reader, const nlohmann::json& rows,
                                                    const std::string& path, const expected_count_table& family);

[[nodiscard]] PGM_DECL parameter_prior prior_from_json(const json_reader& reader, const nlohmann::json& value,
                                                       const std::string& path, const expected_count_table& family);

}  // namespace detail

[[nodiscard]] PGM_DECL nlohmann::json to_json(const fit_statistics& statistics);

/// The "statistics" of a model file over `structure`: one family per node, in node order.
[[nodiscard]] PGM_DECL fit_statistics parse_statistics_json(const detail::json_reader& reader,
                                                            const nlohmann::json& value,
                                                            const network_structure& structure);

/// The statistics at JSON path `path`, one family per entry of `families` (empty count tables
/// of each family's shape), in that order.
[[nodiscard]] PGM_DECL fit_statistics parse_statistics_json(const detail::json_reader& reader,
                                                            const nlohmann::json& value, const std::string& path,
                                                            std::vector<expected_count_table> families);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/io/impl/statistics_json.ipp"
#endif
