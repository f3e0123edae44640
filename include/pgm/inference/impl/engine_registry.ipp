#pragma once
// The definitions of pgm/inference/engine_registry.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/inference/engine_registry.hpp"

namespace pgm {

namespace detail {

/// "auto" on a model of class M: the junction tree when it fits, else `fallback` (named `why`).
template <GraphicalModel M, class Fallback>
[[nodiscard]] engine_factory_for<M> automatic(std::string why, Fallback fallback) {
  return [why = std::move(why), fallback](std::shared_ptr<const M> model, const inference_options& options) {
    try {
      return any_inference_engine(
          junction_tree_engine<M>(model, {options.heuristic, options.max_junction_tree_cells}),
          "auto chose jt: the junction tree fits within " + std::to_string(options.max_junction_tree_cells) + " cells");
    } catch (const table_too_large& e) {
      auto engine = fallback(std::move(model), options);
      engine.set_note("auto chose " + why + ": " + e.what());
      return engine;
    }
  };
}

template <GraphicalModel M>
[[nodiscard]] engine_factory_for<M> exact_ve() {
  return [](std::shared_ptr<const M> model, const inference_options& options) {
    return any_inference_engine(variable_elimination<M>(std::move(model), {options.heuristic}));
  };
}

template <GraphicalModel M>
[[nodiscard]] engine_factory_for<M> exact_jt() {
  return [](std::shared_ptr<const M> model, const inference_options& options) {
    return any_inference_engine(
        junction_tree_engine<M>(std::move(model), {options.heuristic, options.max_junction_tree_cells}));
  };
}

template <GraphicalModel M>
[[nodiscard]] engine_factory_for<M> loopy_bp() {
  return [](std::shared_ptr<const M> model, const inference_options& options) {
    return any_inference_engine(belief_propagation_engine<M>(std::move(model), options.bp));
  };
}

[[nodiscard]] inline any_inference_engine weighting(std::shared_ptr<const bayesian_network> network,
                                                    const inference_options& options) {
  any_inference_engine engine(likelihood_weighting(*network, options.sampling));
  engine.keep(std::move(network));
  return engine;
}

[[nodiscard]] inline factor_gibbs_options factor_gibbs_options_of(const sampling_options& sampling) {
  return {.sweeps = sampling.samples, .burn_in = sampling.burn_in, .seed = sampling.seed};
}

}  // namespace detail

PGM_DECL engine_registry& engine_registry::instance() {
  static engine_registry registry = [] {
    using markov = markov_network;
    engine_registry r;
    r.add("ve", {detail::exact_ve<bayesian_network>(), detail::exact_ve<markov>()});
    r.add("jt", {detail::exact_jt<bayesian_network>(), detail::exact_jt<markov>()});
    r.add("bp", {detail::loopy_bp<bayesian_network>(), detail::loopy_bp<markov>()});
    r.add("lw", {detail::weighting, {}});
    r.add("gibbs", {[](std::shared_ptr<const bayesian_network> network, const inference_options& options) {
                      any_inference_engine engine(gibbs_sampling(*network, options.sampling));
                      engine.keep(std::move(network));
                      return engine;
                    },
                    [](std::shared_ptr<const markov> model, const inference_options& options) {
                      return any_inference_engine(factor_gibbs_engine<markov>(
                          std::move(model), detail::factor_gibbs_options_of(options.sampling)));
                    }});
    r.add("auto", {detail::automatic<bayesian_network>("lw (likelihood weighting)", detail::weighting),
                   detail::automatic<markov>("bp (loopy belief propagation)", detail::loopy_bp<markov>())});
    return r;
  }();
  return registry;
}

PGM_DECL std::string engine_registry::refusal(std::string_view name, std::string_view kind) const {
  const auto serving =
      kind == model_kind<bayesian_network>() ? names_for<bayesian_network>() : names_for<markov_network>();
  return "the engine '" + std::string(name) + "' does not serve a " + std::string(kind) +
         (name == "lw" ? " (it samples along a DAG)" : "") + "; engines for it: " + detail::list_for_message(serving);
}

}  // namespace pgm
