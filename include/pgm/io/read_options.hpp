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

#include "pgm/core/compilation.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/text.hpp"

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
PGM_DECL void keep_pgm_property(std::string_view text, std::map<std::string, std::string>* properties);

/// Normalizing the columns of one table at a time, and the one note for a whole file.
class column_normalizer {
 public:
  explicit column_normalizer(double tolerance) : tolerance_(tolerance) {}

  /// Normalizes the columns of `values` (`child_states` values each) that are off by more than
  /// cpt's tolerance and at most `tolerance`. Returns the first column off by more than
  /// `tolerance` (left as it is, for the caller to refuse) and its sum.
  PGM_DECL std::optional<std::pair<std::size_t, double>> normalize(std::span<double> values, std::size_t child_states);

  [[nodiscard]] double tolerance() const noexcept { return tolerance_; }

  /// Adds the note for `source` to `notes` if any column was normalized.
  PGM_DECL void report(const std::string& source, std::vector<std::string>* notes) const;

  /// The message for a column off by more than the tolerance.
  [[nodiscard]] std::string refusal(const std::string& variable_name, double sum) const {
    return "a distribution of '" + variable_name + "' sums to " + text::format_double(sum) + ", not 1 within " +
           text::format_short(tolerance_) + " (the tolerance for rounded published tables)";
  }

 private:
  double tolerance_;
  std::size_t columns_ = 0;
  std::size_t tables_ = 0;
  double largest_ = 0;
};

}  // namespace detail

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/io/impl/read_options.ipp"
#endif
