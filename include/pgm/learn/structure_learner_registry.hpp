#pragma once
/// \file
/// Structure learners by name: `make_structure_learner("tabu[score=bdeu[iss=10]]")` gives a
/// `structure_learner`, which `learn_structure`, the program's `--algorithm` and Python's
/// `algorithm=` all take. The built-in names are pc (the default), hc, tabu, mmhc and empty
/// (pgm/learn/structure_learners.hpp).
///
/// A user's learner joins in one line in its own translation unit:
///
///     static const pgm::register_structure_learner<my_learner> registered("mine", "what it does");
///
/// where `my_learner` models StructureLearner and either is default-constructible or declares
/// `static std::vector<pgm::option_declaration> options()` and is constructible from the
/// `const pgm::option_values&` they are read into.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/component_registry.hpp"
#include "pgm/learn/structure_learner.hpp"

namespace pgm {

using structure_learner_registry = component_registry<structure_learner>;

/// The learner of the program, Python and learn_structure's callers who name none: PC-stable.
inline constexpr std::string_view default_structure_learner = "pc";

/// The program-wide registry of structure learners, holding the built-in ones from the start.
[[nodiscard]] PGM_DECL structure_learner_registry& structure_learners();

/// The learner `text` chooses ("pc", "hc[score=bdeu[iss=10],restarts=5]"). Throws
/// unknown_name for an unknown learner or option, model_error for a bad value.
[[nodiscard]] inline structure_learner make_structure_learner(std::string_view text) {
  return structure_learners().make(text);
}

/// The learner `text` chooses with each given setting set on it, as the program and Python
/// read their options: a setting goes to the learner that `start` chooses when that one
/// declares it ("--start pc --alpha 0.05" sets pc's alpha), and to the learner itself when it
/// declares it (mmhc's alpha too). Throws model_error, after the setting's label, for a setting
/// neither declares, that the text sets already, or whose value fails its check.
[[nodiscard]] PGM_DECL structure_learner make_structure_learner(std::string_view text,
                                                                const std::vector<component_setting>& settings);

/// Registers a learner type when the program starts:
/// `static const register_structure_learner<T> r("name", "…");`.
template <StructureLearner T>
using register_structure_learner = component_registration<&structure_learners, T>;

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/structure_learner_registry.ipp"
#endif
