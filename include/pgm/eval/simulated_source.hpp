#pragma once
/// \file
/// The link between simulation and evaluation: a task source whose data come from
/// pgm::sim::simulate on the task files of some folders, and whose facts (known parents,
/// semantic tags, controllable variables) come from those files. It simulates on every call;
/// wrap it in pgm::cached (eval/cached_source.hpp) to share data between scenarios.

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/detail/checksum.hpp"
#include "pgm/eval/experiment.hpp"
#include "pgm/sim/simulator.hpp"
#include "pgm/sim/task.hpp"
#include "pgm/sim/task_lookup.hpp"

namespace pgm {

/// What the protocol needs of `node` in `task`: its parents in the task's known structure, the
/// tags of every variable, which variables the robot controls, and the success state of an
/// outcome.
[[nodiscard]] PGM_DECL task_facts facts_of(const sim::task_definition& task, const std::string& node);

struct simulated_source_options {
  /// Where task files are looked up by name (pgm::sim::default_task_directories()).
  std::vector<std::filesystem::path> task_folders;
  std::string backend = "analytic";
  unsigned threads = 0;  ///< 0: every core
  /// Experiments of `task` finished so far, out of `total`, while its data are simulated.
  std::function<void(const std::string& task, std::size_t done, std::size_t total)> progress;
};

/// A source simulating each task named by a scenario. Task files are read once; copies of
/// the result share them, and it is safe to call from several threads.
[[nodiscard]] PGM_DECL task_source simulated_source(simulated_source_options options);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/eval/impl/simulated_source.ipp"
#endif
