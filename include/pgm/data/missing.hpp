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

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

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

/// The policy named `name` ("error", "drop", "available"); throws std::invalid_argument otherwise.
[[nodiscard]] inline missing_policy missing_policy_named(std::string_view name) {
  if (name == "error") return missing_policy::error;
  if (name == "drop") return missing_policy::drop;
  if (name == "available") return missing_policy::available;
  throw std::invalid_argument("unknown missing-value policy '" + std::string(name) +
                              "' (expected error, drop or available)");
}

/// The code that marks a missing value in a discrete column stored as `Code`.
template <class Code>
inline constexpr Code missing_code = std::numeric_limits<Code>::max();

}  // namespace pgm
