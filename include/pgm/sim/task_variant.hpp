#pragma once
/// \file
/// A task by name and variant, as `pgm simulate --task --variant` and the Python
/// `pgm.simulate(task, variant=)` name it: "2-stack" with variant "reality" is the task file
/// "2-stack-reality" (the stand-in for the real robot, not real data).

#include <algorithm>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/sim/task.hpp"
#include "pgm/sim/task_lookup.hpp"

namespace pgm::sim {

/// The name of `task`'s `variant` ("sim" or "reality"). Throws pgm::error for another variant,
/// or a reality task ("2-stack-reality") asked for as "sim".
[[nodiscard]] PGM_DECL std::string task_variant_name(std::string_view task, std::string_view variant);

/// Loads `task`'s `variant` from the first directory that has it. Throws unknown_name for an
/// unknown task, data_error for a task without a reality variant.
[[nodiscard]] PGM_DECL task_definition load_task_variant(std::string_view task, std::string_view variant,
                                                         const std::vector<std::filesystem::path>& directories);

}  // namespace pgm::sim

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/sim/impl/task_variant.ipp"
#endif
