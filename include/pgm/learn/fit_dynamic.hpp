#pragma once
/// \file
/// Fitting a dynamic network (pgm/core/dynamic_network.hpp) from episodes in long form
/// (pgm/data/episodes.hpp) with tied parameters: the first slice's tables from the rows at t = 0,
/// and each template variable's one transition table from the rows of every later step of every
/// episode, each counted with the step before. Any parameter prior of a static fit applies.

#include <map>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/dynamic_network.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/episodes.hpp"
#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/learn/fit.hpp"
#include "pgm/learn/parameter_prior.hpp"

namespace pgm {

/// What a dynamic network is before its tables: the first slice over the template variables,
/// and the transition over two slices (dynamic_network::two_slices: each X as `X@-1`, then X).
struct dynamic_structure {
  network_structure initial;
  network_structure transition;

  [[nodiscard]] const std::vector<variable>& variables() const noexcept { return initial.variables(); }
  friend bool operator==(const dynamic_structure&, const dynamic_structure&) = default;
};

/// The structure of these template variables with `edges`: "a->b" lies within a slice (the
/// first and every later one), "a@-1->b" runs from the slice before (the transition only).
/// Throws model_error for an edge into another slice (`a->b@-1`), from a later slice or more
/// than one back, or naming no template variable; not_a_dag for a cycle within a slice.
[[nodiscard]] PGM_DECL dynamic_structure dynamic_structure_of(std::vector<variable> templates,
                                                              const std::vector<named_edge>& edges);

/// The same, its template variables the discrete columns of `data` that `edges` name, in the
/// data's column order, then the `latent` ones, which no column holds (EM estimates them,
/// pgm/learn/dynamic_em.hpp). Throws data_error for a column that is absent or continuous, or
/// a latent variable the data hold; model_error for a latent variable in no edge.
[[nodiscard]] PGM_DECL dynamic_structure dynamic_structure_from_data(const dataset& data,
                                                                     const std::vector<named_edge>& edges,
                                                                     const std::vector<variable>& latent = {});

namespace detail {

/// "a, b, c": the template variables, for messages.
[[nodiscard]] PGM_DECL std::string template_list(const network_structure& templates);

}  // namespace detail

/// The structure of a dynamic network, without its tables.
[[nodiscard]] PGM_DECL dynamic_structure structure_of(const dynamic_network& model);

/// The long form as the two slices' data: `initial` holds each episode's row at t = 0 (columns
/// named X), `transitions` one row per later step, with each template variable's value at that
/// step (X) and at the step before (X@-1).
struct slice_data {
  dataset initial;
  dataset transitions;
};

/// Splits `data` into slices by `episodes`. Throws data_error for a template variable whose
/// column is absent, continuous or of other states.
[[nodiscard]] PGM_DECL slice_data slices_of(const dataset& data, const std::vector<variable>& templates,
                                            const episode_index& episodes);

/// The counts of every table: each first-slice family over the rows at t = 0, each transition
/// family over every later step (tied), in template order.
struct dynamic_counts {
  std::vector<count_table> initial;
  std::vector<count_table> transition;
  std::size_t episodes = 0;
  std::size_t steps = 0;  ///< rows of the long form
};

struct dynamic_fit_options {
  /// The prior of every table; `fit.node_priors` gives single template variables' transition
  /// tables their own (a transferred `weighted_prior`, say).
  fit_options fit;
  /// Priors of single first-slice tables, by template variable.
  std::map<std::string, parameter_prior, std::less<>> initial_priors;
  episode_columns columns;
};

/// Counts every family of `structure` in the long-form `data`.
[[nodiscard]] PGM_DECL dynamic_counts count_dynamic(const dynamic_structure& structure, const dataset& data,
                                                    const episode_columns& columns = {},
                                                    const count_options& counting = {});

/// Fits every table of `structure` from its counts.
[[nodiscard]] PGM_DECL dynamic_network fit_dynamic(const dynamic_structure& structure, const dynamic_counts& counts,
                                                   const dynamic_fit_options& options = {});

/// Fits every table of `structure` from the long-form `data`.
[[nodiscard]] PGM_DECL dynamic_network fit_dynamic(const dynamic_structure& structure, const dataset& data,
                                                   const dynamic_fit_options& options = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/fit_dynamic.ipp"
#endif
