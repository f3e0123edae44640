// The causal questions for Python, each the library call the program makes; results cross as
// plain values and NumPy arrays, and pgm/__init__.py makes pandas objects of them.

#include "causal.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <map>
#include <string>
#include <vector>

#include "columns.hpp"
#include "network_handle.hpp"
#include "pgm/causal/adjustment.hpp"
#include "pgm/causal/counterfactual.hpp"
#include "pgm/causal/d_separation.hpp"
#include "pgm/causal/dag_check.hpp"
#include "pgm/causal/intervention.hpp"
#include "pgm/core/text.hpp"
#include "pgm/io/structural_file.hpp"

namespace py = pybind11;

namespace pgm::python {
namespace {

std::vector<variable_id> ids_of(const network_handle& handle, const std::vector<std::string>& names) {
  std::vector<variable_id> ids;
  for (const auto& name : names) ids.push_back(node_of(handle.network, name));
  return ids;
}

py::dict check_frame(const network_handle& handle, const py::list& columns, const std::string& test, double alpha,
                     unsigned threads) {
  std::vector<py::array> keep;
  const auto buffers = read_column_buffers(columns, keep);
  dag_check result;
  {
    const py::gil_scoped_release release;
    const auto data = make_dataset(buffers, "DataFrame");
    dag_check_options options;
    options.test = make_independence_test(test);
    options.alpha = alpha;
    options.threads = threads;
    result = check_dag(handle.network.structure(), data, options);
  }
  std::vector<std::string> x, y, given;
  py::array_t<double> statistic(static_cast<py::ssize_t>(result.tests.size()));
  py::array_t<double> df(static_cast<py::ssize_t>(result.tests.size()));
  py::array_t<double> p(static_cast<py::ssize_t>(result.tests.size()));
  for (std::size_t k = 0; k < result.tests.size(); ++k) {
    const auto& t = result.tests[k];
    x.push_back(t.x);
    y.push_back(t.y);
    given.push_back(text::join(t.given, ","));
    statistic.mutable_data()[k] = t.result.statistic;
    df.mutable_data()[k] = t.result.df;
    p.mutable_data()[k] = t.result.p_value;
  }
  py::dict out;
  out["x"] = x;
  out["y"] = y;
  out["given"] = given;
  out["statistic"] = statistic;
  out["df"] = df;
  out["p_value"] = p;
  return out;
}

/// A counterfactual's table for Python: (probabilities, the last variable fastest; each variable's
/// states; P(evidence)).
py::tuple counterfactual_answer(const posterior& answer) {
  std::vector<std::vector<std::string>> states;
  for (const auto& v : answer.variables) states.push_back(v.states());
  const auto& values = answer.table.values();
  return py::make_tuple(std::vector<double>(values.begin(), values.end()), states, answer.evidence_probability);
}

}  // namespace

void add_causal(py::module_& m) {
  m.def("holds_structural_model", [](const std::string& path) { return holds_structural_model(path); });
  m.def("counterfactual_structural",
        [](const std::string& path, const std::vector<std::string>& names,
           const std::map<std::string, std::string>& seen, const std::map<std::string, std::string>& set) {
          const evidence observed(seen.begin(), seen.end());
          const intervention done(set.begin(), set.end());
          return counterfactual_answer(counterfactual_query(read_structural_model(path), names, observed, done));
        });
  m.def("counterfactual_monotone",
        [](const network_handle& handle, const std::vector<std::string>& names,
           const std::map<std::string, std::string>& seen, const std::map<std::string, std::string>& set) {
          const evidence observed(seen.begin(), seen.end());
          const intervention done(set.begin(), set.end());
          return counterfactual_answer(monotone_counterfactual_query(handle.network, names, observed, done));
        });
  m.def("d_separated",
        [](const network_handle& handle, const std::vector<std::string>& x, const std::vector<std::string>& y,
           const std::vector<std::string>& given) { return d_separated(handle.network.structure(), x, y, given); });
  m.def("check", &check_frame);
  m.def("intervene", [](const network_handle& handle, const std::map<std::string, std::string>& set) {
    const intervention by_name(set.begin(), set.end());
    return network_handle{intervene(handle.network, by_name), std::nullopt, {}};
  });
  m.def("backdoor_sets", [](const network_handle& handle, const std::vector<std::string>& x,
                            const std::vector<std::string>& y, std::size_t limit) {
    const auto xs = ids_of(handle, x);
    const auto ys = ids_of(handle, y);
    const auto found = minimal_backdoor_sets(handle.network.graph(), xs, ys, limit);
    std::vector<std::vector<std::string>> sets;
    for (const auto& s : found.sets) {
      std::vector<std::string> names;
      for (auto id : s) names.push_back(handle.network.variables()[id.value()].name());
      sets.push_back(std::move(names));
    }
    return py::make_tuple(sets, found.complete);
  });
}

}  // namespace pgm::python
