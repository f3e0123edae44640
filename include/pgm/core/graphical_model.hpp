#pragma once
/// \file
/// The `GraphicalModel` concept: what every exact and message-passing engine takes. A model is
/// a set of named discrete variables and a set of factors over them; P(x) ∝ Π_f φ_f(x_f). It
/// gives its variables (`variables()`, `id(name)`), the number of its factors and, for each, its
/// scope (variable ids, the last fastest in the numbering of its values) and its table
/// (`factor(f)`, a `factor_table` or anything with `scope()`, `cardinalities()` and `values()`).
///
/// | model | factors |
/// |---|---|
/// | `bayesian_network` | one per node: its table over (parents…, node); Z = 1 |
/// | `markov_network` | its potentials, any scopes; Z the partition function |
///
/// A model that is a DAG with a table per node (`DirectedModel`) also lets an engine leave out
/// barren nodes and answer interventions; engines that need a DAG (likelihood weighting, do())
/// require it and say so by name when given another model.

#include <concepts>
#include <cstddef>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/factor_table.hpp"
#include "pgm/core/markov_network.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/core/variable.hpp"

namespace pgm {

namespace detail {

template <class T>
concept ReadsAsFactorTable = requires(const T& table) {
  { table.scope() } -> std::convertible_to<std::span<const variable_id>>;
  { table.cardinalities() } -> std::convertible_to<std::span<const std::size_t>>;
  { table.values() } -> std::convertible_to<std::span<const double>>;
};

template <class M>
concept HasNamedVariables = requires(const M& model, std::string_view name) {
  { model.variables() } -> std::same_as<const std::vector<variable>&>;
  { model.size() } -> std::convertible_to<std::size_t>;
  { model.id(name) } -> std::same_as<variable_id>;
};

template <class M>
concept HasFactors = requires(const M& model, std::size_t f) {
  { model.factor_count() } -> std::convertible_to<std::size_t>;
  { model.factor_scope(f) } -> std::convertible_to<std::vector<variable_id>>;
  { model.factor(f) } -> ReadsAsFactorTable;
};

}  // namespace detail

/// Named discrete variables and factors over them.
template <class M>
concept GraphicalModel = detail::HasNamedVariables<M> && detail::HasFactors<M>;

/// A graphical model whose factor i is the table of variable i given its parents in a DAG.
template <class M>
concept DirectedModel = GraphicalModel<M> && requires(const M& model) {
  { model.graph() } -> std::same_as<const dag&>;
  { model.tables() } -> std::convertible_to<const std::vector<cpt<double>>&>;
};

/// What a model class is called in messages ("a Markov network does not ...").
template <GraphicalModel M>
[[nodiscard]] constexpr std::string_view model_kind() noexcept {
  if constexpr (DirectedModel<M>) {
    return "Bayesian network";
  } else {
    return "Markov network";
  }
}

/// A model lent to an engine without a copy. The engine shares no ownership, so the model must
/// outlive it (the caller's promise, as with a std::span): for an engine made and dropped
/// within the scope that holds the model. Engines given the model itself keep their own copy.
template <GraphicalModel M>
[[nodiscard]] std::shared_ptr<const M> borrowed(const M& model) noexcept {
  return std::shared_ptr<const M>(std::shared_ptr<const M>(), &model);
}

static_assert(DirectedModel<bayesian_network>);
static_assert(GraphicalModel<markov_network> && !DirectedModel<markov_network>);

}  // namespace pgm
