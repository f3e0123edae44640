#pragma once
// missing="em"'s options as pgm/__init__.py passes them to pgm.fit and pgm.fit_dynamic.

#include <cstddef>
#include <cstdint>
#include <tuple>

#include "pgm/learn/expectation_maximization.hpp"

namespace pgm::python {

/// (restarts, seed, max_iterations, tolerance, hard).
using em_arguments = std::tuple<std::size_t, std::uint64_t, std::size_t, double, bool>;

inline em_options em_options_of(const em_arguments& args, unsigned threads) {
  em_options options;
  std::tie(options.restarts, options.seed, options.max_iterations, options.tolerance, std::ignore) = args;
  options.kind = std::get<4>(args) ? em_kind::hard : em_kind::soft;
  options.threads = threads;
  return options;
}

}  // namespace pgm::python
