#pragma once
/// \file
/// Inference over time in a `dynamic_network`, by the interface algorithm: the variables of a
/// slice with a child in the next (the interface) separate the past from the future, so two
/// junction trees compiled once carry everything from one step to the next in a table over the
/// interface. The first slice's tree holds the first slice's tables; the transition's holds one
/// slice's tables and the previous slice's interface, whose prior (the last step's filtered
/// interface) is a factor set anew at each step (`propagation::set_factor`). A step costs the
/// same at step 10 and at step 10,000.
///
/// - filtering: P(X_t | e_0..t), each step's interface normalised, ln P(e_0..t) summed from the
///   normalisers;
/// - prediction: the same steps past the last, without evidence;
/// - smoothing: P(X_t | e_0..T−1), forward then backward: β_t(I_t) = P(e_t+1..T−1 | I_t) enters the
///   tree as a factor over slice t's interface;
/// - the most probable sequence: the joint state of every variable at every step of highest
///   probability with the evidence (Viterbi through the interface): max-product forward, then
///   back, each step maximised with its interface held at the state the next step chose;
/// - do(X = x) at a step: the intervention of that step's propagation (X's table left out).
///
/// Evidence is given per step over the template variables' ids.

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/dynamic_network.hpp"
#include "pgm/inference/junction_tree.hpp"
#include "pgm/inference/propagation.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/inference/semiring.hpp"

namespace pgm {

/// Every template variable's distribution at each step: [step][variable][state], each summing
/// to 1 (an observed variable's a point mass).
struct dynamic_marginals {
  std::vector<std::vector<std::vector<double>>> steps;
  double log_evidence_probability = 0.0;  ///< ln P(every step's evidence)
};

/// The most probable joint state of every template variable at every step: [step][variable].
struct most_probable_steps {
  std::vector<std::vector<std::size_t>> states;
  double log_probability = 0.0;  ///< ln P(x*, every step's evidence)
};

class interface_filter {
 public:
  /// Compiles the two trees. Throws table_too_large as a junction tree does.
  PGM_DECL explicit interface_filter(dynamic_network model, const junction_tree_options& options = {});

  [[nodiscard]] const dynamic_network& model() const noexcept { return model_; }
  /// The interface: the template variables that have a child in the next slice, ascending.
  [[nodiscard]] const std::vector<variable_id>& interface() const noexcept { return interface_; }

  /// P(X_t | e_0..t) for t = 0 … steps.size() − 1, then P(X_t | e_0..T−1) for `predict` more
  /// steps. Throws impossible_evidence naming the first step whose evidence has probability 0
  /// given the steps before.
  [[nodiscard]] PGM_DECL dynamic_marginals filter(std::span<const evidence_set> steps, std::size_t predict = 0);

  /// P(X_t | e_0..T−1) for every step t.
  [[nodiscard]] PGM_DECL dynamic_marginals smooth(std::span<const evidence_set> steps);

  /// The most probable joint state of every variable at every step given the evidence (ties
  /// settled the same way every time). Throws impossible_evidence as filter does.
  [[nodiscard]] PGM_DECL most_probable_steps most_probable(std::span<const evidence_set> steps);

 private:
  struct step_answer {
    std::vector<std::vector<double>> marginals;  ///< normalised
    std::vector<double> interface;               ///< the joint over the interface, normalised
    double log_total = 0.0;                      ///< ln of what was normalised away
  };

  /// One step: the first slice (`first`) or a transition from `prior` (the last interface's
  /// distribution), with `future` (β over this slice's interface) and this step's evidence.
  /// `step` names the step in an error.
  step_answer step(bool first, const std::vector<double>& prior, const std::vector<double>& future,
                   const evidence_set& observed, std::size_t step);

  /// "the evidence at step t (…) has probability 0 given the steps before".
  [[nodiscard]] impossible_evidence impossible_at(std::size_t step, const evidence_set& observed) const;

  /// β_{t−1} from β_t and step t's evidence: the previous interface's joint in the transition
  /// with no prior, normalised (its scale does not matter to smoothing).
  std::vector<double> backward(const std::vector<double>& future, const evidence_set& observed, std::size_t step);

  /// Sets factor f of `in` to `values` unless `now` (what it holds) is the same already: each set
  /// drops the messages from its clique.
  template <class Propagation>
  static void set_if_changed(Propagation& in, std::size_t f, const std::vector<double>& values,
                             std::vector<double>& now) {
    if (values == now) return;
    in.set_factor(f, values);
    now = values;
  }

  dynamic_network model_;
  std::vector<variable_id> every_;  ///< every template variable's id, for a step's marginals
  std::vector<variable_id> interface_;
  std::size_t interface_cells_ = 1;
  std::vector<variable_id> previous_interface_;  ///< the interface's ids in the transition's tree
  std::unique_ptr<propagation<sum_product<double>>> first_;
  std::unique_ptr<propagation<sum_product<double>>> transition_;
  // The same trees in max-product, for the most probable sequence.
  std::unique_ptr<propagation<max_product<double>>> first_max_;
  std::unique_ptr<propagation<max_product<double>>> transition_max_;
  // What the prior and β factors of each tree hold now.
  std::vector<double> first_future_, transition_prior_, transition_future_, max_prior_;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/inference/impl/dynamic_inference.ipp"
#endif
