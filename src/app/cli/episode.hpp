#pragma once
// One episode of a dynamic network's data in long form (episode,t,<variables>), as `pgm filter`
// and `pgm prevent --dynamic` read it.

#include <string>
#include <vector>

#include "pgm/core/dynamic_network.hpp"
#include "pgm/inference/query.hpp"

namespace pgm::cli {

/// A template variable by name, or an error naming the closest; `where` names the input.
variable_id template_id(const dynamic_network& model, const std::string& name, const std::string& where);

/// One episode's evidence per step from the long form: the rows in order of t = 0, 1, …, an
/// empty cell (or NA, ?) unobserved; an error for a second episode, a gap in t or a column that
/// is no variable of the model.
std::vector<evidence_set> read_episode(const dynamic_network& model, const std::string& path);

}  // namespace pgm::cli
