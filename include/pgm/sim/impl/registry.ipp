#pragma once
// The definitions of pgm/sim/registry.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/sim/registry.hpp"

namespace pgm::sim {

PGM_DECL backend_function backend_registry::at(std::string_view name) const {
  if (auto run = backends_.find(name)) return *std::move(run);
  if (name == "bullet") {
    throw data_error(
        "the bullet back-end was not built (configure with -DPGM_BUILD_BULLET=ON and "
        "libbullet-dev installed, and link pgm_bullet)");
  }
  throw unknown_name("simulator back-end", std::string(name), names());
}

}  // namespace pgm::sim
