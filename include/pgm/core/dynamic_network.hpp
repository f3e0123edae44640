#pragma once
/// \file
/// `dynamic_network`: a two-slice temporal Bayesian network (2-TBN) over template variables, a
/// task that unfolds over several actions. The first slice is a Bayesian network of its own; in
/// every later slice each variable has one table (tied: shared by every slice), whose parents lie
/// in the same slice or the one before. Unrolled over T slices it is a `bayesian_network` whose
/// variables are named `X@t`, t = 0 … T−1, on which every engine, format and command works.
///
/// The transition is held as a network over two slices: each template variable X once as `X@-1`
/// (the previous slice; no table, no parents) and once as `X` (this slice, with its table).

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/core/variable.hpp"

namespace pgm {

/// How a variable of a slice is named: "X@t", and "X@-1" for the previous slice in a transition
/// (with another separator for formats whose names cannot hold '@': "X_t").
[[nodiscard]] inline std::string slice_name(std::string_view name, long slice, char separator = '@') {
  return std::string(name) + separator + std::to_string(slice);
}

/// The template variable a slice's name stands for: "X" for "X", "X@-1" and "X@3".
[[nodiscard]] inline std::string template_of(std::string_view name) {
  return std::string(name.substr(0, name.rfind('@')));
}

class dynamic_network {
 public:
  dynamic_network() = default;

  /// `initial`: the first slice, over the template variables. `transition`: one table per template
  /// variable, its parents named `Y` (this slice) or `Y@-1` (the previous one). Throws model_error
  /// naming what is wrong: a table missing or given twice, a parent of another slice (`Y@-2`,
  /// `Y@+1`) or unknown, states that differ from the template's, a cycle within a slice.
  PGM_DECL dynamic_network(bayesian_network initial, std::vector<cpt<double>> transition);

  /// The template variables, in the first slice's order.
  [[nodiscard]] const std::vector<variable>& variables() const noexcept { return initial_.variables(); }
  [[nodiscard]] std::size_t size() const noexcept { return initial_.size(); }
  [[nodiscard]] const bayesian_network& initial() const noexcept { return initial_; }
  /// The two-slice network: `X@-1` for every template variable X (roots), then X.
  [[nodiscard]] const network_structure& transition_structure() const noexcept { return transition_; }
  /// The two-slice network of these template variables, without edges: each X as `X@-1`, then
  /// as X. Throws model_error on a repeated name.
  [[nodiscard]] PGM_DECL static network_structure two_slices(const std::vector<variable>& templates);
  /// The transition tables, in template order.
  [[nodiscard]] const std::vector<cpt<double>>& transition_tables() const noexcept { return tables_; }

  /// The network of `slices` slices (at least 1): `X@0` … `X@(slices−1)` for every template
  /// variable X (`X_0` … with `separator` '_'), the first slice's tables at t = 0 and the
  /// transition's after it.
  [[nodiscard]] PGM_DECL bayesian_network unroll(std::size_t slices, char separator = '@') const;

  friend bool operator==(const dynamic_network&, const dynamic_network&) = default;

 private:
  bayesian_network initial_;
  network_structure transition_;
  std::vector<cpt<double>> tables_;
};

namespace detail {

/// `v` under another name, with its states, edges and tags.
[[nodiscard]] PGM_DECL variable renamed(const variable& v, std::string name);

/// `table` with its child and parents renamed (same states, same values, dense or sparse).
[[nodiscard]] PGM_DECL cpt<double> renamed(const cpt<double>& table, variable child, std::vector<variable> parents);

/// Which slice a transition's parent `name` of `child` lies in: {"Y", 0} for "Y", {"Y", −1} for
/// "Y@-1". Throws model_error for another slice or a malformed one, saying which and why.
[[nodiscard]] PGM_DECL std::pair<std::string, long> slice_of_parent(const std::string& name, const std::string& child);

}  // namespace detail

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/dynamic_network.ipp"
#endif
