#pragma once
// Documents whose numbers come from experiment summaries: a Markdown template in which every
// number is a placeholder `{{FORMAT EXPRESSION}}` evaluated on one or more summary.csv files
// (pgm::parse_summary_csv), so that a result page can be checked against the data it quotes.
// `pgm report` renders docs/results/RESULTS.template.md into docs/RESULTS.md; the syntax is
// documented there and in docs/api.md.
//
// FORMAT: `pct:N` (×100, N decimals), `num:N` (N decimals), `count` (a whole number with
// thousands separators); a leading `+` always shows the sign.
//
// EXPRESSION, in prefix form:
// - a selector `[SOURCE:]scenario/target/strategy/w/rows/metric`: the mean of every matching
//   summary row. Each field is `*` or a comma list of values; rows may also be `max` (the
//   largest |D| of each scenario and target). SOURCE names a summary given as NAME=FILE; none
//   means the first summary.
// - a number, e.g. `0.7`;
// - `sd X`, `reps X`: the standard deviation or repetition count of selector X's rows;
// - `diff X Y`: X − Y, row by row; rows of two selectors are paired on the fields they write
//   alike (so `…/direct,cross/auto/max/…` and `…/direct,cross/5/max/…` pair by strategy);
// - `abs X`, `min X`, `max X`;
// - `range X`: "lo–hi" (one number when both print alike);
// - `first-within T X Y`: the smallest |D| at which |X − Y| ≤ T (X, Y one series over |D|).
//
// An expression giving several values must be reduced (min, max, range); a selector matching
// nothing is an error naming the field and the values it could take. `\{{` stands for `{{`.

#include <string>
#include <string_view>
#include <vector>

#include "pgm/eval/experiment.hpp"

namespace pgm::cli {

/// One summary a template may quote, by name ("" for the default).
struct named_summary {
  std::string name;
  std::vector<aggregated_point> rows;
};

/// Replaces every `{{FORMAT EXPRESSION}}` of `text` by its value from `summaries` (see the
/// file comment). `source` names the template in errors (parse_error with line and column).
[[nodiscard]] std::string render_report_template(std::string_view text, const std::string& source,
                                                 const std::vector<named_summary>& summaries);

}  // namespace pgm::cli
