#pragma once
/// \file
/// A posterior P(query | evidence) as a table for people and programs: every joint state of
/// the query variables with its probability (and its standard error, for sampling engines), as
/// CSV or JSON, to a chosen number of significant digits (17 reads back to the same double);
/// likewise every marginal at once and the most probable explanation. Also the parsers of the
/// command line's `--query X,Y`, `--evidence a=s,b=t` and `--soft X=0.2:0.8`, so that
/// `pgm query` is argument parsing plus one call.

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/inference/query.hpp"

namespace pgm {

enum class posterior_format { csv, json };

[[nodiscard]] constexpr std::string_view to_string(posterior_format format) noexcept {
  return format == posterior_format::json ? "json" : "csv";
}

inline constexpr std::array posterior_formats{posterior_format::csv, posterior_format::json};

/// The output formats' names, for messages and the command line's allowed values.
[[nodiscard]] inline std::vector<std::string> known_posterior_formats() { return names_of(posterior_formats); }

/// Parses "csv" or "json"; throws unknown_name otherwise.
[[nodiscard]] inline posterior_format parse_posterior_format(std::string_view text) {
  return parse_choice("output format", text, posterior_formats);
}

/// How a posterior is written.
struct posterior_table_options {
  posterior_format format = posterior_format::csv;
  /// Significant digits of each probability, 1 to 17; 17 reads back to the same double.
  int digits = 6;
};

/// "X,Y" → {"X", "Y"}. Throws model_error for an empty list or an empty name; unknown and
/// repeated names are reported by `query`.
[[nodiscard]] PGM_DECL std::vector<std::string> parse_query_variables(std::string_view text);

/// "a=s,b=t" → {a: s, b: t}; an empty text is no evidence. Throws model_error for a piece
/// that is not name=state or a variable observed twice; unknown variables and states are
/// reported by `query`.
[[nodiscard]] PGM_DECL evidence parse_evidence(std::string_view text);

/// "X=x,Z=z" → do(X = x, Z = z), as --do spells interventions; an empty text is none. Throws
/// model_error for a piece that is not name=state or a variable set twice.
[[nodiscard]] PGM_DECL intervention parse_intervention(std::string_view text);

/// "X=0.2:0.8,Y=1:2:0" → {X: [0.2, 0.8], Y: [1, 2, 0]}, one weight per state in the variable's
/// order; an empty text is none. Throws model_error for a piece that is not name=w:w…, a weight
/// that is not a finite number, or a variable given twice; the weights' count and values are
/// checked against the network by resolve_evidence.
[[nodiscard]] PGM_DECL soft_evidence parse_soft_evidence(std::string_view text);

namespace detail {

[[nodiscard]] PGM_DECL std::string format_probability(double value, int digits);

/// Calls `row(codes, probability)` for every joint state, the last variable fastest (the
/// order of the posterior's table).
template <class Row>
void for_each_joint_state(const posterior& p, Row&& row) {
  std::vector<std::size_t> codes(p.variables.size(), 0);
  const auto& values = p.table.values();
  for (std::size_t i = 0; i < values.size(); ++i) {
    row(codes, values[i]);
    for (std::size_t k = codes.size(); k-- > 0;) {
      if (++codes[k] < p.variables[k].cardinality()) break;
      codes[k] = 0;
    }
  }
}

}  // namespace detail

namespace detail {

[[nodiscard]] inline std::string json_text(const std::string& s) { return nlohmann::json(s).dump(); }

/// `"evidence": {...}` and, when there is any, `"soft_evidence": {...}` and `"do": {...}`, each
/// with a leading two-space indent and a trailing ",\n".
[[nodiscard]] PGM_DECL std::string json_evidence(const evidence& observed, const soft_evidence& soft,
                                                 const std::function<std::string(double)>& number,
                                                 const intervention& set = {});

PGM_DECL void check_table_options(const posterior_table_options& options, std::span<const variable> variables);

}  // namespace detail

/// Writes `p`: CSV has a column per query variable then `probability` (and `standard_error`
/// for a sampling engine), one row per joint state; JSON is {"query": [...], "evidence": {...},
/// ["soft_evidence": {...},] "evidence_probability": P(e), "engine": name, "distribution":
/// [{"X": state, ..., "probability": p[, "standard_error": se]}, ...]}. Rows in table order,
/// the last query variable fastest. Throws model_error for digits outside 1..17 or a query
/// variable named like a column.
PGM_DECL void write_posterior_table(std::ostream& out, const posterior& p, const evidence& observed,
                                    const posterior_table_options& options = {}, const soft_evidence& soft = {},
                                    const intervention& set = {});

/// Writes every marginal of `marginals`: CSV `variable,state,probability[,standard_error]`, one
/// row per state; JSON {"evidence": …, "evidence_probability": P(e), "engine": name,
/// "marginals": {"X": {"state": p, …}, …}[, "standard_errors": {…}]}.
PGM_DECL void write_marginals_table(std::ostream& out, const std::vector<posterior>& marginals,
                                    const evidence& observed, const posterior_table_options& options = {},
                                    const soft_evidence& soft = {}, const intervention& set = {});

/// Writes the most probable explanation: CSV a column per variable then `probability`
/// (P(states | evidence)), one row; JSON {"evidence": …, "mpe": {"X": state, …},
/// "probability": P(states | e), "joint_probability": P(states, e), "log_probability": ln of
/// the joint, "engine": name}.
PGM_DECL void write_mpe_table(std::ostream& out, const mpe_result& best, const evidence& observed,
                              const posterior_table_options& options = {}, const soft_evidence& soft = {},
                              const intervention& set = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/inference/impl/posterior_table.ipp"
#endif
