#pragma once
/// \file
/// The headline numbers of a scenario, as the paper reports them: the success rate after
/// failure prevention at |D| = 0, per strategy. With no target data every w > 0 gives the
/// transferred prior itself, so one weight per strategy says it all.

#include <set>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/text.hpp"
#include "pgm/eval/experiment.hpp"
#include "pgm/eval/scenario.hpp"

namespace pgm {

struct headline_entry {
  std::string strategy;  ///< as in the summary: oracle, mle, direct, …, "<strategy>+auto-map"
  double success;        ///< mean success rate after prevention, in [0, 1]
};

/// One entry per strategy of `scenario_name`'s `target` at |D| = 0, in the summary's order,
/// taken from the first weight listed.
[[nodiscard]] PGM_DECL std::vector<headline_entry> prevention_at_zero_data(const std::vector<aggregated_point>& summary,
                                                                           const std::string& scenario_name,
                                                                           const std::string& target);

/// "<title>, <target>: success after prevention at |D| = 0:  oracle 99.9%  mle 57%  …", as
/// `pgm experiment` prints it (percentages to 3 significant digits).
[[nodiscard]] PGM_DECL std::string headline(const scenario& s, const std::string& target,
                                            const std::vector<aggregated_point>& summary);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/eval/impl/headline.ipp"
#endif
