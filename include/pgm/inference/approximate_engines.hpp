#pragma once
/// \file
/// Loopy belief propagation ("bp") and Gibbs sampling on the factors ("gibbs" for a model that is
/// not a Bayesian network) as engines over any model, for the registry and `pgm query`. Each
/// runs once per evidence and answers every variable's marginal from that run; a joint of two or
/// more variables is theirs to refuse (use jt or ve).
///
/// P(evidence): bp's is the Bethe estimate Z(e)/Z (exact where the factor graph is a tree; Z = 1
/// for a Bayesian network); a Gibbs chain has none, so its posteriors carry NaN there and its
/// log_probability_of_evidence() refuses.

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/graphical_model.hpp"
#include "pgm/inference/belief_propagation.hpp"
#include "pgm/inference/exact.hpp"
#include "pgm/inference/factor_gibbs.hpp"
#include "pgm/inference/query.hpp"

namespace pgm {

namespace detail {

/// What both engines share: the model, the evidence, and the marginals of the last run.
template <GraphicalModel M>
class marginals_engine {
 public:
  [[nodiscard]] const M& model() const noexcept { return *model_; }
  [[nodiscard]] const M& network() const noexcept requires DirectedModel<M> { return *model_; }
  [[nodiscard]] const evidence_set& evidence() const noexcept { return evidence_; }

 protected:
  explicit marginals_engine(std::shared_ptr<const M> model) : model_(std::move(model)) {
    if (!model_) throw model_error("the engine was given no model");
  }

  void replace_evidence(evidence_set observed, std::string_view engine) {
    if (!observed.intervened.empty()) {
      throw model_error("the engine '" + std::string(engine) + "' does not answer interventions (do); use jt or ve");
    }
    evidence_ = std::move(observed);
    marginals_.reset();
  }

  /// Each node's marginal, asked of `engine` one at a time.
  template <class Engine>
  [[nodiscard]] static std::vector<posterior> each_joint(Engine& engine, std::span<const variable_id> nodes) {
    std::vector<posterior> result;
    for (auto node : nodes) result.push_back(engine.joint(std::span(&node, 1)));
    return result;
  }

  /// The posterior of one variable from `marginals` (every variable's, in id order).
  [[nodiscard]] posterior one(std::span<const variable_id> query, const std::vector<std::vector<double>>& marginals,
                              double log_evidence, std::string_view engine) const {
    if (query.size() != 1) {
      throw model_error("the engine '" + std::string(engine) +
                        "' answers one variable's marginal at a time; ask for each, or use jt or ve for a joint");
    }
    const auto id = query.front();
    posterior p;
    p.engine = std::string(engine);
    p.variables.push_back(model_->variables()[id.value()]);
    const auto& values = marginals[id.value()];
    p.table = factor({id}, {values.size()}, values);
    p.log_evidence_probability = log_evidence;
    p.evidence_probability = std::exp(log_evidence);
    return p;
  }

  std::shared_ptr<const M> model_;
  evidence_set evidence_;
  std::optional<std::vector<std::vector<double>>> marginals_;
};

}  // namespace detail

/// Loopy belief propagation as an engine: one run per evidence, and one without evidence for
/// Z when P(evidence) is asked of a model that is not a Bayesian network.
template <GraphicalModel M = bayesian_network>
class belief_propagation_engine : public detail::marginals_engine<M> {
 public:
  using model_type = M;

  explicit belief_propagation_engine(M model, bp_options options = {})
      : belief_propagation_engine(std::make_shared<const M>(std::move(model)), options) {}
  explicit belief_propagation_engine(std::shared_ptr<const M> model, bp_options options = {})
      : detail::marginals_engine<M>(std::move(model)), options_(options) {}

  [[nodiscard]] std::string_view name() const noexcept { return "bp"; }
  void set_evidence(evidence_set observed) { this->replace_evidence(std::move(observed), name()); }

  [[nodiscard]] posterior joint(std::span<const variable_id> query) {
    const auto& marginals = run().marginals;
    return this->one(query, marginals, log_probability_of_evidence(), name());
  }

  [[nodiscard]] std::vector<posterior> marginals(std::span<const variable_id> nodes) {
    return this->each_joint(*this, nodes);
  }

  /// The Bethe estimate of ln Z(e) − ln Z (ln Z = 0 for a Bayesian network).
  [[nodiscard]] double log_probability_of_evidence() { return run().log_partition - log_partition(); }

  /// The Bethe estimate of ln Z without evidence (0 for a Bayesian network), run once.
  [[nodiscard]] double log_partition() {
    if constexpr (DirectedModel<M>) {
      return 0.0;
    } else {
      if (!log_partition_) log_partition_ = belief_propagation(*this->model_, {}, options_).log_partition;
      return *log_partition_;
    }
  }

  /// The last run: converged or not, its iterations and residual.
  [[nodiscard]] const bp_result& last_run() { return run(); }

 private:
  const bp_result& run() {
    if (!this->marginals_) {
      result_ = belief_propagation(*this->model_, this->evidence_, options_);
      this->marginals_ = result_.marginals;
    }
    return result_;
  }

  bp_options options_;
  bp_result result_;
  std::optional<double> log_partition_;
};

/// Gibbs sampling on the factors as an engine: one chain per evidence, seeded.
template <GraphicalModel M = markov_network>
class factor_gibbs_engine : public detail::marginals_engine<M> {
 public:
  using model_type = M;

  explicit factor_gibbs_engine(M model, factor_gibbs_options options = {})
      : factor_gibbs_engine(std::make_shared<const M>(std::move(model)), options) {}
  explicit factor_gibbs_engine(std::shared_ptr<const M> model, factor_gibbs_options options = {})
      : detail::marginals_engine<M>(std::move(model)), options_(options) {}

  [[nodiscard]] std::string_view name() const noexcept { return "gibbs"; }
  void set_evidence(evidence_set observed) { this->replace_evidence(std::move(observed), name()); }

  [[nodiscard]] posterior joint(std::span<const variable_id> query) {
    if (!this->marginals_) this->marginals_ = factor_gibbs(*this->model_, this->evidence_, options_).marginals;
    const double unknown = std::numeric_limits<double>::quiet_NaN();
    return this->one(query, *this->marginals_, this->evidence_.empty() ? 0.0 : unknown, name());
  }

  [[nodiscard]] std::vector<posterior> marginals(std::span<const variable_id> nodes) {
    return this->each_joint(*this, nodes);
  }

  [[nodiscard]] double log_probability_of_evidence() const {
    if (this->evidence_.empty()) return 0.0;
    throw model_error("Gibbs sampling does not estimate P(evidence); use jt, ve or bp");
  }

 private:
  factor_gibbs_options options_;
};

}  // namespace pgm
