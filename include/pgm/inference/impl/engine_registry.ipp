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

/// The built-in engines' options, each declared once with the default of the setting it sets.
[[nodiscard]] inline option_declaration heuristic_option() {
  return word_option("heuristic", std::string(to_string(inference_options{}.heuristic)), known_elimination_heuristics(),
                     "the elimination order's heuristic");
}
[[nodiscard]] inline option_declaration max_cells_option() {
  return count_option("max_cells", inference_options{}.max_junction_tree_cells,
                      "the most cells of the junction tree's tables")
      .at_least(1);
}
[[nodiscard]] inline std::vector<option_declaration> sampling_declarations(bool gibbs) {
  const sampling_options defaults;
  std::vector<option_declaration> declared{
      count_option("samples", defaults.samples, "samples per query").at_least(1),
      count_option("seed", defaults.seed, "the seed of the samples"),
  };
  if (gibbs) {
    declared.push_back(count_option("burn_in", defaults.burn_in, "sweeps each chain discards first"));
    declared.push_back(count_option("chains", defaults.chains, "independent chains").at_least(1));
  }
  return declared;
}
[[nodiscard]] inline std::vector<option_declaration> bp_declarations() {
  const bp_options defaults;
  return {
      word_option("schedule", std::string(to_string(defaults.schedule)), known_bp_schedules(),
                  "the order of the messages"),
      number_option("damping", defaults.damping, "the weight of the old message in each update")
          .at_least(0.0)
          .less_than(1.0),
      number_option("tolerance", defaults.tolerance, "the largest message change at convergence").greater_than(0.0),
      count_option("max_iterations", defaults.max_iterations, "the most sweeps of messages").at_least(1),
  };
}

/// Writes a built-in engine's option into the setting it stands for.
inline void apply_built_in_option(std::string_view key, const option_values& values, inference_options& options) {
  if (key == "heuristic") options.heuristic = parse_elimination_heuristic(values.word(key));
  if (key == "max_cells") options.max_junction_tree_cells = values.count(key);
  if (key == "samples") options.sampling.samples = values.count(key);
  if (key == "seed") options.sampling.seed = values.count(key);
  if (key == "burn_in") options.sampling.burn_in = values.count(key);
  if (key == "chains") options.sampling.chains = values.count(key);
  if (key == "schedule") options.bp.schedule = parse_bp_schedule(values.word(key));
  if (key == "damping") options.bp.damping = values.number(key);
  if (key == "tolerance") options.bp.tolerance = values.number(key);
  if (key == "max_iterations") options.bp.max_iterations = values.count(key);
}

/// `declared` joined, in order.
[[nodiscard]] inline std::vector<option_declaration> joined(
    std::initializer_list<std::vector<option_declaration>> parts) {
  std::vector<option_declaration> all;
  for (const auto& part : parts) all.insert(all.end(), part.begin(), part.end());
  return all;
}

}  // namespace detail

PGM_DECL engine_registry& engine_registry::instance() {
  static engine_registry registry = [] {
    using markov = markov_network;
    engine_registry r;
    const auto apply = detail::apply_built_in_option;
    r.add("ve",
          {detail::exact_ve<bayesian_network>(), detail::exact_ve<markov>(), {detail::heuristic_option()}, apply});
    r.add("jt", {detail::exact_jt<bayesian_network>(),
                 detail::exact_jt<markov>(),
                 {detail::heuristic_option(), detail::max_cells_option()},
                 apply});
    r.add("bp", {detail::loopy_bp<bayesian_network>(), detail::loopy_bp<markov>(), detail::bp_declarations(), apply});
    r.add("lw", {detail::weighting, {}, detail::sampling_declarations(false), apply});
    r.add("gibbs", {[](std::shared_ptr<const bayesian_network> network, const inference_options& options) {
                      any_inference_engine engine(gibbs_sampling(*network, options.sampling));
                      engine.keep(std::move(network));
                      return engine;
                    },
                    [](std::shared_ptr<const markov> model, const inference_options& options) {
                      return any_inference_engine(factor_gibbs_engine<markov>(
                          std::move(model), detail::factor_gibbs_options_of(options.sampling)));
                    },
                    detail::sampling_declarations(true), apply});
    // auto's options are those of the engines it may choose: jt's, lw's on a Bayesian network,
    // bp's on a Markov network.
    r.add("auto", {detail::automatic<bayesian_network>("lw (likelihood weighting)", detail::weighting),
                   detail::automatic<markov>("bp (loopy belief propagation)", detail::loopy_bp<markov>()),
                   detail::joined({{detail::heuristic_option(), detail::max_cells_option()},
                                   detail::sampling_declarations(false),
                                   detail::bp_declarations()}),
                   apply});
    return r;
  }();
  return registry;
}

PGM_DECL void engine_registry::check(std::string_view choice) const {
  const auto spec = parse_component_spec(choice, "inference engine");
  const auto factory = factories_.find(spec.name);
  if (!factory) throw unknown_name("inference engine", spec.name, names());
  option_values values(factory->options);
  for (const auto& [key, value] : spec.settings) values.set(key, value, "inference engine", spec.name);
}

PGM_DECL std::string engine_registry::refusal(std::string_view name, std::string_view kind) const {
  const auto serving =
      kind == model_kind<bayesian_network>() ? names_for<bayesian_network>() : names_for<markov_network>();
  return "the engine '" + std::string(name) + "' does not serve a " + std::string(kind) +
         (name == "lw" ? " (it samples along a DAG)" : "") + "; engines for it: " + text::list_for_message(serving);
}

}  // namespace pgm
