#pragma once
// The definitions of pgm/sim/run.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/sim/run.hpp"

namespace pgm::sim {

PGM_DECL void sample_inputs(const task_definition& task, std::uint64_t seed, std::uint64_t index,
                            std::span<double> values) {
  random_stream inputs(seed, index, stream_purpose::inputs);
  for (std::size_t k = 0; k < task.variables.size(); ++k) {
    const auto& v = task.variables[k];
    values[k] = v.kind == variable_kind::outcome ? 0.0 : v.sampling.sample(inputs);
  }
}

}  // namespace pgm::sim
