// pgm._core's dynamic networks (dynamic.hpp).

#include "dynamic.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "columns.hpp"
#include "em_arguments.hpp"
#include "network_handle.hpp"
#include "pgm/core/dynamic_network.hpp"
#include "pgm/core/text.hpp"
#include "pgm/inference/dynamic_inference.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/learn/estimate.hpp"
#include "pgm/learn/estimator_choice.hpp"
#include "pgm/pipeline/dynamic_fit_pipeline.hpp"

namespace py = pybind11;

namespace pgm::python {
namespace {

/// A dynamic network and the counts it was estimated from, when it keeps them: what
/// pgm.DynamicNetwork holds.
using model_and_counts = std::pair<dynamic_network, std::optional<dynamic_fit_statistics>>;

/// The dynamic network of a pgm JSON model of "kind": "dynamic", with its counts (None where
/// it keeps none), or None for another model.
py::object read_dynamic_json(const std::filesystem::path& path) {
  const auto text = read_model_text(path);
  if (declared_model_kind(text) != "dynamic") return py::none();
  auto file = parse_dynamic_model_json(text, path.string());
  return py::cast(model_and_counts{std::move(file.model), std::move(file.statistics)});
}

/// The episodes of the frame's columns (episode, t and the template variables), the template
/// variables recoded onto `model`'s states when there is one.
dataset episodes_of(const std::vector<column_buffer>& buffers, const dynamic_network* model) {
  auto data = make_dataset(buffers, "DataFrame");
  if (model == nullptr) return data;
  dataset recoded(data.source());
  const auto& templates = model->initial().structure();
  for (const auto& column : data.columns()) {
    const auto& name = column_name(column);
    recoded.add(templates.contains(name) ? data_column(with_model_states(data.discrete(name), templates.at(name)))
                                         : column);
  }
  return recoded;
}

/// pgm.fit_dynamic: the 2-TBN fitted from a frame of episodes in long form, as pgm fit --dynamic.
/// `model`: the structure and states to fit instead of `edges`'.
/// `latent`: template variables in no column, fitted by EM (`request.em`).
py::tuple fit_dynamic_frame(const py::list& columns, const std::string& edges, const dynamic_network* model,
                            const std::vector<variable>& latent, const dynamic_fit_request& request) {
  std::vector<py::array> keep;
  const auto buffers = read_column_buffers(columns, keep);
  fitted_dynamic fitted;
  {
    const py::gil_scoped_release release;
    const auto data = episodes_of(buffers, model);
    const auto structure =
        model ? structure_of(*model) : dynamic_structure_from_data(data, parse_edge_list(edges), latent);
    fitted = fit_from_episodes(structure, data, request);
  }
  std::vector<std::string> notes;
  if (fitted.em) notes.push_back(summary_of(*fitted.em));
  if (fitted.transfer) {
    for (const auto& [node, entry] : fitted.transfer->nodes) {
      notes.push_back("'" + node + "' gets the " + request.transfer.strategy + " prior from '" + entry.prior_node +
                      "' with w = " + text::format_short(entry.weight));
    }
  }
  return py::make_tuple(py::cast(model_and_counts{std::move(fitted.model), std::move(fitted.statistics)}), notes);
}

/// DynamicNetwork.update: the frame's episodes added to the model's counts, every table
/// estimated again under its prior (old counts weighted by `decay`), as pgm update.
model_and_counts update_frame(const model_and_counts& current, const py::list& columns, double decay,
                              unsigned threads) {
  if (!current.second) {
    throw error(
        "the dynamic network carries no counts to add the episodes to: fit it with keep_counts=True (or read a "
        "model written so, or by pgm fit --dynamic --keep-counts)");
  }
  std::vector<py::array> keep;
  const auto buffers = read_column_buffers(columns, keep);
  const py::gil_scoped_release release;
  auto fitted =
      update_with_episodes(current.first, *current.second, episodes_of(buffers, &current.first), decay, threads);
  return {std::move(fitted.model), std::move(fitted.statistics)};
}

using step_evidence = std::vector<std::map<std::string, std::string>>;  // per step: {variable: state}
using step_interventions = std::vector<std::map<std::string, std::string>>;

/// The evidence of each step over the template variables' ids; a step of `intervened` past the
/// observed ones adds steps (prediction reaches them).
std::vector<evidence_set> resolve_steps(const dynamic_network& d, const step_evidence& observed,
                                        const step_interventions& intervened) {
  std::vector<evidence_set> steps(std::max(observed.size(), intervened.size()));
  const auto add = [&](const step_evidence& given, bool by_do) {
    for (std::size_t t = 0; t < given.size(); ++t) {
      for (const auto& [name, state] : given[t]) {
        const auto id = d.initial().id(name);  // an unknown name is an error saying the closest
        const auto s = d.variables()[id.value()].state(state);
        (by_do ? steps[t].intervened : steps[t].hard).push_back({id, s});
      }
    }
  };
  add(observed, false);
  add(intervened, true);
  return steps;
}

/// Filtering (with `predict` steps more) or smoothing, as the columns of its table: (t, variable,
/// state, probability) for every variable neither observed nor set at its step, and
/// ln P(evidence); a frame is made of them at once.
py::tuple filter_columns(const dynamic_network& d, const step_evidence& observed, const step_interventions& intervened,
                         std::size_t predict, bool smooth) {
  const auto steps = resolve_steps(d, observed, intervened);
  dynamic_marginals answer;
  std::vector<std::int64_t> t_column, variable_column, state_column;
  std::vector<double> probability_column;
  {
    const py::gil_scoped_release release;
    interface_filter filter(d);
    const auto beyond = predict > steps.size() - observed.size() ? predict - (steps.size() - observed.size()) : 0;
    answer = smooth ? filter.smooth(steps) : filter.filter(steps, beyond);
    for (std::size_t t = 0; t < answer.steps.size(); ++t) {
      for (std::size_t v = 0; v < answer.steps[t].size(); ++v) {
        if (t < steps.size() && steps[t].fixes(variable_id(static_cast<std::uint32_t>(v)))) continue;
        const auto& distribution = answer.steps[t][v];
        for (std::size_t s = 0; s < distribution.size(); ++s) {
          t_column.push_back(static_cast<std::int64_t>(t));
          variable_column.push_back(static_cast<std::int64_t>(v));
          state_column.push_back(static_cast<std::int64_t>(s));
          probability_column.push_back(distribution[s]);
        }
      }
    }
  }
  const auto array = [](const auto& values) {
    return py::array(static_cast<py::ssize_t>(values.size()), values.data());
  };
  return py::make_tuple(array(t_column), array(variable_column), array(state_column), array(probability_column),
                        answer.log_evidence_probability);
}

/// ([step][variable] state index, ln P(x*, e)) of the most probable sequence.
std::pair<std::vector<std::vector<std::size_t>>, double> most_probable_steps_of(const dynamic_network& d,
                                                                                const step_evidence& observed,
                                                                                const step_interventions& intervened) {
  const auto steps = resolve_steps(d, observed, intervened);
  most_probable_steps best;
  {
    const py::gil_scoped_release release;
    interface_filter filter(d);
    best = filter.most_probable(steps);
  }
  return {std::move(best.states), best.log_probability};
}

}  // namespace

void add_dynamic(py::module_& m) {
  py::class_<dynamic_network>(m, "DynamicNetwork")
      .def_property_readonly("variables",
                             [](const dynamic_network& d) {
                               std::vector<std::string> names;
                               for (const auto& v : d.variables()) names.push_back(v.name());
                               return names;
                             })
      .def("states", [](const dynamic_network& d, const std::string& name) { return d.initial().at(name).states(); })
      .def_property_readonly("initial",
                             [](const dynamic_network& d) {
                               return network_handle{d.initial(), {}, {}, {}};
                             })
      .def_property_readonly("transition_edges",
                             [](const dynamic_network& d) {
                               std::vector<std::pair<std::string, std::string>> edges;
                               for (const auto& e : d.transition_structure().edges()) edges.emplace_back(e.from, e.to);
                               return edges;
                             })
      .def("unroll",
           [](const dynamic_network& d, std::size_t slices) {
             return network_handle{d.unroll(slices), {}, {}, {}};
           })
      .def("filter_columns", &filter_columns)
      .def("most_probable", &most_probable_steps_of)
      .def("to_json", [](const dynamic_network& d) { return to_json(d).dump(2); })
      .def("write", [](const dynamic_network& d, const std::filesystem::path& path) { write_dynamic_json(d, path); });
  py::class_<dynamic_fit_statistics>(m, "DynamicCounts")  // opaque: kept, updated and written with its model
      .def("write", [](const dynamic_fit_statistics& s, const dynamic_network& d, const std::filesystem::path& path) {
        write_dynamic_json(d, path, {}, &s);
      });
  m.def("read_dynamic_json", &read_dynamic_json);
  m.def(
      "fit_dynamic",
      [](const py::list& columns, const std::string& edges, const dynamic_network* model, const std::string& estimator,
         const std::string& prior, const std::vector<std::tuple<std::string, std::string, std::string>>& prior_settings,
         const std::string& empty, unsigned threads, const network_handle* prior_model, const std::string& strategy,
         const std::string& map, std::optional<double> w_prior, const std::optional<std::string>& initial_map,
         const std::optional<std::string>& initial_strategy, const std::optional<em_arguments>& em,
         const std::vector<std::pair<std::string, std::vector<std::string>>>& latent, bool keep_counts) {
        dynamic_fit_request request;
        estimator_choice choice{estimator, prior, {}};
        for (const auto& [keyword, key, value] : prior_settings) choice.settings.push_back({keyword, key, value});
        request.options.fit.prior = prior_of(choice);
        request.options.fit.estimation.empty = parse_empty_configuration(empty);
        request.options.fit.counting.threads = threads;
        if (prior_model) request.prior_network = &prior_model->network;
        request.transfer.strategy = strategy;
        request.transfer.map = map;
        request.transfer.weight = w_prior;
        request.initial_map = initial_map;
        request.initial_strategy = initial_strategy;
        request.keep_statistics = keep_counts;
        if (em) request.em = dynamic_em_options{.em = em_options_of(*em, threads)};
        std::vector<variable> hidden;
        for (const auto& [name, states] : latent) hidden.emplace_back(name, states);
        return fit_dynamic_frame(columns, edges, model, hidden, request);
      },
      py::arg("columns"), py::arg("edges"), py::arg("model").none(true), py::arg("estimator"), py::arg("prior"),
      py::arg("prior_settings"), py::arg("empty"), py::arg("threads"), py::arg("prior_model").none(true),
      py::arg("strategy"), py::arg("map"), py::arg("w_prior"), py::arg("initial_map"), py::arg("initial_strategy"),
      py::arg("em").none(true), py::arg("latent"), py::arg("keep_counts"));
  m.def(
      "update_dynamic",
      [](const dynamic_network& model, const dynamic_fit_statistics* counts, const py::list& columns, double decay,
         unsigned threads) {
        return update_frame({model, counts ? std::optional(*counts) : std::nullopt}, columns, decay, threads);
      },
      py::arg("model"), py::arg("counts").none(true), py::arg("columns"), py::arg("decay"), py::arg("threads"));
  m.def("parse_dynamic_json", &parse_dynamic_json);
}

}  // namespace pgm::python
