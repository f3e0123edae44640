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

#include "network_handle.hpp"
#include "pgm/core/dynamic_network.hpp"
#include "pgm/inference/dynamic_inference.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"

namespace py = pybind11;

namespace pgm::python {
namespace {

/// The dynamic network of a pgm JSON model of "kind": "dynamic", or None for another model.
py::object read_dynamic_json(const std::filesystem::path& path) {
  const auto text = read_model_text(path);
  if (declared_model_kind(text) != "dynamic") return py::none();
  return py::cast(parse_dynamic_json(text, path.string()));
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
  m.def("read_dynamic_json", &read_dynamic_json);
  m.def("parse_dynamic_json", &parse_dynamic_json);
}

}  // namespace pgm::python
