#pragma once
/// \file
/// Missing values in data: which CSV texts mean "no value" and what a reader does with a row
/// that has one. The defaults follow pandas' reading (`NA`, the empty field, and `?`, the UCI
/// repository's mark); the default policy refuses them, naming the first one's place.
///
/// In a `dataset`, a missing discrete value is the reserved code `missing_code<Code>` (the
/// largest value of the column's code type, which a column with missing values never uses for
/// a state) and a missing continuous value is NaN. Counting skips a row for a family (or an
/// independence test) when any of its variables is missing there: available-case analysis, as
/// pgmpy counts.

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/unknown_name.hpp"

namespace pgm {

/// What a reader does with a row that holds a missing value.
enum class missing_policy {
  error,      ///< refuse the data, naming the first missing value's line and column
  drop,       ///< leave out every row with a missing value in a column read (listwise deletion)
  available,  ///< keep the row: each family is counted over the rows where its variables are present
};

/// The texts read as missing, and what to do with them.
struct missing_values {
  /// Field texts (after trimming blanks) that mean "no value"; "" is the empty field.
  std::vector<std::string> tokens{"NA", "", "?"};
  missing_policy policy = missing_policy::error;
};

/// "error", "drop" or "available", as the command line, Python and messages spell the policy.
[[nodiscard]] constexpr std::string_view to_string(missing_policy policy) noexcept {
  switch (policy) {
    case missing_policy::drop:
      return "drop";
    case missing_policy::available:
      return "available";
    case missing_policy::error:
      break;
  }
  return "error";
}

inline constexpr std::array missing_policies{missing_policy::error, missing_policy::drop, missing_policy::available};

/// The policies' names, for parsing, messages and the command line's allowed values.
[[nodiscard]] inline std::vector<std::string> known_missing_policies() { return names_of(missing_policies); }

/// Parses "error", "drop" or "available"; throws unknown_name otherwise.
[[nodiscard]] inline missing_policy parse_missing_policy(std::string_view text) {
  return parse_choice("missing-value policy", text, missing_policies);
}

/// The code that marks a missing value in a discrete column stored as `Code`.
template <class Code>
inline constexpr Code missing_code = std::numeric_limits<Code>::max();

}  // namespace pgm
