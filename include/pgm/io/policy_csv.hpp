#pragma once
/// \file
/// An influence diagram's policies as CSV, the form `pgm decide --policy-out` writes and
/// `--policy-in` reads:
///
///     decision,observed,action
///     Test,,yes
///     Drill,"Test=yes,Seismic=closed",yes
///
/// one row per configuration of what a decision observes (every row of a decision names the same
/// variables, in the same order), the action a state of the decision. A decision may observe only
/// what is known when it is taken: its parents, the evidence, and, with perfect recall, every
/// earlier decision and what that one observed. A configuration the evidence rules out may be
/// left out. Every error names the file, line and column and what was expected.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/influence_diagram.hpp"
#include "pgm/inference/query.hpp"

namespace pgm {

/// The policies of `diagram` in `text`, one per decision, in the order the decisions are taken;
/// `source` names the text in errors (parse_error). `limited_memory`: a decision knows its
/// parents only, as `decision_options::limited_memory` reads a diagram.
[[nodiscard]] PGM_DECL std::vector<decision_policy> parse_policy_csv(std::string_view text, const std::string& source,
                                                                     const influence_diagram& diagram,
                                                                     const evidence& observed = {},
                                                                     bool limited_memory = false);

/// The same, from a file.
[[nodiscard]] PGM_DECL std::vector<decision_policy> read_policy_csv(const std::filesystem::path& path,
                                                                    const influence_diagram& diagram,
                                                                    const evidence& observed = {},
                                                                    bool limited_memory = false);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/io/impl/policy_csv.ipp"
#endif
