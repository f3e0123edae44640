#pragma once
// The definitions of pgm/detail/parallel_for.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/detail/parallel_for.hpp"

namespace pgm::detail {

PGM_DECL unsigned worker_count(std::size_t n, const parallel_options& options) noexcept {
  const std::size_t items = options.share.of(n).size();
  if (items == 0) return 0;
  const std::size_t chunk = std::max<std::size_t>(1, options.chunk);
  const std::size_t chunks = items / chunk + (items % chunk != 0);
  const std::size_t by_work = std::max<std::size_t>(1, items / std::max<std::size_t>(1, options.min_items_per_thread));
  return static_cast<unsigned>(std::min({std::size_t{resolve_threads(options.threads)}, chunks, by_work}));
}

PGM_DECL void sum_over_processes(process_group& group, std::span<std::uint64_t> values, std::exception_ptr failure) {
  agree(group, failure);
  if (group.size() == 1) return;
  group.sum(values);
}

}  // namespace pgm::detail
