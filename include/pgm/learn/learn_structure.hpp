#pragma once
/// \file
/// One entry point for structure learning, which the program and the Python package both call:
/// `learn_structure(data, learner)` runs any StructureLearner (pgm/learn/structure_learner.hpp)
/// over the data's discrete columns — PC-stable, hill climbing, tabu search, the hybrid, or a
/// user's learner chosen by name (`make_structure_learner("tabu[score=bdeu[iss=10]]")`).

#include <span>
#include <string>

#include "pgm/core/compilation.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/learn/structure_learner.hpp"
#include "pgm/learn/structure_learner_registry.hpp"
#include "pgm/learn/structure_learners.hpp"

namespace pgm {

/// The problem of learning over the named columns of `data`. Throws data_error for a missing
/// or continuous column.
[[nodiscard]] PGM_DECL structure_problem structure_problem_of(const dataset& data, std::span<const std::string> names,
                                                              structure_context context = {});

/// Learns a structure over the named columns of `data` (all discrete) with `learner`, its
/// result's `learner` the learner's name. Throws model_error for knowledge or a context the
/// learner refuses, data_error for a missing or continuous column.
template <StructureLearner L>
[[nodiscard]] structure_result learn_structure(const dataset& data, std::span<const std::string> names,
                                               const L& learner, structure_context context = {}) {
  auto result = learner.learn(structure_problem_of(data, names, std::move(context)));
  if constexpr (requires { learner.name(); }) result.learner = learner.name();
  return result;
}

/// Learns a structure over every column of `data`.
template <StructureLearner L>
[[nodiscard]] structure_result learn_structure(const dataset& data, const L& learner, structure_context context = {}) {
  const auto names = data.names();
  return learn_structure(data, names, learner, std::move(context));
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/learn_structure.ipp"
#endif
