// pgm._core's Markov networks (markov.hpp): built from names, states and flat factor tables,
// solved without the GIL.

#include "markov.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "network_handle.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/markov_network.hpp"
#include "pgm/inference/solve.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/io/uai.hpp"

namespace py = pybind11;

namespace pgm::python {
namespace {

using factor_spec = std::pair<std::vector<std::string>, std::vector<double>>;

markov_handle make_markov(const std::vector<std::pair<std::string, std::vector<std::string>>>& variables,
                          const std::vector<factor_spec>& factors) {
  std::vector<variable> vars;
  for (const auto& [name, states] : variables) vars.emplace_back(name, states);
  const markov_network names(vars, {});
  std::vector<factor_table> tables;
  for (const auto& [scope_names, values] : factors) {
    std::vector<variable_id> scope;
    std::vector<std::size_t> cards;
    for (const auto& name : scope_names) {
      scope.push_back(names.id(name));
      cards.push_back(vars[scope.back().value()].cardinality());
    }
    tables.emplace_back(std::move(scope), std::move(cards), values);
  }
  return {markov_network(std::move(vars), std::move(tables))};
}

evidence_set evidence_of(const markov_network& model, const std::map<std::string, std::string>& hard) {
  evidence_set observed;
  for (const auto& [name, state] : hard) {
    const auto id = model.id(name);
    observed.hard.push_back({id, model.variables()[id.value()].state(state)});
  }
  return observed;
}

solve_options options_of(const std::string& engine, std::size_t memory_limit_mib) {
  solve_options options;
  options.engine = parse_solve_engine(engine);
  options.memory_limit_bytes = memory_limit_mib << 20;
  return options;
}

/// (the task's answer, the engine that ran, whether it is exact, whether bp converged, auto's note)
py::tuple solve_task(const markov_handle& h, const std::string& task, const std::map<std::string, std::string>& hard,
                     const std::string& engine, std::size_t memory_limit_mib) {
  const auto observed = evidence_of(h.model, hard);
  const auto options = options_of(engine, memory_limit_mib);
  solve_report report;
  py::object answer;
  if (task == "PR") {
    double log_z = 0.0;
    {
      const py::gil_scoped_release release;
      log_z = log_partition(h.model, observed, options, &report);
    }
    answer = py::float_(log_z);
  } else if (task == "MAR") {
    std::vector<std::vector<double>> marginals;
    {
      const py::gil_scoped_release release;
      marginals = all_marginals(h.model, observed, options, &report);
    }
    answer = py::cast(marginals);
  } else if (task == "MAP") {
    std::vector<std::size_t> states;
    {
      const py::gil_scoped_release release;
      states = most_probable_assignment(h.model, observed, options, &report);
    }
    answer = py::cast(states);
  } else {
    throw error("unknown task '" + task + "' (known: PR, MAR, MAP)");
  }
  return py::make_tuple(answer, report.engine, report.exact, report.converged, report.note);
}

/// ("markov", MarkovNetwork) or ("bayes", Network) for a .uai file.
py::tuple read_uai_file(const std::filesystem::path& path) {
  auto file = read_uai(path);
  if (file.kind == uai_kind::bayes) {
    return py::make_tuple("bayes", network_handle{to_bayesian_network(file, path.string()), {}, {}, {}});
  }
  return py::make_tuple("markov", markov_handle{std::move(file.model)});
}

/// The Markov network of a pgm JSON model of "kind": "markov", or None for another model.
py::object read_markov_json(const std::filesystem::path& path) {
  const auto text = read_model_text(path);
  if (!declares_markov_network(text)) return py::none();
  return py::cast(markov_handle{parse_markov_json(text, path.string())});
}

}  // namespace

void add_markov(py::module_& m) {
  py::class_<markov_handle>(m, "MarkovNetwork")
      .def(py::init(&make_markov))
      .def_property_readonly("variables",
                             [](const markov_handle& h) {
                               std::vector<std::string> names;
                               for (const auto& v : h.model.variables()) names.push_back(v.name());
                               return names;
                             })
      .def("states", [](const markov_handle& h, const std::string& name) { return h.model.at(name).states(); })
      .def_property_readonly("factors",
                             [](const markov_handle& h) {
                               std::vector<factor_spec> result;
                               for (const auto& f : h.model.factors()) {
                                 std::vector<std::string> scope;
                                 for (auto v : f.scope()) scope.push_back(h.model.variables()[v.value()].name());
                                 result.emplace_back(std::move(scope), f.values());
                               }
                               return result;
                             })
      .def("write",
           [](const markov_handle& h, const std::filesystem::path& path) {
             if (path.extension() == ".json") {
               write_file_atomically(path, [&](std::ostream& out) { write_markov_json(out, h.model); });
               return;
             }
             const auto text = to_uai(h.model);
             write_file_atomically(path, [&](std::ostream& out) { out << text; });
           })
      .def("solve", &solve_task);
  m.def("read_uai", &read_uai_file);
  m.def("read_markov_json", &read_markov_json);
}

}  // namespace pgm::python
