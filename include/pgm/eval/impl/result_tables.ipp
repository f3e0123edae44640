#pragma once
// The definitions of pgm/eval/result_tables.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/eval/result_tables.hpp"

namespace pgm {

PGM_DECL void write_points_csv(const std::vector<experiment_point>& points, std::ostream& out) {
  out << "scenario,target,strategy,w,rows,repetition,metric,value\n";
  for (const auto& p : points) {
    out << detail::csv_text(p.scenario) << ',' << detail::csv_text(p.target) << ',' << detail::csv_text(p.strategy)
        << ',' << detail::csv_text(p.weight) << ',' << p.rows << ',' << p.repetition << ',' << to_string(p.metric)
        << ',' << text::format_double(p.value) << '\n';
  }
}

PGM_DECL void write_summary_csv(const std::vector<aggregated_point>& summary, std::ostream& out) {
  out << text::join(detail::summary_columns, ",") << '\n';
  for (const auto& p : summary) {
    out << detail::csv_text(p.scenario) << ',' << detail::csv_text(p.target) << ',' << detail::csv_text(p.strategy)
        << ',' << detail::csv_text(p.weight) << ',' << p.rows << ',' << to_string(p.metric) << ','
        << text::format_double(p.mean) << ',' << text::format_double(p.standard_deviation) << ',' << p.repetitions
        << '\n';
  }
}

PGM_DECL std::vector<aggregated_point> parse_summary_csv(std::string_view text, const std::string& source) {
  detail::csv_scanner scanner(text, source, ',');
  std::vector<detail::csv_field> fields;
  if (!scanner.next(fields)) throw parse_error(source, 1, 1, "the file is empty; expected a summary's header row");
  std::array<std::size_t, detail::summary_columns.size()> position{};
  for (std::size_t c = 0; c < detail::summary_columns.size(); ++c) {
    std::optional<std::size_t> found;
    for (std::size_t f = 0; f < fields.size(); ++f) {
      if (fields[f].text == detail::summary_columns[c]) found = f;
    }
    if (!found) {
      throw parse_error(source, 1, 1,
                        "the header has no column '" + std::string(detail::summary_columns[c]) + "' (a summary has " +
                            text::join(detail::summary_columns) + ")");
    }
    position[c] = *found;
  }
  const std::size_t width = fields.size();
  std::vector<aggregated_point> summary;
  while (scanner.next(fields)) {
    if (fields.size() != width) {
      throw parse_error(
          source, fields.back().line, fields.back().column,
          "expected " + std::to_string(width) + " fields as in the header, found " + std::to_string(fields.size()));
    }
    auto field = [&](std::size_t c) -> const detail::csv_field& { return fields[position[c]]; };
    auto fail = [&](std::size_t c, const std::string& what) {
      throw parse_error(source, field(c).line, field(c).column,
                        "column '" + std::string(detail::summary_columns[c]) + "': " + what + ", got '" +
                            std::string(field(c).text) + "'");
    };
    auto whole = [&](std::size_t c) {
      const auto digits = field(c).text;
      std::size_t value = 0;
      const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
      if (digits.empty() || ec != std::errc{} || end != digits.data() + digits.size())
        fail(c, "expected a whole number");
      return value;
    };
    auto real = [&](std::size_t c) {
      const auto value = text::parse_double(field(c).text);
      if (!value || !std::isfinite(*value)) fail(c, "expected a finite number");
      return *value;
    };
    auto name = [&](std::size_t c) {
      if (field(c).text.empty()) fail(c, "expected a name");
      return std::string(field(c).text);
    };
    auto metric = [&](std::size_t c) {
      try {
        return parse_experiment_metric(field(c).text);
      } catch (const unknown_name& e) {
        throw parse_error(source, field(c).line, field(c).column,
                          "column '" + std::string(detail::summary_columns[c]) + "': " + e.what());
      }
    };
    summary.push_back({name(0), name(1), name(2), name(3), whole(4), metric(5), real(6), real(7), whole(8)});
  }
  return summary;
}

}  // namespace pgm
