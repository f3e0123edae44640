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

#include "pgm/core/error.hpp"
#include "pgm/detail/file.hpp"
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
inline void check_output_folder(const std::filesystem::path& folder) {
  if (folder.empty()) throw io_error("no output folder was given");
  std::error_code ec;
  if (std::filesystem::exists(folder, ec) && !std::filesystem::is_directory(folder, ec)) {
    throw io_error("'" + folder.string() + "' is a file, not a folder");
  }
  const auto parent = folder.has_parent_path() ? folder.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(parent, ec)) {
    throw io_error("the folder '" + parent.string() + "' does not exist");
  }
}

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
  void add(const scenario& s, const std::vector<experiment_point>& points) {
    std::filesystem::create_directory(folder_);
    const auto summary = aggregate(points);
    for (const auto& t : s.targets) {
      const auto stem = folder_ / (s.name + "-" + t.task);
      const auto script = gnuplot_script(s, t.task, summary, stem);
      const std::filesystem::path script_file = stem.string() + ".gp";
      detail::write_file_atomically(script_file, [&](std::ostream& out) { out << script; });
      if (options_.render_plots && !options_.render_plots(script_file)) {
        say("the plot script " + script_file.string() + " failed to render");
      }
    }
    if (options_.headline) {
      for (const auto& t : s.targets) options_.headline(headline(s, t.task, summary));
    }
    points_.insert(points_.end(), points.begin(), points.end());
  }

  /// Writes points.csv and summary.csv of every scenario added (atomically, each).
  report_files finish() {
    std::filesystem::create_directory(folder_);
    report_files files{points_.size(), folder_ / "points.csv", folder_ / "summary.csv",
                       static_cast<bool>(options_.render_plots)};
    write_points_csv(points_, files.points_csv);
    write_summary_csv(aggregate(points_), files.summary_csv);
    return files;
  }

 private:
  void say(const std::string& text) const {
    if (options_.note) options_.note(text);
  }

  std::filesystem::path folder_;
  report_options options_;
  std::vector<experiment_point> points_;
};

}  // namespace pgm
