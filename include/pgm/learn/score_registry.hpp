#pragma once
/// \file
/// Scores by name: `make_score("bdeu[iss=10]")` gives a `family_score`, any FamilyScore
/// (pgm/learn/score.hpp) behind one type, which the structure search, `score_network`, the
/// program's `--score` and Python's `score=` all take. The built-in names are bic, aic[k=1],
/// bdeu[iss=1] (bnlearn's "bde" too), k2 and loglik.
///
/// A user's score joins in one line in its own translation unit:
///
///     static const pgm::register_score<my_score> registered("mine", "what it rewards");
///
/// where `my_score` models FamilyScore and either is default-constructible or declares
/// `static std::vector<pgm::option_declaration> options()` and is constructible from the
/// `const pgm::option_values&` they are read into; `--score mine[key=value]` then reaches it.

#include <concepts>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/component_options.hpp"
#include "pgm/core/component_registry.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/learn/score.hpp"

namespace pgm {

/// Any family score, with the name and options it was chosen by.
class family_score : public chosen_function<double(const count_table&)> {
 public:
  /// bic, the library's default.
  PGM_DECL family_score();
  family_score(function_type score, component_choice choice) : chosen_function(std::move(score), std::move(choice)) {}
};

static_assert(FamilyScore<family_score>);

using score_registry = component_registry<family_score>;

/// The program-wide registry of scores, holding the built-in ones from the start.
[[nodiscard]] PGM_DECL score_registry& scores();

/// The score `text` chooses ("bic", "bdeu[iss=10]"). Throws unknown_name for an unknown
/// score or option, model_error for a bad value.
[[nodiscard]] inline family_score make_score(std::string_view text) { return scores().make(text); }

/// Registers a score type when the program starts: `static const register_score<S> r("name", "…");`.
template <FamilyScore S>
using register_score = component_registration<&scores, S>;

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/score_registry.ipp"
#endif
