#pragma once
// The definitions of pgm/inference/engine_registry.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/inference/engine_registry.hpp"

namespace pgm {

PGM_DECL any_inference_engine engine_registry::make(std::string_view name, const bayesian_network& network,
                                                    const inference_options& options) const {
  if (auto factory = factories_.find(name)) return (*factory)(network, options);
  throw unknown_name("inference engine", std::string(name), names());
}

}  // namespace pgm
