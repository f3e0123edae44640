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

namespace detail {

/// Whether a field's text is one of the missing tokens, in one table look-up for most texts
/// (a code such as "3" never starts like "NA" or "?").
class missing_matcher {
 public:
  explicit missing_matcher(const std::vector<std::string>& tokens) {
    for (auto& f : first_) f = false;
    for (const auto& token : tokens) {
      if (token.empty()) {
        empty_ = true;
        continue;
      }
      first_[static_cast<unsigned char>(token.front())] = true;
      tokens_.push_back(token);
    }
  }

  [[nodiscard]] bool operator()(std::string_view text) const noexcept {
    if (text.empty()) return empty_;
    if (!first_[static_cast<unsigned char>(text.front())]) return false;
    for (const auto& token : tokens_) {
      if (text == token) return true;
    }
    return false;
  }

  [[nodiscard]] bool empty_is_missing() const noexcept { return empty_; }

 private:
  bool empty_ = false;
  bool first_[256];
  std::vector<std::string> tokens_;
};

}  // namespace detail
}  // namespace pgm
