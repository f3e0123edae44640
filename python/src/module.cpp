// pgm._core: the library's calls for Python. Thin on purpose: each function turns its
// arguments into the library's types, makes the one library call the CLI makes, and hands
// the result back as NumPy buffers and plain values; pgm/__init__.py turns those into pandas.
// Long calls run without the GIL.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "columns.hpp"
#include "pgm/core/error.hpp"
#include "pgm/data/bin_columns.hpp"
#include "pgm/decide/decision_model.hpp"
#include "pgm/decide/explain.hpp"
#include "pgm/decide/predict.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/eval/cached_source.hpp"
#include "pgm/eval/run_scenarios.hpp"
#include "pgm/eval/scenario_catalog.hpp"
#include "pgm/eval/simulated_source.hpp"
#include "pgm/inference/variable_elimination.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/learn/estimator_choice.hpp"
#include "pgm/learn/fit.hpp"
#include "pgm/learn/pc.hpp"
#include "pgm/sim/simulator.hpp"
#include "pgm/sim/task_lookup.hpp"
#include "pgm/sim/task_variant.hpp"
#include "pgm/transfer/transfer_settings.hpp"

namespace py = pybind11;

namespace pgm::python {
namespace {

/// A network with what Python shows beside it: the success event a JSON model names, and the
/// notes of the fit that made it.
struct network_handle {
  bayesian_network network;
  std::optional<std::string> success;
  std::vector<std::string> notes;
};

using edge_pairs = std::vector<std::pair<std::string, std::string>>;
using edges_by_name = std::map<std::string, std::vector<double>>;

std::vector<named_edge> to_edges(const edge_pairs& pairs) {
  std::vector<named_edge> edges;
  edges.reserve(pairs.size());
  for (const auto& [from, to] : pairs) edges.push_back({from, to});
  return edges;
}

edge_pairs to_pairs(const std::vector<named_edge>& edges) {
  edge_pairs pairs;
  pairs.reserve(edges.size());
  for (const auto& e : edges) pairs.emplace_back(e.from, e.to);
  return pairs;
}

/// Interval variables from {name: edges} (as pgm.discretize returns them) or from a
/// discretization file (as `pgm discretize --edges-out` writes it).
discretization intervals_of(const std::optional<edges_by_name>& edges, const std::optional<std::string>& file) {
  if (file) return read_discretization_json(*file);
  discretization result;
  if (edges) {
    for (const auto& [name, values] : *edges) result.emplace(name, variable::intervals(name, values));
  }
  return result;
}

std::vector<std::string> names_of(const std::vector<variable>& variables) {
  std::vector<std::string> names;
  for (const auto& v : variables) names.push_back(v.name());
  return names;
}

// ---- the network ---------------------------------------------------------------------------

network_handle read_network_file(const std::filesystem::path& path) {
  auto network = read_network(path);
  return {std::move(network), read_success_metadata(path), {}};
}

/// A table for pgm/__init__.py: the parents' names, each configuration's parent state codes
/// (configurations × parents, last parent fastest), the child's states and the probabilities
/// (configurations × child states).
py::tuple table_of(const network_handle& handle, const std::string& name) {
  const auto& table = handle.network.table(detail::node_of(handle.network, name));
  const auto configurations = table.configurations();
  const auto parents = table.parents().size();
  const auto states = table.child_cardinality();
  py::array_t<std::uint32_t> codes({configurations, parents});
  py::array_t<double> values({configurations, states});
  auto code_view = codes.mutable_unchecked<2>();
  auto value_view = values.mutable_unchecked<2>();
  for (std::size_t u = 0; u < configurations; ++u) {
    const auto parent_codes = table.parent_codes(config_index(static_cast<config_index::rep>(u)));
    for (std::size_t p = 0; p < parents; ++p) code_view(u, p) = static_cast<std::uint32_t>(parent_codes[p]);
    const auto column = table.column(config_index(static_cast<config_index::rep>(u)));
    for (std::size_t x = 0; x < states; ++x) value_view(u, x) = column[x];
  }
  return py::make_tuple(names_of(table.parents()), std::move(codes), table.child().states(), std::move(values));
}

/// A network from (child, child states, parents, probabilities as configurations × states)
/// per node, as pgm.from_pgmpy collects them. A parent's states are those of its own table.
network_handle network_from_tables(const py::list& tables) {
  struct entry {
    std::string child;
    std::vector<std::string> states;
    std::vector<std::string> parents;
    std::vector<double> values;
  };
  std::vector<entry> entries;
  std::map<std::string, variable, std::less<>> variables;
  for (const auto& item : tables) {
    const auto t = item.cast<py::tuple>();
    entry e{t[0].cast<std::string>(), t[1].cast<std::vector<std::string>>(), t[2].cast<std::vector<std::string>>(), {}};
    const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(t[3]);
    if (!values || values.ndim() != 2 || static_cast<std::size_t>(values.shape(1)) != e.states.size()) {
      throw model_error("the table of '" + e.child + "' must have one column per state of '" + e.child + "'");
    }
    e.values.assign(values.data(), values.data() + values.size());
    variables.insert_or_assign(e.child, variable(e.child, e.states));
    entries.push_back(std::move(e));
  }
  std::vector<cpt<double>> cpts;
  for (auto& e : entries) {
    std::vector<variable> parents;
    for (const auto& p : e.parents) {
      const auto it = variables.find(p);
      if (it == variables.end()) {
        throw model_error("'" + p + "' is a parent of '" + e.child + "' but has no table of its own");
      }
      parents.push_back(it->second);
    }
    cpts.emplace_back(variables.at(e.child), std::move(parents), std::move(e.values));
  }
  return {bayesian_network::from_tables(std::move(cpts)), std::nullopt, {}};
}

// ---- fit -----------------------------------------------------------------------------------

struct fit_arguments {
  estimator_choice estimator;
  std::string empty = "uniform";
  unsigned threads = 0;
  std::optional<edges_by_name> intervals;
  std::optional<std::string> intervals_file;
  const network_handle* prior_model = nullptr;
  transfer_settings transfer;
};

network_handle fit_frame(const py::list& columns, const std::vector<std::string>& available, const edge_pairs& pairs,
                         const fit_arguments& args) {
  std::vector<py::array> keep;
  const auto buffers = read_column_buffers(columns, keep);
  const py::gil_scoped_release release;
  const auto edges = to_edges(pairs);
  std::vector<std::string> wanted;
  for (const auto& e : edges) {
    for (const auto* name : {&e.from, &e.to}) {
      if (std::find(wanted.begin(), wanted.end(), *name) == wanted.end()) wanted.push_back(*name);
    }
  }
  require_columns(wanted, available, "DataFrame");
  fit_options options;
  options.prior = prior_of(args.estimator);
  if (args.empty != "uniform" && args.empty != "fail") {
    throw error("empty must be uniform or fail, got '" + args.empty + "'");
  }
  options.estimation.empty = args.empty == "fail" ? empty_configuration::fail : empty_configuration::uniform;
  options.counting.threads = args.threads;
  const auto add_intervals = [&](network_structure structure) {
    if (!args.intervals && !args.intervals_file) return structure;
    return with_intervals(std::move(structure), intervals_of(args.intervals, args.intervals_file),
                          args.intervals_file.value_or("intervals"));
  };
  // Columns of integer codes are counted straight from their buffers, unless a prior model asks
  // for the data (its transfer looks at the rows).
  if (!args.prior_model) {
    if (auto counts = count_integer_families(buffers, edges, options.counting)) {
      const auto structure = add_intervals(network_structure(std::move(counts->variables), edges));
      std::vector<count_table> tables;
      for (std::size_t i = 0; i < structure.size(); ++i) {
        const variable_id node(static_cast<variable_id::rep>(i));
        tables.push_back(counts->tables[i].with_variables(structure.at(node), structure.parent_variables(node)));
      }
      return {fit(structure, tables, options), std::nullopt, {}};
    }
  }
  const auto data = make_dataset(buffers, "DataFrame");
  const auto structure = add_intervals(structure_from_data(data, edges));
  std::vector<std::string> notes;
  if (args.prior_model) {
    const auto report = add_transferred_priors(options, structure, data, args.prior_model->network, args.transfer);
    if (report.map_proposed) notes.push_back("map='auto': " + to_string(report.map));
    for (const auto& [node, entry] : report.nodes) {
      if (entry.reason) notes.push_back("w_prior='auto' for '" + node + "': " + *entry.reason);
    }
    for (const auto& [node, entry] : report.nodes) {
      notes.push_back("'" + node + "' gets the " + args.transfer.strategy + " prior from '" + entry.prior_node +
                      "' with w = " + detail::format_short(entry.weight));
    }
  }
  return {fit(structure, data, options), std::nullopt, std::move(notes)};
}

// ---- decide --------------------------------------------------------------------------------

success_event success_of(const network_handle& handle, const std::optional<std::string>& given) {
  return choose_success_event(handle.network, given.value_or(""), handle.success);
}

/// An assignment from "name=value,…" or a dict: a string value reads as in the text form; a
/// number is a number in the units of an interval variable, and otherwise reads as its text.
assignment assignment_of(const bayesian_network& network, const py::object& planned) {
  if (py::isinstance<py::str>(planned)) return parse_assignment(planned.cast<std::string>(), network);
  if (!py::isinstance<py::dict>(planned)) throw py::type_error("assign must be a dict or a string \"name=value,...\"");
  assignment result;
  for (const auto& [key, value] : planned.cast<py::dict>()) {
    const auto name = py::str(key).cast<std::string>();
    const auto& v = network.structure().at(detail::node_of(network, name));
    const bool number =
        !py::isinstance<py::bool_>(value) && (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value));
    if (number && v.has_intervals()) {
      result.emplace(name, value.cast<double>());
    } else {
      result.emplace(name, planned_value_of(v, py::str(value).cast<std::string>()));
    }
  }
  if (result.empty()) throw model_error("the assignment is empty");
  return result;
}

py::object to_python(const planned_value& value) {
  if (const auto* number = std::get_if<double>(&value)) return py::float_(*number);
  return py::str(std::get<std::string>(value));
}

double predict_plan(const network_handle& handle, const py::object& planned, const std::optional<std::string>& success,
                    bool marginalize) {
  const auto event = success_of(handle, success);
  return predict_success(handle.network, event, assignment_of(handle.network, planned),
                         {.marginalize_missing = marginalize});
}

py::dict prevent_plan(const network_handle& handle, const py::object& planned,
                      const std::optional<std::vector<std::string>>& controllable, double epsilon,
                      const std::string& distance, const std::optional<std::string>& success, bool marginalize) {
  const auto& network = handle.network;
  const auto event = success_of(handle, success);
  const auto plan_values = assignment_of(network, planned);
  const auto movable = controllable ? *controllable : default_controllable(network, event);
  if (!(epsilon >= 0.0 && epsilon <= 1.0))
    throw error("epsilon must lie in [0, 1], got " + detail::format_double(epsilon));
  if (distance != "steps" && distance != "units")
    throw error("distance must be steps or units, got '" + distance + "'");
  prevention_options options;
  options.epsilon = epsilon;
  options.metric = distance == "units" ? prevention_options::distance::units : prevention_options::distance::steps;
  const auto plan =
      plan_prevention(network, event, plan_values, movable, options, {.marginalize_missing = marginalize});
  const auto& why = plan.why;
  py::dict suggestion;
  for (const auto& [name, value] : suggested_values(why, plan_values)) suggestion[py::str(name)] = to_python(value);
  py::list responsible;
  for (const auto& c : why.responsible()) responsible.append(c.variable);
  py::dict result;
  result["success"] = why.success_variable + "=" + why.success_state;
  result["predicted"] = why.predicted;
  result["failure_predicted"] = why.failure_predicted();
  result["suggestion"] = suggestion;
  result["predicted_after"] = why.target_predicted;
  result["target_succeeds"] = why.target_succeeds();
  result["responsible"] = responsible;
  result["steps"] = why.steps;
  result["distance"] = why.distance_units ? py::object(py::float_(*why.distance_units)) : py::object(py::none());
  return result;
}

py::tuple query_network(const network_handle& handle, const std::vector<std::string>& variables,
                        const std::map<std::string, std::string>& observed) {
  const evidence given(observed.begin(), observed.end());
  const auto result = query(handle.network, variables, given);
  std::vector<std::vector<std::string>> states;
  for (const auto& v : result.variables) states.push_back(v.states());
  const auto values = result.table.values();
  py::array_t<double> probabilities(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), probabilities.mutable_data());
  return py::make_tuple(states, std::move(probabilities), result.evidence_probability);
}

// ---- structure, discretization, simulation, experiments --------------------------------------

struct learn_arguments {
  std::string test = "g2";
  double alpha = 0.01;
  std::size_t max_conditioning = 3;
  std::string tiers;
  std::string forbid;
  std::string require;
  unsigned threads = 0;
};

edge_pairs learn_frame(const py::list& columns, const learn_arguments& args) {
  std::vector<py::array> keep;
  const auto buffers = read_column_buffers(columns, keep);
  const py::gil_scoped_release release;
  pc_options options;
  options.test = parse_ci_test(args.test);
  if (!(args.alpha > 0.0 && args.alpha < 1.0)) {
    throw error("alpha must lie strictly between 0 and 1, got " + detail::format_double(args.alpha));
  }
  options.alpha = args.alpha;
  options.max_conditioning = args.max_conditioning;
  options.threads = args.threads;
  if (!args.tiers.empty()) options.knowledge.tiers = parse_tiers(args.tiers);
  if (!args.forbid.empty()) options.knowledge.forbidden = parse_edge_list(args.forbid);
  if (!args.require.empty()) options.knowledge.required = parse_edge_list(args.require);
  const auto data = make_dataset(buffers, "DataFrame");
  const auto result = pc_stable(data, options);
  // A fitted model needs a DAG: one member of the CPDAG's class, as pgm learn-structure writes.
  return to_pairs(extend_to_dag(result.graph, true));
}

py::tuple discretize_frame(const py::list& columns, const std::vector<std::string>& available, std::size_t bins,
                           const std::vector<std::string>& wanted, const std::string& method,
                           const std::optional<edges_by_name>& saved, const std::optional<std::string>& saved_file) {
  std::vector<py::array> keep;
  const auto buffers = read_column_buffers(columns, keep);
  binned_columns result;
  {
    const py::gil_scoped_release release;
    require_columns(wanted, available, "DataFrame");
    column_binning request;
    request.columns = wanted;
    request.bins = bins;
    if (method == "quantile" || method == "width") {
      request.method = method == "quantile" ? binning::quantile : binning::equal_width;
    } else {
      throw error("method must be quantile or width, got '" + method + "'");
    }
    if (bins == 0) throw error("bins must be positive");
    if (saved || saved_file) {
      request.saved = intervals_of(saved, saved_file);
      request.saved_source = saved_file.value_or("edges");
    }
    result = bin_columns(make_dataset(buffers, "DataFrame"), request);
  }
  edges_by_name edges;
  for (const auto& [name, v] : result.edges) edges.emplace(name, v.edges());
  dataset binned;
  for (const auto& [name, v] : result.edges) binned.add(result.data.at(name));
  return py::make_tuple(dataset_columns(binned), edges);
}

std::vector<std::filesystem::path> task_folders(const std::optional<std::string>& tasks_dir) {
  if (tasks_dir) return {*tasks_dir};
  return sim::default_task_directories();
}

py::list simulate_task(const std::string& task, std::size_t rows, std::uint64_t seed, const std::string& backend,
                       const std::string& variant, unsigned threads, const std::optional<std::string>& tasks_dir) {
  dataset data;
  {
    const py::gil_scoped_release release;
    if (rows == 0) throw error("rows must be positive");
    const auto definition = sim::load_task_variant(task, variant, task_folders(tasks_dir));
    sim::simulate_options options;
    options.backend = backend;
    options.rows = rows;
    options.seed = seed;
    options.threads = threads;
    data = sim::simulate(definition, options);
  }
  return dataset_columns(data);
}

/// Codes of strings, with the distinct strings in the order met: a categorical column.
struct category_column {
  std::vector<std::int32_t> codes;
  std::vector<std::string> categories;
  std::map<std::string, std::int32_t, std::less<>> index;

  void add(const std::string& text) {
    const auto [it, fresh] = index.emplace(text, static_cast<std::int32_t>(categories.size()));
    if (fresh) categories.push_back(text);
    codes.push_back(it->second);
  }
  [[nodiscard]] py::tuple to_python() const {
    py::array_t<std::int32_t> array(static_cast<py::ssize_t>(codes.size()));
    std::copy(codes.begin(), codes.end(), array.mutable_data());
    return py::make_tuple(std::move(array), categories);
  }
};

struct experiment_arguments {
  std::string scenario = "all";
  std::size_t repetitions = 0;
  std::uint64_t seed = 1;
  std::string backend = "analytic";
  unsigned threads = 0;
  std::string distance = "steps";
  bool automatic_lines = true;
  std::optional<std::string> tasks_dir;
};

/// The points of `pgm experiment`'s points.csv, column by column, and the protocol's notes.
py::tuple run_experiments(const experiment_arguments& args) {
  std::vector<experiment_point> points;
  std::vector<std::string> notes;
  {
    const py::gil_scoped_release release;
    if (args.distance != "steps" && args.distance != "units") {
      throw error("distance must be steps or units, got '" + args.distance + "'");
    }
    const auto folders = task_folders(args.tasks_dir);
    const auto scenarios = select_scenarios(args.scenario, find_scenario_folder(folders));
    experiment_options options;
    options.seed = args.seed;
    options.repetitions = args.repetitions;
    options.threads = args.threads;
    options.automatic_lines = args.automatic_lines;
    options.prevention.metric =
        args.distance == "units" ? prevention_options::distance::units : prevention_options::distance::steps;
    std::mutex mutex;
    options.note = [&](const std::string& text) {
      const std::lock_guard lock(mutex);
      notes.push_back(text);
    };
    const auto source = cached(simulated_source({folders, args.backend, args.threads}));
    for (const auto& s : scenarios) {
      auto more = run_scenario(s, source, options);
      points.insert(points.end(), std::make_move_iterator(more.begin()), std::make_move_iterator(more.end()));
    }
  }
  category_column scenario, target, strategy, weight, metric;
  py::array_t<std::int64_t> rows(static_cast<py::ssize_t>(points.size()));
  py::array_t<std::int64_t> repetition(static_cast<py::ssize_t>(points.size()));
  py::array_t<double> value(static_cast<py::ssize_t>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    scenario.add(p.scenario);
    target.add(p.target);
    strategy.add(p.strategy);
    weight.add(p.weight);
    metric.add(p.metric);
    rows.mutable_data()[i] = static_cast<std::int64_t>(p.rows);
    repetition.mutable_data()[i] = static_cast<std::int64_t>(p.repetition);
    value.mutable_data()[i] = p.value;
  }
  py::dict columns;
  columns["scenario"] = scenario.to_python();
  columns["target"] = target.to_python();
  columns["strategy"] = strategy.to_python();
  columns["w"] = weight.to_python();
  columns["rows"] = rows;
  columns["repetition"] = repetition;
  columns["metric"] = metric.to_python();
  columns["value"] = value;
  return py::make_tuple(columns, notes);
}

}  // namespace
}  // namespace pgm::python

PYBIND11_MODULE(_core, m) {
  using namespace pgm::python;
  m.doc() = "pgm's library calls for Python; use the package pgm, which wraps them for pandas.";
  py::register_exception<pgm::error>(m, "Error", PyExc_ValueError);

  py::class_<network_handle>(m, "Network")
      .def_property_readonly("variables", [](const network_handle& h) { return names_of(h.network.variables()); })
      .def("states",
           [](const network_handle& h, const std::string& name) {
             return h.network.structure().at(pgm::detail::node_of(h.network, name)).states();
           })
      .def("parents",
           [](const network_handle& h, const std::string& name) {
             return names_of(h.network.structure().parent_variables(pgm::detail::node_of(h.network, name)));
           })
      .def("interval_edges",
           [](const network_handle& h, const std::string& name) -> std::optional<std::vector<double>> {
             const auto& v = h.network.structure().at(pgm::detail::node_of(h.network, name));
             if (!v.has_intervals()) return std::nullopt;
             return v.edges();
           })
      .def_property_readonly("edges", [](const network_handle& h) { return to_pairs(h.network.structure().edges()); })
      .def_property_readonly("free_parameters", [](const network_handle& h) { return h.network.free_parameters(); })
      .def_property_readonly("success", [](const network_handle& h) { return h.success; })
      .def_property_readonly("notes", [](const network_handle& h) { return h.notes; })
      .def("table", &table_of)
      .def("write", [](const network_handle& h, const std::filesystem::path& path) { write_network(h.network, path); })
      .def("to_json", [](const network_handle& h) { return pgm::to_json(h.network).dump(2); });

  m.def("read_network", &read_network_file);
  m.def("network_from_tables", &network_from_tables);
  m.def("parse_edge_list", [](const std::string& text) { return to_pairs(pgm::parse_edge_list(text)); });
  m.def("backends", &pgm::sim::backends);

  m.def(
      "fit",
      [](const py::list& columns, const std::vector<std::string>& available, const edge_pairs& edges,
         const std::string& estimator, const std::optional<std::string>& prior, std::optional<double> alpha,
         std::optional<double> ess, const std::string& empty, unsigned threads,
         const std::optional<edges_by_name>& intervals, const std::optional<std::string>& intervals_file,
         const network_handle* prior_model, const std::string& strategy, const std::string& map,
         std::optional<double> w_prior, const std::string& success, const std::string& match) {
        fit_arguments args;
        args.estimator = {estimator, prior.value_or(""), alpha, ess};
        args.empty = empty;
        args.threads = threads;
        args.intervals = intervals;
        args.intervals_file = intervals_file;
        args.prior_model = prior_model;
        args.transfer.strategy = strategy;
        args.transfer.map = map;
        args.transfer.weight = w_prior;
        args.transfer.success = success;
        if (match != "midpoint" && match != "overlap")
          throw pgm::error("match must be midpoint or overlap, got '" + match + "'");
        args.transfer.matching = match == "overlap" ? pgm::state_matching::overlap : pgm::state_matching::midpoint;
        return fit_frame(columns, available, edges, args);
      },
      py::arg("columns"), py::arg("available"), py::arg("edges"), py::arg("estimator"), py::arg("prior"),
      py::arg("alpha"), py::arg("ess"), py::arg("empty"), py::arg("threads"), py::arg("intervals"),
      py::arg("intervals_file"), py::arg("prior_model").none(true), py::arg("strategy"), py::arg("map"),
      py::arg("w_prior"), py::arg("success"), py::arg("match"));

  m.def("query", &query_network);
  m.def("predict", &predict_plan);
  m.def("prevent", &prevent_plan);

  m.def("learn_structure",
        [](const py::list& columns, const std::string& test, double alpha, std::size_t max_conditioning,
           const std::string& tiers, const std::string& forbid, const std::string& require, unsigned threads) {
          return learn_frame(columns, {test, alpha, max_conditioning, tiers, forbid, require, threads});
        });
  m.def("discretize", &discretize_frame);
  m.def("simulate", &simulate_task);
  m.def("experiment",
        [](const std::string& scenario, std::size_t repetitions, std::uint64_t seed, const std::string& backend,
           unsigned threads, const std::string& distance, bool automatic, const std::optional<std::string>& tasks_dir) {
          return run_experiments({scenario, repetitions, seed, backend, threads, distance, automatic, tasks_dir});
        });
}
