// pgm._core's influence diagrams (decisions.hpp), solved without the GIL.

#include "decisions.hpp"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "pgm/core/mixed_radix.hpp"
#include "pgm/decide/solve_decisions.hpp"
#include "pgm/io/influence_file.hpp"

namespace py = pybind11;

namespace pgm::python {
namespace {

evidence evidence_of(const std::map<std::string, std::string>& observed) {
  return evidence(observed.begin(), observed.end());
}

/// (decision, [observed names], [[their states…, action], …]) per policy, one row per
/// configuration of what the decision observes (the last fastest).
py::list policies_of(const influence_diagram& d, const decision_solution& solution) {
  py::list policies;
  for (const auto& policy : solution.policies) {
    std::vector<std::string> observed;
    std::vector<std::size_t> cards;
    for (const auto id : policy.observed) {
      observed.push_back(d.at(id).name());
      cards.push_back(d.at(id).cardinality());
    }
    const mixed_radix configurations(cards);
    std::vector<std::vector<std::string>> rows;
    std::vector<std::size_t> states(cards.size());
    for (std::size_t c = 0; c < configurations.size(); ++c) {
      configurations.decode(c, states);
      std::vector<std::string> row;
      for (std::size_t k = 0; k < states.size(); ++k) row.push_back(d.at(policy.observed[k]).states()[states[k]]);
      row.push_back(d.at(policy.decision).states()[policy.actions[c]]);
      rows.push_back(std::move(row));
    }
    policies.append(py::make_tuple(d.at(policy.decision).name(), observed, rows));
  }
  return policies;
}

/// (meu, policies, local_optimum, start_expected_utility, rounds)
py::tuple solve(const diagram_handle& h, const std::map<std::string, std::string>& observed, bool limited_memory) {
  decision_solution solution;
  {
    const py::gil_scoped_release release;
    solution = solve_decisions(h.model, evidence_of(observed), {.limited_memory = limited_memory});
  }
  return py::make_tuple(solution.meu, policies_of(h.model, solution), solution.local_optimum,
                        solution.start_expected_utility, solution.rounds);
}

double information(const diagram_handle& h, const std::string& variable, const std::string& before,
                   const std::map<std::string, std::string>& observed, bool limited_memory) {
  const py::gil_scoped_release release;
  return value_of_information(h.model, variable, before, evidence_of(observed), {.limited_memory = limited_memory});
}

}  // namespace

void add_decisions(py::module_& m) {
  py::class_<diagram_handle>(m, "InfluenceDiagram")
      .def_property_readonly("decisions",
                             [](const diagram_handle& h) {
                               std::vector<std::string> names;
                               for (const auto id : h.model.decision_order()) names.push_back(h.model.at(id).name());
                               return names;
                             })
      .def_property_readonly("chance_variables",
                             [](const diagram_handle& h) {
                               std::vector<std::string> names;
                               for (std::size_t i = 0; i < h.model.size(); ++i) {
                                 const auto id = index_at<variable_id>(i);
                                 if (!h.model.is_decision(id)) names.push_back(h.model.at(id).name());
                               }
                               return names;
                             })
      .def_property_readonly("utilities",
                             [](const diagram_handle& h) {
                               std::vector<std::string> names;
                               for (const auto& u : h.model.utilities()) names.push_back(u.name);
                               return names;
                             })
      .def("states",
           [](const diagram_handle& h, const std::string& name) { return h.model.at(h.model.id(name)).states(); })
      .def("solve", &solve)
      .def("value_of_information", &information)
      .def("write",
           [](const diagram_handle& h, const std::filesystem::path& path) { write_influence_diagram(h.model, path); });
  m.def("read_influence_diagram",
        [](const std::filesystem::path& path) { return diagram_handle{read_influence_diagram(path)}; });
}

}  // namespace pgm::python
