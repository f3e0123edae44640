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

#include "pgm/core/compilation.hpp"
#include "pgm/eval/experiment.hpp"

namespace pgm {

/// `inner` with its data remembered by (task, rows, seed). Copies of the result share one
/// memory; it is safe to call from several threads (a data set asked for twice at once may be
/// made twice, and the first one kept). Task facts are passed through.
[[nodiscard]] PGM_DECL task_source cached(task_source inner);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/eval/impl/cached_source.ipp"
#endif
