#pragma once
/// \file
/// The success event of a task, e.g. onTop2 = 1: what predictions, preventions and the metrics
/// of a transfer ask the probability of, and what a model's metadata may name.

#include <string>
#include <string_view>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"

namespace pgm {

/// Which variable and state mean "the task succeeded", e.g. onTop2 = 1.
struct success_event {
  std::string variable;
  std::string state;
  friend bool operator==(const success_event&, const success_event&) = default;
};

/// The default success event: the unique node that has parents, no children and a state
/// labelled "1". Throws model_error when there is no such node or more than one, naming them.
[[nodiscard]] PGM_DECL success_event default_success_event(const bayesian_network& network);

/// Parses "variable=state" and checks it against the network.
[[nodiscard]] PGM_DECL success_event parse_success_event(std::string_view text, const bayesian_network& network);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/success_event.ipp"
#endif
