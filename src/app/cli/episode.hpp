#pragma once
// A dynamic network's data in long form (episode,t,<variables>): the episodes `pgm fit
// --dynamic` and `pgm update` count, and one episode as `pgm filter` and `pgm prevent --dynamic`
// read it.

#include <set>
#include <string>
#include <vector>

#include "pgm/core/dynamic_network.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/missing.hpp"
#include "pgm/inference/query.hpp"

namespace pgm::cli {

/// A template variable by name, or an error naming the closest; `where` names the input.
variable_id template_id(const dynamic_network& model, const std::string& name, const std::string& where);

/// Episodes in long form from `path` ("-": standard input): the columns of `templates` (those
/// of `model` read with its states, when given), the step's and, where present, the episode's.
dataset read_episodes(const std::string& path, const std::set<std::string>& templates, const dynamic_network* model,
                      const missing_values& missing, unsigned threads);

/// One episode's evidence per step from the long form: the rows in order of t = 0, 1, …, an
/// empty cell (or NA, ?) unobserved; an error for a second episode, a gap in t or a column that
/// is no variable of the model.
std::vector<evidence_set> read_episode(const dynamic_network& model, const std::string& path);

}  // namespace pgm::cli
