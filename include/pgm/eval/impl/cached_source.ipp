#pragma once
// The definitions of pgm/eval/cached_source.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/eval/cached_source.hpp"

namespace pgm {

PGM_DECL task_source cached(task_source inner) {
  struct state {
    task_source inner;
    std::mutex mutex;
    std::map<std::tuple<std::string, std::size_t, std::uint64_t>, dataset> data;
  };
  auto shared = std::make_shared<state>();
  shared->inner = std::move(inner);
  task_source result;
  result.data = [shared](const std::string& task, std::size_t rows, std::uint64_t seed) {
    auto key = std::make_tuple(task, rows, seed);
    {
      const std::lock_guard lock(shared->mutex);
      if (const auto it = shared->data.find(key); it != shared->data.end()) return it->second;
    }
    auto made = shared->inner.data(task, rows, seed);
    const std::lock_guard lock(shared->mutex);
    return shared->data.emplace(std::move(key), std::move(made)).first->second;
  };
  result.facts = [shared](const std::string& task, const std::string& node) { return shared->inner.facts(task, node); };
  if (shared->inner.origin) {
    result.origin = [shared](const std::string& task) { return shared->inner.origin(task); };
  }
  return result;
}

}  // namespace pgm
