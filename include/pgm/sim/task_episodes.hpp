#pragma once
/// \file
/// A task of N actions read as episodes of N steps, the long form that dynamic networks learn
/// from (`episode,t,<variables>`; docs/dynamic.md). The variables numbered 1..N (xOff1, onTop1,
/// xOff2, …) become template variables without the number (xOff, onTop) at steps t = 0..N-1;
/// the others, the world's (colorDown), keep their name and repeat at every step.

#include <cstddef>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/sim/task.hpp"

namespace pgm::sim {

/// Where each step's template variables are among a task's variables.
struct episode_layout {
  std::size_t steps = 0;
  /// Template variables (numbered in the task), in the order of their first step's columns.
  std::vector<std::string> template_names;
  /// columns[t][j]: the task's variable that is template variable j at step t.
  std::vector<std::vector<std::size_t>> columns;
  /// The task's unnumbered variables, the same at every step.
  std::vector<std::size_t> constants;
};

/// The layout of a task whose actions are numbered. Throws data_error, naming the task and the
/// variable, for a task with no numbered variables (the drop tasks), a numbered variable
/// missing at some step (`'dropOff2' has no 'dropOff3'`) or a template name that is also an
/// unnumbered variable.
[[nodiscard]] PGM_DECL episode_layout episode_layout_of(const task_definition& task);

/// The experiments of `wide` (one row per episode, the task's columns) in long form: columns
/// `episode` (first_episode, first_episode + 1, …) and `t`, then the template variables, then
/// the constants; one row per episode and step, episodes in order. A template variable's
/// states and tags are its first step's, less the role (cubeUp1), which names one action.
[[nodiscard]] PGM_DECL dataset episodes_of(const dataset& wide, const task_definition& task,
                                           const episode_layout& layout, std::size_t first_episode = 0);

}  // namespace pgm::sim

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/sim/impl/task_episodes.ipp"
#endif
