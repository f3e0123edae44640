#pragma once
// The definitions of pgm/eval/disk_cache.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/eval/disk_cache.hpp"

namespace pgm {

PGM_DECL std::filesystem::path disk_cache_file(const std::filesystem::path& folder, const std::string& task,
                                               const std::string& backend, std::size_t rows, std::uint64_t seed) {
  return folder /
         (task + "." + backend + ".seed-" + std::to_string(seed) + ".rows-" + std::to_string(rows) + ".pgmdata");
}

PGM_DECL task_source disk_cached(task_source inner, disk_cache_options options) {
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
