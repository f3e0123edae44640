// The inference engines for Python. Results cross as NumPy arrays and plain values (states as
// lists of labels); pgm/__init__.py makes pandas objects of them. Every computation runs
// without the GIL, one at a time per engine (an engine keeps caches between queries).

#include "inference.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "markov.hpp"
#include "network_handle.hpp"
#include "pgm/core/graphical_model.hpp"
#include "pgm/inference/engine_registry.hpp"
#include "pgm/inference/inference_engine.hpp"

namespace py = pybind11;

namespace pgm::python {
namespace {

/// An engine over a Bayesian or Markov network's handle (kept alive by Python for as long as the
/// engine lives, so the engine borrows the model).
class engine_handle {
 public:
  engine_handle(const network_handle& network, const std::string& name, std::size_t samples, std::uint64_t seed,
                std::size_t burn_in, unsigned threads)
      : engine_(make_engine(name, borrowed(network.network), options_of(samples, seed, burn_in, threads))) {}
  engine_handle(const markov_handle& model, const std::string& name, std::size_t samples, std::uint64_t seed,
                std::size_t burn_in, unsigned threads)
      : engine_(make_engine(name, borrowed(model.model), options_of(samples, seed, burn_in, threads))) {}

  [[nodiscard]] std::string name() const { return std::string(engine_.name()); }
  [[nodiscard]] std::string note() const { return engine_.note(); }

  void set_evidence(const std::map<std::string, std::string>& hard,
                    const std::map<std::string, std::vector<double>>& soft,
                    const std::map<std::string, std::string>& set) {
    const evidence given(hard.begin(), hard.end());
    const soft_evidence weights(soft.begin(), soft.end());
    const intervention by_name(set.begin(), set.end());
    const py::gil_scoped_release release;
    const std::lock_guard lock(mutex_);
    engine_.set_evidence(resolve_evidence(engine_.model(), given, weights, by_name));
  }

  /// (probabilities, P(evidence), standard errors or None), over the joint states of
  /// `variables` in the network's state order, the last fastest.
  py::tuple joint(const std::vector<std::string>& variables) {
    posterior answer;
    {
      const py::gil_scoped_release release;
      const std::lock_guard lock(mutex_);
      answer = query(engine_, variables);
    }
    return to_python(answer);
  }

  /// [(name, probabilities, standard errors or None)] for every unobserved variable (the
  /// states are the network's, which Python keeps).
  py::list marginals() {
    std::vector<posterior> answers;
    {
      const py::gil_scoped_release release;
      const std::lock_guard lock(mutex_);
      answers = pgm::marginals(engine_);
    }
    py::list result;
    for (const auto& a : answers) {
      result.append(py::make_tuple(a.variables.front().name(), array_of(a.table.values()), errors_of(a)));
    }
    return result;
  }

  /// ({name: state}, P(states | evidence), ln P(states, evidence))
  py::tuple mpe(const std::optional<std::vector<std::string>>& variables) {
    mpe_result best;
    {
      const py::gil_scoped_release release;
      const std::lock_guard lock(mutex_);
      if (variables && variables->empty()) throw model_error("variables is an empty list; give None for all");
      best = variables ? most_probable(engine_, *variables) : engine_.mpe({});
    }
    py::dict states;
    for (std::size_t k = 0; k < best.variables.size(); ++k) {
      states[py::str(best.variables[k].name())] = best.variables[k].states()[best.states[k].value()];
    }
    return py::make_tuple(states, best.probability, best.log_joint_probability);
  }

  double log_probability_of_evidence() {
    const py::gil_scoped_release release;
    const std::lock_guard lock(mutex_);
    return engine_.log_probability_of_evidence();
  }

  double log_partition_function() {
    const py::gil_scoped_release release;
    const std::lock_guard lock(mutex_);
    return engine_.log_partition_function();
  }

 private:
  static inference_options options_of(std::size_t samples, std::uint64_t seed, std::size_t burn_in, unsigned threads) {
    inference_options options;
    if (samples == 0) throw model_error("samples must be at least 1");
    options.sampling.samples = samples;
    options.sampling.seed = seed;
    options.sampling.burn_in = burn_in;
    options.sampling.threads = threads;
    return options;
  }

  static py::array_t<double> array_of(std::span<const double> values) {
    py::array_t<double> array(static_cast<py::ssize_t>(values.size()));
    std::copy(values.begin(), values.end(), array.mutable_data());
    return array;
  }
  static py::object errors_of(const posterior& p) {
    if (p.standard_errors.empty()) return py::none();
    return array_of(p.standard_errors);
  }
  static py::tuple to_python(const posterior& p) {
    return py::make_tuple(array_of(p.table.values()), p.evidence_probability, errors_of(p));
  }

  any_inference_engine engine_;
  std::mutex mutex_;
};

}  // namespace

void add_inference(py::module_& m) {
  py::class_<engine_handle>(m, "Engine")
      .def(py::init<const network_handle&, const std::string&, std::size_t, std::uint64_t, std::size_t, unsigned>(),
           py::arg("network"), py::arg("engine"), py::arg("samples"), py::arg("seed"), py::arg("burn_in"),
           py::arg("threads"), py::keep_alive<1, 2>())
      .def(py::init<const markov_handle&, const std::string&, std::size_t, std::uint64_t, std::size_t, unsigned>(),
           py::arg("network"), py::arg("engine"), py::arg("samples"), py::arg("seed"), py::arg("burn_in"),
           py::arg("threads"), py::keep_alive<1, 2>())
      .def_property_readonly("name", &engine_handle::name)
      .def_property_readonly("note", &engine_handle::note)
      .def("set_evidence", &engine_handle::set_evidence)
      .def("joint", &engine_handle::joint)
      .def("marginals", &engine_handle::marginals)
      .def("mpe", &engine_handle::mpe)
      .def("log_probability_of_evidence", &engine_handle::log_probability_of_evidence)
      .def("log_partition_function", &engine_handle::log_partition_function);
  m.def("engine_names", [] { return engine_registry::instance().names(); });
  m.def("engine_listing", [] { return engine_registry::instance().listing(); });
}

}  // namespace pgm::python
