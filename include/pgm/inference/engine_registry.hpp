#pragma once
/// \file
/// Engines by name, for the `pgm` program, the Python package and code that picks one at run
/// time: `make_engine("jt", model, options)` gives an `any_inference_engine` over a Bayesian
/// network or a Markov network. A name may carry the engine's declared options, as libDAI
/// writes `BP[tol=1e-9]`: `make_engine("bp[damping=0.5,max_iterations=200]", model)` sets them
/// on top of `options`. The built-in names:
///
/// | name | Bayesian network | Markov network |
/// |---|---|---|
/// | ve, jt | exact | exact |
/// | bp | loopy belief propagation | loopy belief propagation |
/// | lw | likelihood weighting | — (needs a DAG) |
/// | gibbs | Gibbs sampling (the network's) | Gibbs sampling on the factors |
/// | auto | jt, else lw | jt, else bp |
///
/// A user's engine joins with one line in its own translation unit (linked as an object file,
/// as for transfer strategies):
///
///     static const pgm::register_engine<my_engine> registered("mine");
///
/// where `my_engine` models InferenceEngine and is constructible from
/// (std::shared_ptr<const M>, const inference_options&) or (const M&, const inference_options&)
/// for M = bayesian_network, markov_network or both: it serves the model classes it can be
/// built from. The engine the registry makes keeps the model alive, so one holding a reference
/// to it is safe. An engine with options of its own declares them,
/// `static std::vector<pgm::option_declaration> options()`, and reads them from
/// `inference_options::engine` ("mine[depth=3]").
///
/// "auto" is exact unless exact is out of reach: the junction tree when it compiles within
/// `inference_options::max_junction_tree_cells`, otherwise likelihood weighting (bp for a Markov
/// network); the engine's name() is the one chosen and note() says why.

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/component_options.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/graphical_model.hpp"
#include "pgm/core/markov_network.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/detail/named_registry.hpp"
#include "pgm/inference/approximate_engines.hpp"
#include "pgm/inference/belief_propagation.hpp"
#include "pgm/inference/factor_gibbs.hpp"
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
  bp_options bp;
  /// The options the engine chosen by name declares, at their defaults unless its choice set
  /// them ("mine[depth=3]"): how a user's engine gets options of its own.
  option_values engine;
};

/// Any engine over any model, type-erased; it models MpeEngine itself (mpe throws model_error
/// for an engine that has none).
class any_inference_engine {
  struct interface;

 public:
  template <InferenceEngine E>
  requires(!std::same_as<E, any_inference_engine>) explicit any_inference_engine(E engine, std::string note = {})
      : self_(std::make_unique<holder<E>>(std::move(engine))), view_(self_.get()), note_(std::move(note)) {}

  any_inference_engine(any_inference_engine&& other) noexcept
      : self_(std::move(other.self_)),
        view_(self_.get()),
        note_(std::move(other.note_)),
        kept_(std::move(other.kept_)) {}
  any_inference_engine& operator=(any_inference_engine&& other) noexcept {
    self_ = std::move(other.self_);
    view_ = model_view(self_.get());
    note_ = std::move(other.note_);
    kept_ = std::move(other.kept_);
    return *this;
  }

  /// The named variables of the model inside, and which class of model it is.
  class model_view {
   public:
    [[nodiscard]] const std::vector<variable>& variables() const { return self_->variables(); }
    [[nodiscard]] std::size_t size() const { return variables().size(); }
    /// Throws model_error naming an unknown variable and the known ones.
    [[nodiscard]] variable_id id(std::string_view name) const { return self_->id(name); }
    /// "Bayesian network" or "Markov network".
    [[nodiscard]] std::string_view kind() const { return self_->kind(); }

   private:
    friend class any_inference_engine;
    explicit model_view(const interface* self) : self_(self) {}
    const interface* self_;
  };

  /// Interventions pass through; set_evidence refuses them for an engine that does not read them.
  static constexpr bool handles_interventions = true;
  [[nodiscard]] std::string_view name() const { return self_->name(); }
  /// Whether the engine inside reads interventions.
  [[nodiscard]] bool reads_interventions() const { return self_->reads_interventions(); }
  [[nodiscard]] const model_view& model() const noexcept { return view_; }
  /// The Bayesian network inside; model_error when the model is another kind.
  [[nodiscard]] const bayesian_network& network() const { return self_->network(); }
  [[nodiscard]] const evidence_set& evidence() const { return self_->evidence(); }
  void set_evidence(evidence_set observed) { self_->set_evidence(std::move(observed)); }
  [[nodiscard]] posterior joint(std::span<const variable_id> query) { return self_->joint(query); }
  [[nodiscard]] std::vector<posterior> marginals(std::span<const variable_id> nodes) { return self_->marginals(nodes); }
  [[nodiscard]] double log_probability_of_evidence() { return self_->log_probability_of_evidence(); }
  /// ln Z(e), the partition function with the evidence entered (ln P(e) for a Bayesian network,
  /// whose Z is 1); model_error for an engine that estimates neither.
  [[nodiscard]] double log_partition_function() { return self_->log_partition_function(); }
  [[nodiscard]] mpe_result mpe(std::span<const variable_id> variables) { return self_->mpe(variables); }
  [[nodiscard]] bool finds_mpe() const { return self_->finds_mpe(); }
  /// Why "auto" chose this engine; empty for an engine asked for by name.
  [[nodiscard]] const std::string& note() const noexcept { return note_; }

  /// Says why this engine was chosen (what "auto" does).
  void set_note(std::string note) { note_ = std::move(note); }

  /// Keeps `owner` (the model an engine refers to) alive as long as this engine.
  void keep(std::shared_ptr<const void> owner) { kept_ = std::move(owner); }

 private:
  struct interface {
    virtual ~interface() = default;
    [[nodiscard]] virtual std::string_view name() const = 0;
    [[nodiscard]] virtual const std::vector<variable>& variables() const = 0;
    [[nodiscard]] virtual variable_id id(std::string_view name) const = 0;
    [[nodiscard]] virtual std::string_view kind() const = 0;
    [[nodiscard]] virtual const bayesian_network& network() const = 0;
    [[nodiscard]] virtual const evidence_set& evidence() const = 0;
    virtual void set_evidence(evidence_set observed) = 0;
    virtual posterior joint(std::span<const variable_id> query) = 0;
    virtual std::vector<posterior> marginals(std::span<const variable_id> nodes) = 0;
    virtual double log_probability_of_evidence() = 0;
    virtual double log_partition_function() = 0;
    virtual mpe_result mpe(std::span<const variable_id> variables) = 0;
    [[nodiscard]] virtual bool finds_mpe() const = 0;
    [[nodiscard]] virtual bool reads_interventions() const = 0;
  };

  template <InferenceEngine E>
  struct holder final : interface {
    using model_type = std::remove_cvref_t<decltype(detail::model_of(std::declval<const E&>()))>;

    explicit holder(E e) : engine(std::move(e)) {}
    std::string_view name() const override { return engine.name(); }
    const std::vector<variable>& variables() const override { return detail::model_of(engine).variables(); }
    variable_id id(std::string_view name) const override { return node_of(detail::model_of(engine), name); }
    std::string_view kind() const override {
      if constexpr (GraphicalModel<model_type>) {
        return model_kind<model_type>();
      } else {
        return detail::model_of(engine).kind();
      }
    }
    const bayesian_network& network() const override {
      if constexpr (std::same_as<model_type, bayesian_network>) {
        return detail::model_of(engine);
      } else if constexpr (requires { detail::model_of(engine).network(); }) {
        return detail::model_of(engine).network();
      } else {
        throw model_error("the engine '" + std::string(engine.name()) + "' holds a " + std::string(kind()) +
                          ", not a Bayesian network");
      }
    }
    const evidence_set& evidence() const override { return engine.evidence(); }
    void set_evidence(evidence_set observed) override {
      if (!detail::HandlesInterventions<E> && !observed.intervened.empty()) {
        throw model_error("the engine '" + std::string(engine.name()) + "' does not handle interventions (do)" +
                          (kind() == model_kind<bayesian_network>()
                               ? std::string()
                               : "; interventions cut a variable from its parents in a DAG, and this model is a " +
                                     std::string(kind())));
      }
      engine.set_evidence(std::move(observed));
    }
    posterior joint(std::span<const variable_id> query) override { return engine.joint(query); }
    std::vector<posterior> marginals(std::span<const variable_id> nodes) override {
      return detail::marginals_of(engine, nodes);
    }
    double log_probability_of_evidence() override { return engine.log_probability_of_evidence(); }
    double log_partition_function() override {
      if constexpr (requires { engine.log_partition(); }) {
        return engine.log_partition() + engine.log_probability_of_evidence();
      } else if constexpr (DirectedModel<model_type>) {
        return engine.log_probability_of_evidence();
      } else {
        throw model_error("the engine '" + std::string(engine.name()) +
                          "' does not estimate the partition function; use jt, ve or bp");
      }
    }
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
  model_view view_;
  std::string note_;
  std::shared_ptr<const void> kept_;
};

static_assert(MpeEngine<any_inference_engine>);
static_assert(MpeEngine<variable_elimination<>> && MpeEngine<junction_tree_engine<>>);
static_assert(MpeEngine<variable_elimination<markov_network>> && MpeEngine<junction_tree_engine<markov_network>>);
static_assert(InferenceEngine<likelihood_weighting> && InferenceEngine<gibbs_sampling>);
static_assert(InferenceEngine<belief_propagation_engine<markov_network>> &&
              InferenceEngine<factor_gibbs_engine<markov_network>>);

/// Builds an engine for a model of class M with the given settings.
template <GraphicalModel M>
using engine_factory_for = std::function<any_inference_engine(std::shared_ptr<const M>, const inference_options&)>;

/// How one engine is built for each model class it serves (empty for a class it does not),
/// with the options it declares.
struct engine_factory {
  engine_factory_for<bayesian_network> for_network;
  engine_factory_for<markov_network> for_markov;
  std::vector<option_declaration> options;
  /// Writes the declared option `key`, as a choice set it, into the built-in settings it
  /// stands for (bp's damping into `bp.damping`); none for an engine that reads its own.
  std::function<void(std::string_view key, const option_values&, inference_options&)> apply;

  template <GraphicalModel M>
  [[nodiscard]] const engine_factory_for<M>& of() const noexcept {
    if constexpr (std::same_as<M, bayesian_network>) {
      return for_network;
    } else {
      return for_markov;
    }
  }
};

namespace detail {

/// A factory for E over models of class M when E can be built from one, else an empty one.
template <class E, GraphicalModel M>
[[nodiscard]] engine_factory_for<M> factory_of() {
  if constexpr (std::constructible_from<E, std::shared_ptr<const M>, const inference_options&>) {
    return [](std::shared_ptr<const M> model, const inference_options& options) {
      return any_inference_engine(E(std::move(model), options));
    };
  } else if constexpr (std::constructible_from<E, const M&, const inference_options&>) {
    // The engine may hold a reference to the model: the erased engine keeps it alive.
    return [](std::shared_ptr<const M> model, const inference_options& options) {
      any_inference_engine engine(E(*model, options));
      engine.keep(std::move(model));
      return engine;
    };
  } else {
    return {};
  }
}

}  // namespace detail

class engine_registry {
 public:
  /// The program-wide registry, holding the built-in engines from the start.
  [[nodiscard]] PGM_DECL static engine_registry& instance();

  /// Adds an engine under `name`; a second engine of the same name is an error.
  void add(std::string name, engine_factory factory) { factories_.add(std::move(name), std::move(factory)); }

  /// The engine `choice` names over `model` (shared, not copied): "bp", or with options set
  /// on top of `options`, "bp[damping=0.5]". Throws unknown_name for an unknown name or
  /// option, model_error for a malformed choice, a value its declaration refuses, or an engine
  /// that does not serve this class of model.
  template <GraphicalModel M>
  [[nodiscard]] any_inference_engine make(std::string_view choice, std::shared_ptr<const M> model,
                                          const inference_options& options = {}) const {
    const auto spec = parse_component_spec(choice, "inference engine");
    const auto factory = factories_.find(spec.name);
    if (!factory) throw unknown_name("inference engine", spec.name, names());
    const auto& build = factory->template of<M>();
    if (!build) throw model_error(refusal(spec.name, model_kind<M>()));
    auto chosen = options;
    chosen.engine = option_values(factory->options);
    for (const auto& [key, value] : spec.settings) {
      chosen.engine.set(key, value, "inference engine", spec.name);
      if (factory->apply) factory->apply(key, chosen.engine, chosen);
    }
    return build(std::move(model), chosen);
  }

  /// The same over a copy of `model`.
  template <GraphicalModel M>
  [[nodiscard]] any_inference_engine make(std::string_view name, const M& model,
                                          const inference_options& options = {}) const {
    return make(name, std::make_shared<const M>(model), options);
  }

  [[nodiscard]] std::vector<std::string> names() const { return factories_.names(); }

  /// The options the engine `name` declares. Throws unknown_name for an unknown engine.
  [[nodiscard]] std::vector<option_declaration> options(std::string_view name) const {
    const auto factory = factories_.find(name);
    if (!factory) throw unknown_name("inference engine", std::string(name), names());
    return factory->options;
  }

  /// Each engine as it is chosen with its declared defaults, "bp[schedule=residual,...]": for
  /// help texts.
  [[nodiscard]] std::vector<std::string> listing() const {
    std::vector<std::string> lines;
    for (const auto& name : names()) lines.push_back(spec_text(name, option_values(factories_.find(name)->options)));
    return lines;
  }

  /// Throws what make would for `choice` short of building: an unknown engine or option, or
  /// a value its declaration refuses.
  PGM_DECL void check(std::string_view choice) const;

  /// The engines that serve a model of class M.
  template <GraphicalModel M>
  [[nodiscard]] std::vector<std::string> names_for() const {
    std::vector<std::string> result;
    for (const auto& name : names()) {
      if (factories_.find(name)->template of<M>()) result.push_back(name);
    }
    return result;
  }

 private:
  [[nodiscard]] PGM_DECL std::string refusal(std::string_view name, std::string_view kind) const;

  detail::named_registry<engine_factory> factories_{"inference engine"};
};

/// An engine by name from the program-wide registry, over a copy of `model` or sharing it.
template <class Model>
[[nodiscard]] any_inference_engine make_engine(std::string_view name, Model&& model,
                                               const inference_options& options = {}) {
  return engine_registry::instance().make(name, std::forward<Model>(model), options);
}

/// Registers an engine type when the program starts: `static const register_engine<E> r("name");`.
/// E's declared options, if it declares any, are read into `inference_options::engine`.
template <InferenceEngine E>
struct register_engine {
  explicit register_engine(std::string name) {
    engine_factory factory{detail::factory_of<E, bayesian_network>(), detail::factory_of<E, markov_network>()};
    if constexpr (requires { E::options(); }) factory.options = E::options();
    if (!factory.for_network && !factory.for_markov) {
      throw model_error("the engine '" + name +
                        "' can be built from neither a Bayesian nor a Markov network (with inference_options)");
    }
    engine_registry::instance().add(std::move(name), std::move(factory));
  }
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/inference/impl/engine_registry.ipp"
#endif
