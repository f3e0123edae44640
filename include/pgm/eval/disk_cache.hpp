#pragma once
/// \file
/// A task source that keeps its data on disk between runs: each (task, rows, seed) is made
/// once by the wrapped source and written to a folder, one file per task, back-end, seed and
/// row count (pgm/io/dataset_file.hpp, written atomically); a later run with the same key
/// reads the file instead. `pgm experiment --data-cache DIR` is this wrapper, so that the
/// hours of Bullet simulation behind the paper's scenarios are spent once.
///
/// A file is used only if its header holds the same key (task, back-end, seed, rows) and the
/// same origin (the wrapped source's `origin`, e.g. the task file's checksum): a file made from
/// other inputs, a truncated or a corrupt one is an error that names it, never data.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/eval/experiment.hpp"
#include "pgm/io/dataset_file.hpp"

namespace pgm {

struct disk_cache_options {
  /// Where the files go; made if missing.
  std::filesystem::path folder;
  /// What makes the data ("bullet", "analytic"): part of the key, so one back-end's data never
  /// stand in for another's.
  std::string backend;
  /// Each data set read from or written to the folder ("read …", "wrote …").
  std::function<void(const std::string&)> note;
};

/// The file of a key in `folder`: `<task>.<backend>.seed-<seed>.rows-<rows>.pgmdata`.
[[nodiscard]] inline std::filesystem::path disk_cache_file(const std::filesystem::path& folder, const std::string& task,
                                                           const std::string& backend, std::size_t rows,
                                                           std::uint64_t seed) {
  return folder /
         (task + "." + backend + ".seed-" + std::to_string(seed) + ".rows-" + std::to_string(rows) + ".pgmdata");
}

/// `inner` with its data kept in `options.folder`. Safe to call from several threads; wrap
/// the result in pgm::cached to keep data in memory within a run as well.
[[nodiscard]] inline task_source disk_cached(task_source inner, disk_cache_options options) {
  if (options.folder.empty()) throw error("the data cache needs a folder");
  if (options.backend.empty()) throw error("the data cache needs the back-end's name");
  std::error_code unused;
  if (std::filesystem::exists(options.folder, unused) && !std::filesystem::is_directory(options.folder, unused)) {
    throw io_error("the data cache '" + options.folder.string() + "' is a file, not a folder");
  }
  task_source result;
  result.facts = inner.facts;
  result.origin = inner.origin;
  result.data = [inner = std::move(inner), options = std::move(options)](const std::string& task, std::size_t rows,
                                                                         std::uint64_t seed) {
    const auto path = disk_cache_file(options.folder, task, options.backend, rows, seed);
    // In the order a mismatch is reported.
    const std::vector<std::pair<std::string, std::string>> key{{"task", task},
                                                               {"backend", options.backend},
                                                               {"seed", std::to_string(seed)},
                                                               {"rows", std::to_string(rows)},
                                                               {"origin", inner.origin ? inner.origin(task) : ""}};
    std::error_code ec;
    if (std::filesystem::exists(path, ec)) {
      auto content = read_dataset_file(path);
      for (const auto& [name, value] : key) {
        const auto it = content.meta.find(name);
        if (it == content.meta.end() || it->second != value) {
          throw data_error(path.string() + ": made for another " + name + " (the file has " +
                           (it == content.meta.end() ? "none" : "'" + it->second + "'") + ", this run needs '" + value +
                           "'); delete it to make the data again");
        }
      }
      if (content.data.rows() != rows) {
        throw data_error(path.string() + ": holds " + std::to_string(content.data.rows()) + " rows, not " +
                         std::to_string(rows));
      }
      if (options.note) options.note("read " + std::to_string(rows) + " rows of " + task + " from " + path.string());
      return std::move(content.data);
    }
    auto made = inner.data(task, rows, seed);
    std::filesystem::create_directories(options.folder, ec);
    if (ec) throw io_error("cannot make the data cache '" + options.folder.string() + "': " + ec.message());
    write_dataset_file(path, made, dataset_file_meta(key.begin(), key.end()));
    if (options.note) options.note("wrote " + std::to_string(rows) + " rows of " + task + " to " + path.string());
    return made;
  };
  return result;
}

}  // namespace pgm
