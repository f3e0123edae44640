#pragma once
/// \file
/// A posterior P(query | evidence) as a table for people and programs: every joint state of
/// the query variables with its probability, as CSV or JSON, to a chosen number of significant
/// digits (17 reads back to the same double). Also the parsers of the command line's
/// `--query X,Y` and `--evidence a=s,b=t`, so that `pgm query` is argument parsing plus one call.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/error.hpp"
#include "pgm/data/csv.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/inference/variable_elimination.hpp"

namespace pgm {

enum class posterior_format { csv, json };

/// Parses "csv" or "json"; throws model_error otherwise.
[[nodiscard]] inline posterior_format parse_posterior_format(std::string_view text) {
  if (text == "csv") return posterior_format::csv;
  if (text == "json") return posterior_format::json;
  throw model_error("unknown output format '" + std::string(text) + "' (known: csv, json)");
}

/// How a posterior is written.
struct posterior_table_options {
  posterior_format format = posterior_format::csv;
  /// Significant digits of each probability, 1 to 17; 17 reads back to the same double.
  int digits = 6;
};

/// "X,Y" → {"X", "Y"}. Throws model_error for an empty list or an empty name; unknown and
/// repeated names are reported by `query`.
[[nodiscard]] inline std::vector<std::string> parse_query_variables(std::string_view text) {
  auto names = detail::split(text, ',');
  if (names.empty()) throw model_error("the query names no variable; give one or more, e.g. --query X,Y");
  for (const auto& name : names) {
    if (name.empty()) throw model_error("the query '" + std::string(text) + "' has an empty variable name");
  }
  return names;
}

/// "a=s,b=t" → {a: s, b: t}; an empty text is no evidence. Throws model_error for a piece
/// that is not name=state or a variable observed twice; unknown variables and states are
/// reported by `query`.
[[nodiscard]] inline evidence parse_evidence(std::string_view text) {
  evidence result;
  for (const auto& piece : detail::split(text, ',')) {
    const auto equals = piece.find('=');
    const auto name =
        equals == std::string::npos ? std::string_view{} : detail::trim(std::string_view(piece).substr(0, equals));
    const auto state =
        equals == std::string::npos ? std::string_view{} : detail::trim(std::string_view(piece).substr(equals + 1));
    if (name.empty() || state.empty()) {
      throw model_error("the evidence '" + piece + "' is not of the form variable=state");
    }
    if (!result.emplace(std::string(name), std::string(state)).second) {
      throw model_error("'" + std::string(name) + "' is observed twice in the evidence");
    }
  }
  return result;
}

namespace detail {

[[nodiscard]] inline std::string format_probability(double value, int digits) {
  if (digits < 1 || digits > 17) {
    throw model_error("digits must be between 1 and 17, got " + std::to_string(digits));
  }
  return format_short(value, digits);
}

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

/// Writes `p`: CSV has a column per query variable then `probability`, one row per joint
/// state; JSON is {"query": [...], "evidence": {...}, "evidence_probability": P(e),
/// "distribution": [{"X": state, ..., "probability": p}, ...]}. Rows in table order, the last
/// query variable fastest. Throws model_error for digits outside 1..17 or a query variable
/// named "probability".
inline void write_posterior_table(std::ostream& out, const posterior& p, const evidence& observed,
                                  const posterior_table_options& options = {}) {
  const auto number = [&](double v) { return detail::format_probability(v, options.digits); };
  static_cast<void>(number(0.0));  // check the digits before writing anything
  for (const auto& v : p.variables) {
    if (v.name() == "probability") {
      throw model_error("the query variable 'probability' would share its name with the probability column");
    }
  }
  std::string text;
  if (options.format == posterior_format::csv) {
    for (const auto& v : p.variables) text += detail::csv_escape(v.name(), ',') + ",";
    text += "probability\n";
    detail::for_each_joint_state(p, [&](const std::vector<std::size_t>& codes, double value) {
      for (std::size_t k = 0; k < codes.size(); ++k) {
        text += detail::csv_escape(p.variables[k].states()[codes[k]], ',') + ",";
      }
      text += number(value) + "\n";
    });
  } else {
    const auto quoted = [](const std::string& s) { return nlohmann::json(s).dump(); };
    text += "{\n  \"query\": [";
    for (std::size_t k = 0; k < p.variables.size(); ++k) text += (k ? ", " : "") + quoted(p.variables[k].name());
    text += "],\n  \"evidence\": {";
    bool first = true;
    for (const auto& [name, state] : observed) {
      text += (first ? "" : ", ") + quoted(name) + ": " + quoted(state);
      first = false;
    }
    text += "},\n  \"evidence_probability\": " + number(p.evidence_probability) + ",\n  \"distribution\": [";
    first = true;
    detail::for_each_joint_state(p, [&](const std::vector<std::size_t>& codes, double value) {
      text += first ? "\n    {" : ",\n    {";
      first = false;
      for (std::size_t k = 0; k < codes.size(); ++k) {
        text += quoted(p.variables[k].name()) + ": " + quoted(p.variables[k].states()[codes[k]]) + ", ";
      }
      text += "\"probability\": " + number(value) + "}";
    });
    text += "\n  ]\n}\n";
  }
  out << text;
}

}  // namespace pgm
