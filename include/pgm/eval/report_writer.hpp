#pragma once
/// \file
/// The output folder of an experiment run: per scenario, one gnuplot script per target task
/// (rendered to PNG and SVG by the caller's renderer, if any) and the headline numbers; at the end
/// `points.csv` and `summary.csv` of every scenario. Writing is apart from computing, so that
/// whoever computes the points (one process, or the ranks of a cluster) hands them to one
/// writer.

#include <filesystem>
#include <functional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/eval/experiment.hpp"
#include "pgm/eval/headline.hpp"
#include "pgm/eval/plot.hpp"
#include "pgm/eval/result_tables.hpp"
#include "pgm/eval/scenario.hpp"

namespace pgm {

/// Renders a written plot script (`<stem>.gp` into `<stem>.png` and `.svg`); false if it failed.
/// The program's runs gnuplot; the library itself never starts a process.
using plot_renderer = std::function<bool(const std::filesystem::path& script)>;

struct report_options {
  /// Renders each plot script; without one only the scripts (.gp) are written.
  plot_renderer render_plots;
  /// What the user should know but need not act on (a plot that failed to render).
  std::function<void(const std::string&)> note;
  /// Each target's headline line (pgm::headline), once its scenario is written.
  std::function<void(const std::string&)> headline;
};

/// What a finished report wrote.
struct report_files {
  std::size_t points = 0;
  std::filesystem::path points_csv, summary_csv;
  bool plots_rendered = false;
};

/// Throws io_error unless `folder` is a folder or can be made as one: it is not a file and its
/// parent folder exists.
PGM_DECL void check_output_folder(const std::filesystem::path& folder);

class report_writer {
 public:
  /// Checks `folder` at once (see check_output_folder) but makes it only when the first
  /// scenario is added, so that a run failing before has written nothing.
  explicit report_writer(std::filesystem::path folder, report_options options = {})
      : folder_(std::move(folder)), options_(std::move(options)) {
    check_output_folder(folder_);
  }

  [[nodiscard]] const std::filesystem::path& folder() const noexcept { return folder_; }

  /// Writes the scenario's plots (`<scenario>-<target>.gp`, .png, .svg), gives its headline
  /// lines and keeps its points for the tables.
  PGM_DECL void add(const scenario& s, const std::vector<experiment_point>& points);

  /// Writes points.csv and summary.csv of every scenario added (atomically, each).
  PGM_DECL report_files finish();

 private:
  void say(const std::string& text) const {
    if (options_.note) options_.note(text);
  }

  std::filesystem::path folder_;
  report_options options_;
  std::vector<experiment_point> points_;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/eval/impl/report_writer.ipp"
#endif
