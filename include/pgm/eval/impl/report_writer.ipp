#pragma once
// The definitions of pgm/eval/report_writer.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/eval/report_writer.hpp"

namespace pgm {

PGM_DECL void check_output_folder(const std::filesystem::path& folder) {
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

PGM_DECL void report_writer::add(const scenario& s, const std::vector<experiment_point>& points) {
  std::filesystem::create_directory(folder_);
  const auto summary = aggregate(points);
  for (const auto& t : s.targets) {
    const auto stem = folder_ / (s.name + "-" + t.task);
    const auto script = gnuplot_script(s, t.task, summary, stem);
    const std::filesystem::path script_file = stem.string() + ".gp";
    pgm::write_file_atomically(script_file, [&](std::ostream& out) { out << script; });
    if (options_.render_plots && !options_.render_plots(script_file)) {
      say("the plot script " + script_file.string() + " failed to render");
    }
  }
  if (options_.headline) {
    for (const auto& t : s.targets) options_.headline(headline(s, t.task, summary));
  }
  points_.insert(points_.end(), points.begin(), points.end());
}

PGM_DECL report_files report_writer::finish() {
  std::filesystem::create_directory(folder_);
  report_files files{points_.size(), folder_ / "points.csv", folder_ / "summary.csv",
                     static_cast<bool>(options_.render_plots)};
  write_points_csv(points_, files.points_csv);
  write_summary_csv(aggregate(points_), files.summary_csv);
  return files;
}

}  // namespace pgm
