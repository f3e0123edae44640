#pragma once
/// \file
/// Structure learning for a dynamic network (pgm/core/dynamic_network.hpp) from episodes in long
/// form: any structure learner over the transitions' data (each template variable X at a step and
/// X@-1 at the step before), with background knowledge that keeps the previous slice's variables
/// roots, so that an edge between slices runs forward only. The first slice takes the learned
/// edges within a slice: its own t = 0 rows, one per episode, are too few to learn from.

#include <string>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/episodes.hpp"
#include "pgm/learn/bootstrap.hpp"
#include "pgm/learn/fit_dynamic.hpp"
#include "pgm/learn/learn_structure.hpp"

namespace pgm {

struct dynamic_structure_result {
  dynamic_structure structure;
  /// What the learner found over the two slices (`X@-1` and X), its edges among them.
  structure_result learned;
};

namespace detail {

/// `context` with every edge into the previous slice forbidden, from either slice.
[[nodiscard]] PGM_DECL structure_context two_slice_context(const std::vector<variable>& templates,
                                                           structure_context context);

/// The template variables of `names`: discrete columns of `data` (data_error otherwise).
[[nodiscard]] PGM_DECL std::vector<variable> template_variables(const dataset& data,
                                                                std::span<const std::string> names);

}  // namespace detail

/// Learns a dynamic network's structure over the template variables `names` of the long-form
/// `data` with `learner`; `context` names the two slices' variables (`a@-1->b` in its
/// knowledge, say). Throws data_error for bad episodes or columns, as fit_dynamic does.
template <StructureLearner L>
[[nodiscard]] dynamic_structure_result learn_dynamic_structure(const dataset& data, std::span<const std::string> names,
                                                               const L& learner, structure_context context = {},
                                                               const episode_columns& columns = {}) {
  const auto templates = detail::template_variables(data, names);
  const auto slices = slices_of(data, templates, index_episodes(data, columns));
  std::vector<std::string> both;
  for (const auto& v : templates) both.push_back(slice_name(v.name(), -1));
  for (const auto& v : templates) both.push_back(v.name());
  auto learned =
      learn_structure(slices.transitions, both, learner, detail::two_slice_context(templates, std::move(context)));
  auto structure = dynamic_structure_of(templates, learned.edges);
  return {std::move(structure), std::move(learned)};
}

struct dynamic_bootstrap_result {
  /// The averaged network's structure.
  dynamic_structure structure;
  /// Every arc's strength and direction over the two slices' variables (`X@-1` and X), and the
  /// averaged network's arcs among them.
  bootstrap_result arcs;
};

/// learn_dynamic_structure on `options.replicates` bootstrap resamples of the episodes (whole
/// episodes drawn with replacement, so that a step keeps the step before it; each replicate
/// seeded by the seed and its number, in parallel on `context.threads`), then the arcs'
/// strengths and the averaged network as bootstrap_structure gives them: the result is the
/// same for any number of threads. Throws as learn_dynamic_structure and bootstrap_structure do.
[[nodiscard]] PGM_DECL dynamic_bootstrap_result bootstrap_dynamic_structure(
    const dataset& data, std::span<const std::string> names, const structure_learner& learner,
    const structure_context& context, const bootstrap_options& options, const episode_columns& columns = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/learn_dynamic_structure.ipp"
#endif
