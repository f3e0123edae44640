#pragma once
/// \file
/// The experiment's figures in the layout of the paper's Fig. 4–8, as gnuplot scripts: one
/// column per strategy; rows Max-Difference, Mean-Difference and the success rate after failure
/// prevention; one line per weight (MLE blue, w from small to large green, red, yellow, w =
/// auto dashed black, the proposed map dotted purple, the oracle dash-dotted grey); legends
/// outside the data area, right of each panel. The library writes scripts only; rendering them
/// (the `gnuplot` program) is the caller's: `pgm experiment` passes a renderer to the writer.

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/text.hpp"
#include "pgm/eval/experiment.hpp"
#include "pgm/eval/scenario.hpp"

namespace pgm {

/// A gnuplot single-quoted string: a quote inside is written twice.
[[nodiscard]] PGM_DECL std::string gnuplot_quoted(std::string_view text);

/// The gnuplot script of one target task of a scenario, from the scenario's summary (other
/// scenarios' and targets' points are skipped). It writes `<stem>.png` and `<stem>.svg`.
[[nodiscard]] PGM_DECL std::string gnuplot_script(const scenario& s, const std::string& target,
                                                  const std::vector<aggregated_point>& summary,
                                                  const std::filesystem::path& stem);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/eval/impl/plot.ipp"
#endif
