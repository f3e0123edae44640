#pragma once
/// \file
/// Engines by name, for the `pgm` program, the Python package and code that picks one at run
/// time: `make_engine("jt", network, options)` gives an `any_inference_engine`. The built-in
/// names are ve, jt, lw, gibbs and auto; a user's engine joins with one line in its own
/// translation unit (linked as an object file, as for transfer strategies):
///
///     static const pgm::register_engine<my_engine> registered("mine");
///
/// where `my_engine` models InferenceEngine and is constructible from
/// (const bayesian_network&, const inference_options&).
///
/// "auto" is exact unless exact is out of reach: the junction tree when it compiles within
/// `inference_options::max_junction_tree_cells`, otherwise likelihood weighting; the engine's
/// name() is the one chosen and note() says why.

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/detail/named_registry.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/inference/gibbs_sampling.hpp"
#include "pgm/inference/inference_engine.hpp"
#include "pgm/inference/junction_tree_engine.hpp"
#include "pgm/inference/likelihood_weighting.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/inference/sampling_options.hpp"
#include "pgm/inference/variable_elimination.hpp"

namespace pgm {

/// What any engine may be built with; each takes the settings it knows.
struct inference_options {
  elimination_heuristic heuristic = elimination_heuristic::min_fill;
  /// "auto" compiles a junction tree up to this many cells, and "jt" refuses beyond it.
  std::size_t max_junction_tree_cells = std::size_t{1} << 27;
  sampling_options sampling;
};

/// Any engine, type-erased; it models MpeEngine itself (mpe throws model_error for an engine
/// that has none).
class any_inference_engine {
 public:
  template <InferenceEngine E>
  requires(!std::same_as<E, any_inference_engine>) explicit any_inference_engine(E engine, std::string note = {})
      : self_(std::make_unique<model<E>>(std::move(engine))), note_(std::move(note)) {}

  /// Interventions pass through; set_evidence refuses them for an engine that does not read them.
  static constexpr bool handles_interventions = true;
  [[nodiscard]] std::string_view name() const { return self_->name(); }
  /// Whether the engine inside reads interventions.
  [[nodiscard]] bool reads_interventions() const { return self_->reads_interventions(); }
  [[nodiscard]] const bayesian_network& network() const { return self_->network(); }
  [[nodiscard]] const evidence_set& evidence() const { return self_->evidence(); }
  void set_evidence(evidence_set observed) { self_->set_evidence(std::move(observed)); }
  [[nodiscard]] posterior joint(std::span<const variable_id> query) { return self_->joint(query); }
  [[nodiscard]] std::vector<posterior> marginals(std::span<const variable_id> nodes) { return self_->marginals(nodes); }
  [[nodiscard]] double log_probability_of_evidence() { return self_->log_probability_of_evidence(); }
  [[nodiscard]] mpe_result mpe(std::span<const variable_id> variables) { return self_->mpe(variables); }
  [[nodiscard]] bool finds_mpe() const { return self_->finds_mpe(); }
  /// Why "auto" chose this engine; empty for an engine asked for by name.
  [[nodiscard]] const std::string& note() const noexcept { return note_; }

 private:
  struct interface {
    virtual ~interface() = default;
    [[nodiscard]] virtual std::string_view name() const = 0;
    [[nodiscard]] virtual const bayesian_network& network() const = 0;
    [[nodiscard]] virtual const evidence_set& evidence() const = 0;
    virtual void set_evidence(evidence_set observed) = 0;
    virtual posterior joint(std::span<const variable_id> query) = 0;
    virtual std::vector<posterior> marginals(std::span<const variable_id> nodes) = 0;
    virtual double log_probability_of_evidence() = 0;
    virtual mpe_result mpe(std::span<const variable_id> variables) = 0;
    [[nodiscard]] virtual bool finds_mpe() const = 0;
    [[nodiscard]] virtual bool reads_interventions() const = 0;
  };

  template <InferenceEngine E>
  struct model final : interface {
    explicit model(E e) : engine(std::move(e)) {}
    std::string_view name() const override { return engine.name(); }
    const bayesian_network& network() const override { return engine.network(); }
    const evidence_set& evidence() const override { return engine.evidence(); }
    void set_evidence(evidence_set observed) override {
      if (!detail::HandlesInterventions<E> && !observed.intervened.empty()) {
        throw model_error("the engine '" + std::string(engine.name()) + "' does not handle interventions (do)");
      }
      engine.set_evidence(std::move(observed));
    }
    posterior joint(std::span<const variable_id> query) override { return engine.joint(query); }
    std::vector<posterior> marginals(std::span<const variable_id> nodes) override {
      return detail::marginals_of(engine, nodes);
    }
    double log_probability_of_evidence() override { return engine.log_probability_of_evidence(); }
    mpe_result mpe(std::span<const variable_id> variables) override {
      if constexpr (MpeEngine<E>) {
        return engine.mpe(variables);
      } else {
        throw model_error("the engine '" + std::string(engine.name()) +
                          "' does not find the most probable explanation; use ve or jt");
      }
    }
    bool finds_mpe() const override { return MpeEngine<E>; }
    bool reads_interventions() const override { return detail::HandlesInterventions<E>; }
    E engine;
  };

  std::unique_ptr<interface> self_;
  std::string note_;
};

static_assert(MpeEngine<any_inference_engine>);
static_assert(MpeEngine<variable_elimination> && MpeEngine<junction_tree_engine>);
static_assert(InferenceEngine<likelihood_weighting> && InferenceEngine<gibbs_sampling>);

/// Builds an engine for a network with the given settings.
using engine_factory = std::function<any_inference_engine(const bayesian_network&, const inference_options&)>;

class engine_registry {
 public:
  /// The program-wide registry, holding the built-in engines from the start.
  [[nodiscard]] static engine_registry& instance() {
    static engine_registry registry = [] {
      engine_registry r;
      r.add("ve", [](const bayesian_network& network, const inference_options& options) {
        return any_inference_engine(variable_elimination(network, {options.heuristic}));
      });
      r.add("jt", [](const bayesian_network& network, const inference_options& options) {
        return any_inference_engine(
            junction_tree_engine(network, {options.heuristic, options.max_junction_tree_cells}));
      });
      r.add("lw", [](const bayesian_network& network, const inference_options& options) {
        return any_inference_engine(likelihood_weighting(network, options.sampling));
      });
      r.add("gibbs", [](const bayesian_network& network, const inference_options& options) {
        return any_inference_engine(gibbs_sampling(network, options.sampling));
      });
      r.add("auto", [](const bayesian_network& network, const inference_options& options) {
        try {
          return any_inference_engine(
              junction_tree_engine(network, {options.heuristic, options.max_junction_tree_cells}),
              "auto chose jt: the junction tree fits within " + std::to_string(options.max_junction_tree_cells) +
                  " cells");
        } catch (const table_too_large& e) {
          return any_inference_engine(likelihood_weighting(network, options.sampling),
                                      std::string("auto chose lw (likelihood weighting): ") + e.what());
        }
      });
      return r;
    }();
    return registry;
  }

  /// Adds an engine under `name`; a second engine of the same name is an error.
  void add(std::string name, engine_factory factory) { factories_.add(std::move(name), std::move(factory)); }

  /// The engine of that name for `network`; unknown_name otherwise.
  [[nodiscard]] PGM_DECL any_inference_engine make(std::string_view name, const bayesian_network& network,
                                                   const inference_options& options = {}) const;

  [[nodiscard]] std::vector<std::string> names() const { return factories_.names(); }

 private:
  detail::named_registry<engine_factory> factories_{"inference engine"};
};

/// An engine by name from the program-wide registry.
[[nodiscard]] inline any_inference_engine make_engine(std::string_view name, const bayesian_network& network,
                                                      const inference_options& options = {}) {
  return engine_registry::instance().make(name, network, options);
}

/// Registers an engine type when the program starts: `static const register_engine<E> r("name");`.
template <InferenceEngine E>
requires std::constructible_from<E, const bayesian_network&, const inference_options&>
struct register_engine {
  explicit register_engine(std::string name) {
    engine_registry::instance().add(std::move(name), [](const bayesian_network& network, const inference_options& o) {
      return any_inference_engine(E(network, o));
    });
  }
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/inference/impl/engine_registry.ipp"
#endif
