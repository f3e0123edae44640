#pragma once
// The definitions of pgm/inference/posterior_table.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/inference/posterior_table.hpp"

namespace pgm {

PGM_DECL std::vector<std::string> parse_query_variables(std::string_view text) {
  auto names = text::split(text, ',');
  if (names.empty()) throw model_error("the query names no variable; give one or more, e.g. --query X,Y");
  for (const auto& name : names) {
    if (name.empty()) throw model_error("the query '" + std::string(text) + "' has an empty variable name");
  }
  return names;
}

PGM_DECL evidence parse_evidence(std::string_view text) {
  evidence result;
  for (const auto& piece : text::split(text, ',')) {
    const auto equals = piece.find('=');
    const auto name =
        equals == std::string::npos ? std::string_view{} : text::trim(std::string_view(piece).substr(0, equals));
    const auto state =
        equals == std::string::npos ? std::string_view{} : text::trim(std::string_view(piece).substr(equals + 1));
    if (name.empty() || state.empty()) {
      throw model_error("the evidence '" + piece + "' is not of the form variable=state");
    }
    if (!result.emplace(std::string(name), std::string(state)).second) {
      throw model_error("'" + std::string(name) + "' is observed twice in the evidence");
    }
  }
  return result;
}

PGM_DECL intervention parse_intervention(std::string_view text) {
  intervention result;
  for (const auto& [name, state] : parse_evidence(text)) result.emplace(name, state);
  return result;
}

PGM_DECL soft_evidence parse_soft_evidence(std::string_view text) {
  soft_evidence result;
  for (const auto& piece : text::split(text, ',')) {
    const auto equals = piece.find('=');
    const auto name =
        equals == std::string::npos ? std::string_view{} : text::trim(std::string_view(piece).substr(0, equals));
    const auto weights =
        equals == std::string::npos ? std::string_view{} : text::trim(std::string_view(piece).substr(equals + 1));
    if (name.empty() || weights.empty()) {
      throw model_error("the soft evidence '" + piece + "' is not of the form variable=w1:w2:…, e.g. rain=0.2:0.8");
    }
    std::vector<double> values;
    for (const auto& number : text::split(weights, ':')) {
      const auto value = text::parse_double(number);
      if (!value || !std::isfinite(*value)) {
        throw model_error("the soft evidence on '" + std::string(name) + "' has the weight " +
                          text::quoted_number(number) + ", which is not a finite number");
      }
      values.push_back(*value);
    }
    if (!result.emplace(std::string(name), std::move(values)).second) {
      throw model_error("'" + std::string(name) + "' has soft evidence twice");
    }
  }
  return result;
}

}  // namespace pgm

namespace pgm::detail {

PGM_DECL std::string format_probability(double value, int digits) {
  if (digits < 1 || digits > 17) {
    throw model_error("digits must be between 1 and 17, got " + std::to_string(digits));
  }
  return text::format_short(value, digits);
}

/// A probability for JSON; null for one the engine could not estimate (NaN: a Gibbs chain on a
/// Markov network has no P(evidence)).
inline std::string json_probability(double p, const std::function<std::string(double)>& number) {
  return std::isnan(p) ? "null" : number(p);
}

PGM_DECL std::string json_evidence(const evidence& observed, const soft_evidence& soft,
                                   const std::function<std::string(double)>& number, const intervention& set) {
  std::string text;
  if (!set.empty()) {
    text += "  \"do\": {";
    bool first = true;
    for (const auto& [name, state] : set) {
      text += (first ? "" : ", ") + json_text(name) + ": " + json_text(state);
      first = false;
    }
    text += "},\n";
  }
  text += "  \"evidence\": {";
  bool first = true;
  for (const auto& [name, state] : observed) {
    text += (first ? "" : ", ") + json_text(name) + ": " + json_text(state);
    first = false;
  }
  text += "},\n";
  if (!soft.empty()) {
    text += "  \"soft_evidence\": {";
    first = true;
    for (const auto& [name, weights] : soft) {
      text += (first ? "" : ", ") + json_text(name) + ": [";
      for (std::size_t k = 0; k < weights.size(); ++k) text += (k ? ", " : "") + number(weights[k]);
      text += "]";
      first = false;
    }
    text += "},\n";
  }
  return text;
}

PGM_DECL void check_table_options(const posterior_table_options& options, std::span<const variable> variables) {
  static_cast<void>(format_probability(0.0, options.digits));  // check the digits before writing anything
  for (const auto& v : variables) {
    if (v.name() == "probability" || v.name() == "standard_error") {
      throw model_error("the query variable '" + v.name() + "' would share its name with the " + v.name() + " column");
    }
  }
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL void write_posterior_table(std::ostream& out, const posterior& p, const evidence& observed,
                                    const posterior_table_options& options, const soft_evidence& soft,
                                    const intervention& set) {
  const std::function<std::string(double)> number = [&](double v) {
    return detail::format_probability(v, options.digits);
  };
  detail::check_table_options(options, p.variables);
  const bool sampled = !p.standard_errors.empty();
  std::string text;
  if (options.format == posterior_format::csv) {
    for (const auto& v : p.variables) text += text::csv_escape(v.name(), ',') + ",";
    text += sampled ? "probability,standard_error\n" : "probability\n";
    std::size_t row = 0;
    detail::for_each_joint_state(p, [&](const std::vector<std::size_t>& codes, double value) {
      for (std::size_t k = 0; k < codes.size(); ++k) {
        text += text::csv_escape(p.variables[k].states()[codes[k]], ',') + ",";
      }
      text += number(value);
      if (sampled) text += "," + number(p.standard_errors[row]);
      text += "\n";
      ++row;
    });
  } else {
    text += "{\n  \"query\": [";
    for (std::size_t k = 0; k < p.variables.size(); ++k) {
      text += (k ? ", " : "") + detail::json_text(p.variables[k].name());
    }
    text += "],\n" + detail::json_evidence(observed, soft, number, set);
    text += "  \"evidence_probability\": " + detail::json_probability(p.evidence_probability, number) + ",\n";
    if (p.evidence_probability < std::numeric_limits<double>::min()) {
      // Beyond a double: the logarithm carries it.
      text += "  \"log_evidence_probability\": " + text::format_double(p.log_evidence_probability) + ",\n";
    }
    if (!p.engine.empty()) text += "  \"engine\": " + detail::json_text(p.engine) + ",\n";
    text += "  \"distribution\": [";
    bool first = true;
    std::size_t row = 0;
    detail::for_each_joint_state(p, [&](const std::vector<std::size_t>& codes, double value) {
      text += first ? "\n    {" : ",\n    {";
      first = false;
      for (std::size_t k = 0; k < codes.size(); ++k) {
        text += detail::json_text(p.variables[k].name()) + ": " + detail::json_text(p.variables[k].states()[codes[k]]) +
                ", ";
      }
      text += "\"probability\": " + number(value);
      if (sampled) text += ", \"standard_error\": " + number(p.standard_errors[row]);
      text += "}";
      ++row;
    });
    text += "\n  ]\n}\n";
  }
  out << text;
}

PGM_DECL void write_marginals_table(std::ostream& out, const std::vector<posterior>& marginals,
                                    const evidence& observed, const posterior_table_options& options,
                                    const soft_evidence& soft, const intervention& set) {
  const std::function<std::string(double)> number = [&](double v) {
    return detail::format_probability(v, options.digits);
  };
  detail::check_table_options(options, {});
  const bool sampled = !marginals.empty() && !marginals.front().standard_errors.empty();
  std::string text;
  if (options.format == posterior_format::csv) {
    text += sampled ? "variable,state,probability,standard_error\n" : "variable,state,probability\n";
    for (const auto& m : marginals) {
      const auto& v = m.variables.front();
      for (std::size_t s = 0; s < v.cardinality(); ++s) {
        text += text::csv_escape(v.name(), ',') + "," + text::csv_escape(v.states()[s], ',') + "," +
                number(m.table.values()[s]);
        if (sampled) text += "," + number(m.standard_errors[s]);
        text += "\n";
      }
    }
  } else {
    text += "{\n" + detail::json_evidence(observed, soft, number, set);
    if (!marginals.empty()) {
      text +=
          "  \"evidence_probability\": " + detail::json_probability(marginals.front().evidence_probability, number) +
          ",\n";
      text += "  \"engine\": " + detail::json_text(marginals.front().engine) + ",\n";
    }
    const auto section = [&](const char* key, bool errors) {
      text += std::string("  \"") + key + "\": {";
      for (std::size_t i = 0; i < marginals.size(); ++i) {
        const auto& v = marginals[i].variables.front();
        text += (i ? ",\n    " : "\n    ") + detail::json_text(v.name()) + ": {";
        for (std::size_t s = 0; s < v.cardinality(); ++s) {
          text += (s ? ", " : "") + detail::json_text(v.states()[s]) + ": " +
                  number(errors ? marginals[i].standard_errors[s] : marginals[i].table.values()[s]);
        }
        text += "}";
      }
      text += "\n  }";
    };
    section("marginals", false);
    if (sampled) {
      text += ",\n";
      section("standard_errors", true);
    }
    text += "\n}\n";
  }
  out << text;
}

PGM_DECL void write_mpe_table(std::ostream& out, const mpe_result& best, const evidence& observed,
                              const posterior_table_options& options, const soft_evidence& soft,
                              const intervention& set) {
  const std::function<std::string(double)> number = [&](double v) {
    return detail::format_probability(v, options.digits);
  };
  detail::check_table_options(options, best.variables);
  std::string text;
  if (options.format == posterior_format::csv) {
    for (const auto& v : best.variables) text += text::csv_escape(v.name(), ',') + ",";
    text += "probability\n";
    for (std::size_t k = 0; k < best.variables.size(); ++k) {
      text += text::csv_escape(best.variables[k].states()[best.states[k].value()], ',') + ",";
    }
    text += number(best.probability) + "\n";
  } else {
    text += "{\n" + detail::json_evidence(observed, soft, number, set) + "  \"mpe\": {";
    for (std::size_t k = 0; k < best.variables.size(); ++k) {
      text += (k ? ", " : "") + detail::json_text(best.variables[k].name()) + ": " +
              detail::json_text(best.variables[k].states()[best.states[k].value()]);
    }
    text += "},\n  \"probability\": " + number(best.probability) +
            ",\n  \"joint_probability\": " + number(best.joint_probability) +
            ",\n  \"log_probability\": " + text::format_double(best.log_joint_probability) +
            ",\n  \"engine\": " + detail::json_text(best.engine) + "\n}\n";
  }
  out << text;
}

}  // namespace pgm
