#pragma once
// The definitions of pgm/io/query_batch.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/io/query_batch.hpp"

namespace pgm {

PGM_DECL query_batch_reader::query_batch_reader(std::string_view text, std::string source)
    : scanner_(text, std::move(source), ',') {
  const auto& name = scanner_.source();
  if (!scanner_.next(fields_))
    throw parse_error(name, 1, 1, "the query file is empty; its header names a 'query' column");
  bool has_query = false;
  for (const auto& f : fields_) {
    const std::optional<column> which = f.text == "query"      ? column::query
                                        : f.text == "evidence" ? column::observed
                                        : f.text == "soft"     ? column::soft
                                        : f.text == "do"       ? column::intervened
                                        : f.text == "engine"   ? std::optional(column::engine)
                                                               : std::nullopt;
    if (!which) {
      throw parse_error(name, f.line, f.column,
                        "unknown column '" + std::string(f.text) + "' (known: query, evidence, soft, do, engine)");
    }
    if (std::find(columns_.begin(), columns_.end(), *which) != columns_.end()) {
      throw parse_error(name, f.line, f.column, "the column '" + std::string(f.text) + "' is named twice");
    }
    has_query = has_query || which == column::query;
    columns_.push_back(*which);
  }
  if (!has_query) throw parse_error(name, 1, 1, "the header names no 'query' column");
}

PGM_DECL bool query_batch_reader::next(query_request& request) {
  const auto& name = scanner_.source();
  if (!scanner_.next(fields_)) {
    if (records_ == 0) throw parse_error(name, scanner_.line(), 1, "the query file holds a header but no query");
    return false;
  }
  if (fields_.size() > columns_.size()) {
    const auto& extra = fields_[columns_.size()];
    throw parse_error(
        name, extra.line, extra.column,
        "this record has " + std::to_string(fields_.size()) + " fields, the header " + std::to_string(columns_.size()));
  }
  request = query_request{};
  request.line = scanner_.record_line();
  for (std::size_t k = 0; k < fields_.size(); ++k) {
    const auto& f = fields_[k];
    try {
      switch (columns_[k]) {
        case column::query:
          request.query_text = std::string(f.text);
          request.query = parse_query_variables(f.text);
          break;
        case column::observed:
          request.evidence_text = std::string(f.text);
          request.observed = parse_evidence(f.text);
          break;
        case column::soft:
          request.soft_text = std::string(f.text);
          request.soft = parse_soft_evidence(f.text);
          break;
        case column::intervened:
          request.do_text = std::string(f.text);
          request.intervened = parse_intervention(f.text);
          break;
        case column::engine:
          request.engine = std::string(text::trim(f.text));
          break;
      }
    } catch (const model_error& e) {
      throw parse_error(name, f.line, f.column, e.what());
    }
  }
  if (request.query.empty()) throw parse_error(name, request.line, 1, "the record names no query variable");
  ++records_;
  return true;
}

PGM_DECL std::vector<query_request> parse_query_batch(std::string_view text, const std::string& source) {
  query_batch_reader reader(text, source);
  std::vector<query_request> requests;
  for (query_request request; reader.next(request);) requests.push_back(std::move(request));
  return requests;
}

PGM_DECL void write_impossible_record(std::ostream& out, const query_request& request, const std::string& engine,
                                      const std::string& reason, const posterior_table_options& options, bool header) {
  std::string text;
  if (options.format == posterior_format::csv) {
    if (header) text += "line,query,evidence,soft,do,engine,evidence_probability,distribution\n";
    text += std::to_string(request.line) + "," + text::csv_escape(request.query_text, ',') + "," +
            text::csv_escape(request.evidence_text, ',') + "," + text::csv_escape(request.soft_text, ',') + "," +
            text::csv_escape(request.do_text, ',') + "," + text::csv_escape(engine, ',') + ",0,\n";
  } else {
    const auto quoted = [](const std::string& s) { return nlohmann::json(s).dump(); };
    text += "{\"line\": " + std::to_string(request.line) + ", \"query\": " + nlohmann::json(request.query).dump() +
            ", \"evidence\": " + nlohmann::json(request.observed).dump() + ", \"engine\": " + quoted(engine) +
            ", \"evidence_probability\": 0, \"error\": " + quoted(reason) + "}\n";
  }
  out << text;
}

PGM_DECL void write_query_record(std::ostream& out, const query_request& request, const posterior& answer,
                                 const posterior_table_options& options, bool header) {
  const auto number = [&](double v) { return detail::format_probability(v, options.digits); };
  std::string text;
  if (options.format == posterior_format::csv) {
    if (header) text += "line,query,evidence,soft,do,engine,evidence_probability,distribution\n";
    std::string distribution;
    detail::for_each_joint_state(answer, [&](const std::vector<std::size_t>& codes, double value) {
      if (!distribution.empty()) distribution += ';';
      for (std::size_t k = 0; k < codes.size(); ++k) {
        distribution += (k ? "&" : "") + answer.variables[k].states()[codes[k]];
      }
      distribution += "=" + number(value);
    });
    text += std::to_string(request.line) + "," + text::csv_escape(request.query_text, ',') + "," +
            text::csv_escape(request.evidence_text, ',') + "," + text::csv_escape(request.soft_text, ',') + "," +
            text::csv_escape(request.do_text, ',') + "," + text::csv_escape(answer.engine, ',') + "," +
            number(answer.evidence_probability) + "," + text::csv_escape(distribution, ',') + "\n";
  } else {
    const auto quoted = [](const std::string& s) { return nlohmann::json(s).dump(); };
    text += "{\"line\": " + std::to_string(request.line) + ", \"query\": [";
    for (std::size_t k = 0; k < answer.variables.size(); ++k)
      text += (k ? ", " : "") + quoted(answer.variables[k].name());
    text += "], \"evidence\": {";
    bool first = true;
    for (const auto& [name, state] : request.observed) {
      text += (first ? "" : ", ") + quoted(name) + ": " + quoted(state);
      first = false;
    }
    text += "}";
    if (!request.intervened.empty()) text += ", \"do\": " + nlohmann::json(request.intervened).dump(-1);
    if (!request.soft.empty()) {
      text += ", \"soft_evidence\": {";
      first = true;
      for (const auto& [name, weights] : request.soft) {
        text += (first ? "" : ", ") + quoted(name) + ": [";
        for (std::size_t k = 0; k < weights.size(); ++k) text += (k ? ", " : "") + number(weights[k]);
        text += "]";
        first = false;
      }
      text += "}";
    }
    text += ", \"engine\": " + quoted(answer.engine) +
            ", \"evidence_probability\": " + number(answer.evidence_probability) + ", \"distribution\": [";
    first = true;
    std::size_t row = 0;
    detail::for_each_joint_state(answer, [&](const std::vector<std::size_t>& codes, double value) {
      text += first ? "{" : ", {";
      first = false;
      for (std::size_t k = 0; k < codes.size(); ++k) {
        text += quoted(answer.variables[k].name()) + ": " + quoted(answer.variables[k].states()[codes[k]]) + ", ";
      }
      text += "\"probability\": " + number(value);
      if (!answer.standard_errors.empty()) text += ", \"standard_error\": " + number(answer.standard_errors[row]);
      text += "}";
      ++row;
    });
    text += "]}\n";
  }
  out << text;
}

}  // namespace pgm
