#pragma once
/// \file
/// A task source that makes each data set once: scenarios that draw the same task, row count
/// and seed share one data set for the whole run (2-Stack-Reality and 2-Stack-SimToReal both
/// target 2-stack-reality, SphereDropping and Stack-To-Drop both the plate and the glass).
/// It wraps any source, so sources that keep data elsewhere (on disk, on other processes)
/// compose with it.

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>
#include <utility>

#include "pgm/eval/experiment.hpp"

namespace pgm {

/// `inner` with its data remembered by (task, rows, seed). Copies of the result share one
/// memory; it is safe to call from several threads (a data set asked for twice at once may be
/// made twice, and the first one kept). Task facts are passed through.
[[nodiscard]] inline task_source cached(task_source inner) {
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
