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

#include "pgm/core/compilation.hpp"
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
[[nodiscard]] PGM_DECL std::filesystem::path disk_cache_file(const std::filesystem::path& folder,
                                                             const std::string& task, const std::string& backend,
                                                             std::size_t rows, std::uint64_t seed);

/// `inner` with its data kept in `options.folder`. Safe to call from several threads; wrap
/// the result in pgm::cached to keep data in memory within a run as well.
[[nodiscard]] PGM_DECL task_source disk_cached(task_source inner, disk_cache_options options);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/eval/impl/disk_cache.ipp"
#endif
