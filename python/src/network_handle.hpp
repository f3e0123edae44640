#pragma once
// The network a Python pgm.Network wraps, with what Python shows beside it.

#include <optional>
#include <string>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/learn/fit_statistics.hpp"

namespace pgm::python {

/// A network with what Python shows beside it: the success event a JSON model names, the
/// notes of the fit that made it, and the counts it can be updated from (keep_counts=True).
struct network_handle {
  bayesian_network network;
  std::optional<std::string> success;
  std::vector<std::string> notes;
  std::optional<fit_statistics> statistics;
};

}  // namespace pgm::python
