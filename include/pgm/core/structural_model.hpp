#pragma once
/// \file
/// `structural_model`: a discrete structural causal model. Every variable is a deterministic
/// function of its parents and of an exogenous noise of its own, the noises independent:
///
///     V = f_V(parents(V), U_V),   P(U_V = k) given, k = 0 … noise states − 1
///
/// What a causal network leaves open and a counterfactual needs: which units (noise values) move
/// how when the parents change (pgm/causal/counterfactual.hpp). `network()` is the causal
/// network the model implies, P(V = s | pa) = Σ_{k : f_V(pa, k) = s} P(U_V = k).
///
/// A function's values are numbered per configuration of the parents (the last parent fastest,
/// as `cpt` numbers them), then per noise state: values[config × noise states + k] is the state
/// of V.

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/dag.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/core/variable.hpp"

namespace pgm {

/// V = f(parents, U): the noise's distribution and the function as a table.
struct structural_equation {
  std::vector<variable_id> parents;
  /// P(U = k), one entry per noise state.
  std::vector<double> noise;
  /// The state of V per configuration of the parents (last fastest), per noise state.
  std::vector<std::size_t> values;
  friend bool operator==(const structural_equation&, const structural_equation&) = default;
};

class structural_model {
 public:
  structural_model() = default;

  /// `equations[i]` is the equation of `variables[i]`. Throws model_error naming the variable
  /// for two variables of one name, a parent out of range or repeated, a noise that is not a
  /// distribution (finite, ≥ 0, summing to 1 within 1e-6), a function of the wrong size or with a
  /// state out of range, and not_a_dag (naming the cycle) when the parents form one.
  PGM_DECL structural_model(std::vector<variable> variables, std::vector<structural_equation> equations);

  [[nodiscard]] const std::vector<variable>& variables() const noexcept { return variables_; }
  [[nodiscard]] std::size_t size() const noexcept { return variables_.size(); }
  [[nodiscard]] const variable& at(variable_id id) const { return variables_.at(id.value()); }
  /// The id of a variable; throws model_error naming the unknown one and the known ones.
  [[nodiscard]] variable_id id(std::string_view name) const { return graph_.id(name); }
  [[nodiscard]] bool contains(std::string_view name) const { return graph_.contains(name); }
  [[nodiscard]] const structural_equation& equation(variable_id id) const { return equations_.at(id.value()); }
  [[nodiscard]] const dag& graph() const noexcept { return graph_; }

  /// f_V(parents' states, k): the state V takes.
  [[nodiscard]] PGM_DECL std::size_t value(variable_id v, std::size_t configuration, std::size_t noise_state) const;

  /// The causal network the model implies (its observational and interventional distributions).
  [[nodiscard]] PGM_DECL bayesian_network network() const;

  friend bool operator==(const structural_model& a, const structural_model& b) {
    return a.variables_ == b.variables_ && a.equations_ == b.equations_;
  }

 private:
  std::vector<variable> variables_;
  std::vector<structural_equation> equations_;
  dag graph_;
};

/// The number of configurations of `parents` (1 for none).
[[nodiscard]] PGM_DECL std::size_t parent_configurations(const structural_model& model,
                                                         const std::vector<variable_id>& parents);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/structural_model.ipp"
#endif
