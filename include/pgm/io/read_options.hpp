#pragma once
/// \file
/// What the network readers (BIF, XMLBIF, Hugin NET) accept beyond the letter of a file, and
/// how they tell the caller about it. Published networks print rounded probabilities, so a
/// column may sum to 0.9999 or 1.0001: within `tolerance` it is divided by its sum (and a note
/// says how many columns were), beyond it the file is refused.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/cpt.hpp"
#include "pgm/detail/text.hpp"

namespace pgm {

struct network_read_options {
  /// How far a column's sum may stray from one. Columns within cpt's own 1e-6 are kept as
  /// written (so round trips are exact); columns off by more, up to this, are normalized.
  double tolerance = 1e-3;
  /// When set, receives one line per thing the reader changed or ignored (normalized columns,
  /// properties it does not know), for the caller to show.
  std::vector<std::string>* notes = nullptr;
  /// When set, receives pgm's own network-level properties, by key without its prefix: BIF's
  /// `network { property pgm.KEY = VALUE ; }`, XMLBIF's `<NETWORK><PROPERTY>pgm.KEY = VALUE`,
  /// NET's `net { pgm_KEY = "VALUE"; }` (a fit's counts, pgm/io/network_file.hpp).
  std::map<std::string, std::string>* properties = nullptr;
};

namespace detail {

/// Keeps a network-level property's text "pgm.KEY = VALUE" (BIF, XMLBIF) in `properties` as
/// KEY → VALUE; another property, or no `properties`, is left alone.
inline void keep_pgm_property(std::string_view text, std::map<std::string, std::string>* properties) {
  const auto eq = text.find('=');
  if (properties == nullptr || eq == std::string_view::npos) return;
  const auto key = trim(text.substr(0, eq));
  if (key.starts_with("pgm.")) (*properties)[std::string(key.substr(4))] = std::string(trim(text.substr(eq + 1)));
}

/// Normalizing the columns of one table at a time, and the one note for a whole file.
class column_normalizer {
 public:
  explicit column_normalizer(double tolerance) : tolerance_(tolerance) {}

  /// Normalizes the columns of `values` (`child_states` values each) that are off by more than
  /// cpt's tolerance and at most `tolerance`. Returns the first column off by more than
  /// `tolerance` (left as it is, for the caller to refuse) and its sum.
  std::optional<std::pair<std::size_t, double>> normalize(std::span<double> values, std::size_t child_states) {
    if (child_states == 0) return std::nullopt;
    bool table_changed = false;
    for (std::size_t u = 0; u * child_states < values.size(); ++u) {
      const auto column = values.subspan(u * child_states, std::min(child_states, values.size() - u * child_states));
      double sum = 0;
      bool probabilities = true;
      for (const double value : column) {
        probabilities = probabilities && value >= 0 && std::isfinite(value);
        sum += value;
      }
      if (!probabilities) continue;  // the table's own check names the bad value
      const double deviation = std::abs(sum - 1.0);
      if (deviation <= cpt<double>::default_tolerance) continue;
      if (deviation > tolerance_) return std::make_pair(u, sum);
      for (auto& value : column) value /= sum;
      ++columns_;
      table_changed = true;
      largest_ = std::max(largest_, deviation);
    }
    if (table_changed) ++tables_;
    return std::nullopt;
  }

  [[nodiscard]] double tolerance() const noexcept { return tolerance_; }

  /// Adds the note for `source` to `notes` if any column was normalized.
  void report(const std::string& source, std::vector<std::string>* notes) const {
    if (notes == nullptr || columns_ == 0) return;
    notes->push_back("'" + source + "': normalized " + std::to_string(columns_) + " column" +
                     (columns_ == 1 ? "" : "s") + " of " + std::to_string(tables_) + " table" +
                     (tables_ == 1 ? "" : "s") + " that summed to 1 only within " + format_short(tolerance_) +
                     " (largest deviation " + format_short(largest_, 3) + ")");
  }

  /// The message for a column off by more than the tolerance.
  [[nodiscard]] std::string refusal(const std::string& variable_name, double sum) const {
    return "a distribution of '" + variable_name + "' sums to " + format_double(sum) + ", not 1 within " +
           format_short(tolerance_) + " (the tolerance for rounded published tables)";
  }

 private:
  double tolerance_;
  std::size_t columns_ = 0;
  std::size_t tables_ = 0;
  double largest_ = 0;
};

}  // namespace detail

}  // namespace pgm
