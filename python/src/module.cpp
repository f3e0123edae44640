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
#include <tuple>
#include <utility>
#include <vector>

#include "causal.hpp"
#include "columns.hpp"
#include "decisions.hpp"
#include "dynamic.hpp"
#include "em_arguments.hpp"
#include "inference.hpp"
#include "markov.hpp"
#include "network_handle.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/data/bin_columns.hpp"
#include "pgm/decide/explain.hpp"
#include "pgm/decide/predict.hpp"
#include "pgm/decide/prevent_by_utility.hpp"
#include "pgm/decide/table_slice.hpp"
#include "pgm/eval/cached_source.hpp"
#include "pgm/eval/run_scenarios.hpp"
#include "pgm/eval/scenario_catalog.hpp"
#include "pgm/eval/simulated_source.hpp"
#include "pgm/io/decision_model.hpp"
#include "pgm/io/dot.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/learn/estimator_choice.hpp"
#include "pgm/learn/expectation_maximization.hpp"
#include "pgm/learn/fit.hpp"
#include "pgm/learn/learn_structure.hpp"
#include "pgm/learn/network_score.hpp"
#include "pgm/learn/pc.hpp"
#include "pgm/learn/structure_prior.hpp"
#include "pgm/pipeline/fit_pipeline.hpp"
#include "pgm/sim/simulator.hpp"
#include "pgm/sim/task_episodes.hpp"
#include "pgm/sim/task_lookup.hpp"
#include "pgm/sim/task_variant.hpp"
#include "pgm/transfer/transfer_settings.hpp"
#include "pgm/version.hpp"

namespace py = pybind11;

namespace pgm::python {
namespace {

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
  auto model = read_model(path);
  return {model.network(), read_success_metadata(path), {}, std::move(model.statistics)};
}

/// A table for pgm/__init__.py: the parents' names, each configuration's parent state codes
/// (configurations × parents, last parent fastest), the child's states and the probabilities
/// (configurations × child states).
py::tuple table_of(const network_handle& handle, const std::string& name) {
  const auto& table = handle.network.table(node_of(handle.network, name));
  // A sparse table has a row per configuration here too, within pgm's limit of a dense table.
  static_cast<void>(checked_table_cells(name, table.child_cardinality(), table.configurations()));
  const auto configurations = table.configurations();
  const auto parents = table.parents().size();
  const auto states = table.child_cardinality();
  py::array_t<std::uint32_t> codes({configurations, parents});
  py::array_t<double> values({configurations, states});
  auto code_view = codes.mutable_unchecked<2>();
  auto value_view = values.mutable_unchecked<2>();
  for (std::size_t u = 0; u < configurations; ++u) {
    const auto parent_codes = table.parent_codes(index_at<config_index>(u));
    for (std::size_t p = 0; p < parents; ++p) code_view(u, p) = static_cast<std::uint32_t>(parent_codes[p]);
    const auto column = table.column(index_at<config_index>(u));
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
  /// missing="em": how EM runs, and the latent variables with their states.
  std::optional<em_options> em;
  std::vector<latent_variable> latent;
  /// Columns whose states are given, {name: labels} (states=).
  std::vector<std::pair<std::string, std::vector<std::string>>> states;
  bool keep_counts = false;
};

network_handle fit_frame(const py::list& columns, const std::vector<std::string>& available, const edge_pairs& pairs,
                         const fit_arguments& args) {
  std::vector<py::array> keep;
  const auto buffers = read_column_buffers(columns, keep);
  const py::gil_scoped_release release;
  fit_request request;
  auto edges = to_edges(pairs);
  auto observed = columns_of(edges);
  std::erase_if(observed, [&](const std::string& name) {
    return std::any_of(args.latent.begin(), args.latent.end(),
                       [&](const latent_variable& v) { return v.name == name; });
  });
  require_columns(observed, available, "DataFrame");
  request.structure = std::move(edges);
  request.em = args.em;
  request.latent = args.latent;
  request.keep_statistics = args.keep_counts;
  request.options.prior = prior_of(args.estimator);
  request.options.estimation.empty = parse_empty_configuration(args.empty);
  request.options.counting.threads = args.threads;
  // A missing value (NaN, None) leaves out only the families it is in.
  request.missing.policy = missing_policy::available;
  if (args.intervals || args.intervals_file) {
    request.intervals = intervals_of(args.intervals, args.intervals_file);
    request.intervals_source = args.intervals_file.value_or("intervals");
  }
  for (const auto& [name, labels] : args.states) {
    if (std::find(observed.begin(), observed.end(), name) == observed.end()) {
      throw error("states: '" + name + "' is in no edge, or is latent");
    }
    request.states.emplace(name, variable(name, labels));
  }
  if (args.prior_model) {
    request.prior_network = &args.prior_model->network;
    request.transfer = args.transfer;
  }
  numpy_source source(buffers, "DataFrame");
  auto fitted = fit(source, request);
  std::vector<std::string> notes;
  if (fitted.em) notes.push_back(summary_of(*fitted.em));
  if (fitted.transfer) {
    const auto& report = *fitted.transfer;
    if (report.map_proposed) notes.push_back("map='auto': " + to_string(report.map));
    for (const auto& [node, entry] : report.nodes) {
      if (entry.reason) notes.push_back("w_prior='auto' for '" + node + "': " + *entry.reason);
    }
    for (const auto& [node, entry] : report.nodes) {
      notes.push_back("'" + node + "' gets the " + args.transfer.strategy + " prior from '" + entry.prior_node +
                      "' with w = " + text::format_short(entry.weight));
    }
  }
  return {std::move(fitted.network), std::nullopt, std::move(notes), std::move(fitted.statistics)};
}

/// The network with the frame's rows added to its counts (Network.update).
network_handle update_frame(const network_handle& handle, const py::list& columns,
                            const std::vector<std::string>& available, double decay, unsigned threads) {
  if (!handle.statistics) {
    throw error(
        "the network carries no counts to add the rows to: fit it with keep_counts=True (or read a model "
        "written so, or by pgm fit --keep-counts)");
  }
  std::vector<py::array> keep;
  const auto buffers = read_column_buffers(columns, keep);
  const py::gil_scoped_release release;
  std::vector<std::string> names;
  for (const auto& v : handle.network.variables()) names.push_back(v.name());
  require_columns(names, available, "DataFrame");
  update_request request;
  request.missing.policy = missing_policy::available;  // a missing value leaves out only its families
  request.threads = threads;
  request.decay = decay;
  numpy_source source(buffers, "DataFrame");
  auto updated_model = update(source, handle.network.structure(), *handle.statistics, request);
  return {std::move(updated_model.network), handle.success, {}, std::move(updated_model.statistics)};
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
    const auto& v = network.structure().at(node_of(network, name));
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

/// The table of `node` over its parents x and y (Network.plot_table): (P[y, x] of the state, the
/// rows behind each cell or None, the state's label).
py::tuple slice_of(const network_handle& handle, const std::string& node, const std::string& x, const std::string& y,
                   const py::object& given, bool average, const std::optional<std::string>& state, bool counts) {
  if (counts && !handle.statistics) {
    throw pgm::error("counts=True: the network carries no counts; fit it with keep_counts=True");
  }
  table_slice_request request{node, x, y, {}, average, state};
  if (!given.is_none()) request.given = assignment_of(handle.network, given);
  const auto slice = slice_table(handle.network, request, counts ? &*handle.statistics : nullptr);
  const auto nx = static_cast<py::ssize_t>(slice.x->cardinality()),
             ny = static_cast<py::ssize_t>(slice.y->cardinality());
  py::array_t<double> probability({ny, nx});
  std::copy(slice.probability.begin(), slice.probability.end(), probability.mutable_data());
  py::object rows = py::none();
  if (slice.rows) {
    py::array_t<double> cells({ny, nx});
    std::copy(slice.rows->begin(), slice.rows->end(), cells.mutable_data());
    rows = std::move(cells);
  }
  return py::make_tuple(probability, rows, slice.node->states()[slice.state]);
}

py::dict prevent_plan(const network_handle& handle, const py::object& planned,
                      const std::optional<std::vector<std::string>>& controllable, double epsilon,
                      const std::string& distance, const std::optional<std::string>& success, bool marginalize,
                      const std::optional<double>& reward, const std::map<std::string, double>& move_cost,
                      const std::string& per) {
  const auto& network = handle.network;
  const auto event = success_of(handle, success);
  const auto plan_values = assignment_of(network, planned);
  const auto movable = controllable ? *controllable : default_controllable(network, event);
  if (!(epsilon >= 0.0 && epsilon <= 1.0))
    throw error("epsilon must lie in [0, 1], got " + text::format_double(epsilon));
  const auto unit = parse_choice("cost unit", per, distances);  // checked with or without a reward
  prevention_options options;
  options.epsilon = epsilon;
  options.metric = parse_distance(distance);
  const auto plan =
      plan_prevention(network, event, plan_values, movable, options, {.marginalize_missing = marginalize});
  std::optional<utility_prevention> by_utility;
  if (reward) {
    by_utility = prevent_by_utility(plan, movable,
                                    {.reward = *reward, .cost = {move_cost.begin(), move_cost.end()}, .unit = unit});
  }
  const auto& why = by_utility ? by_utility->why : plan.why;
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
  if (by_utility) {
    result["expected_utility"] = by_utility->move.expected_utility;
    result["cost"] = by_utility->move.cost;
  }
  return result;
}

// ---- structure, discretization, simulation, experiments --------------------------------------

struct learn_arguments {
  /// The learner, and the keyword arguments that set one of its options (or its start's), as
  /// (keyword, option, value): the ones the caller gave other than their defaults.
  std::string algorithm;
  std::vector<std::tuple<std::string, std::string, std::string>> settings;
  std::string tiers;
  std::string forbid;
  std::string require;
  unsigned threads = 0;
  edge_pairs start;
  std::optional<edge_pairs> prior_edges;
  std::string map;
  double prior_weight = 5.0;
};

edge_pairs learn_frame(const py::list& columns, const learn_arguments& args) {
  std::vector<py::array> keep;
  const auto buffers = read_column_buffers(columns, keep);
  const py::gil_scoped_release release;
  std::vector<component_setting> settings;
  for (const auto& [keyword, key, value] : args.settings) settings.push_back({keyword, key, value});
  const auto learner = make_structure_learner(args.algorithm, settings);
  structure_context context;
  context.threads = args.threads;
  if (!args.tiers.empty()) context.knowledge.tiers = parse_tiers(args.tiers);
  if (!args.forbid.empty()) context.knowledge.forbidden = parse_edge_list(args.forbid);
  if (!args.require.empty()) context.knowledge.required = parse_edge_list(args.require);
  context.start = to_edges(args.start);
  const auto data = make_dataset(buffers, "DataFrame");
  if (args.prior_edges) {
    context.favoured =
        mapped_prior_edges(to_edges(*args.prior_edges),
                           args.map.empty() ? correspondence{} : parse_correspondence(args.map), data.names());
    context.favour_weight = args.prior_weight;
  } else if (!args.map.empty()) {
    throw error("map applies with prior_model");
  }
  // The DAG: PC's is one member of its CPDAG's class, as pgm learn-structure writes.
  return to_pairs(learn_structure(data, learner, context).edges);
}

/// The declared defaults of the options a registry's components declare, {option: default}:
/// what the signatures of Python's keyword arguments that set them must show.
template <class Product>
py::dict declared_defaults(const component_registry<Product>& registry) {
  py::dict defaults;
  for (const auto& name : registry.names()) {
    const auto entry = registry.find(name).value();
    for (const auto& option : entry.options) defaults[py::str(option.name)] = option.default_text;
  }
  return defaults;
}

py::tuple score_frame(const network_handle& handle, const py::list& columns, const std::string& score_text,
                      unsigned threads) {
  std::vector<py::array> keep;
  const auto buffers = read_column_buffers(columns, keep);
  network_score result;
  {
    const py::gil_scoped_release release;
    const auto score = make_score(score_text);
    const auto& structure = handle.network.structure();
    const auto data = make_dataset(buffers, "DataFrame");
    dataset recoded;
    for (const auto& v : structure.variables()) recoded.add(with_model_states(data.discrete(v.name()), v));
    result = score_network(structure, recoded, score, threads);
  }
  return py::make_tuple(result.total, result.nodes);
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
    request.method = parse_binning(method);
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
                       const std::string& variant, unsigned threads, const std::optional<std::string>& tasks_dir,
                       bool long_form) {
  dataset data;
  {
    const py::gil_scoped_release release;
    if (rows == 0) throw error("rows must be positive");
    if (rows > max_simulated_rows) {
      throw error("rows: " + std::to_string(rows) + " are more than " + std::to_string(max_simulated_rows) +
                  ", pgm's limit of rows to simulate (docs/limits.md)");
    }
    const auto definition = sim::load_task_variant(task, variant, task_folders(tasks_dir));
    sim::simulate_options options;
    options.backend = backend;
    options.rows = rows;
    options.seed = seed;
    options.threads = threads;
    const auto layout = long_form ? std::optional(sim::episode_layout_of(definition)) : std::nullopt;
    data = sim::simulate(definition, options);
    if (layout) data = sim::episodes_of(data, definition, *layout);
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
    const auto folders = task_folders(args.tasks_dir);
    const auto scenarios = select_scenarios(args.scenario, find_scenario_folder(folders));
    experiment_options options;
    options.seed = args.seed;
    options.repetitions = args.repetitions;
    options.threads = args.threads;
    options.automatic_lines = args.automatic_lines;
    options.prevention.metric = parse_distance(args.distance);
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
    metric.add(std::string(to_string(p.metric)));
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
  m.attr("__version__") = pgm::version;
  // The library's defaults, which the package's own default None stands for (as the program's).
  m.attr("default_ci_test") = pgm::independence_test().name();
  m.def("ci_test_listing", [] { return pgm::independence_tests().listing(); });
  m.attr("default_score") = pgm::family_score().name();
  m.attr("default_learner") = std::string(pgm::default_structure_learner);
  m.attr("default_prior") = std::string(pgm::default_parameter_prior);
  m.def("score_listing", [] { return pgm::scores().listing(); });
  m.attr("missing_policies") = pgm::known_missing_policies();

  py::class_<network_handle>(m, "Network")
      .def_property_readonly("variables", [](const network_handle& h) { return names_of(h.network.variables()); })
      .def("states",
           [](const network_handle& h, const std::string& name) {
             return h.network.structure().at(pgm::node_of(h.network, name)).states();
           })
      .def("parents",
           [](const network_handle& h, const std::string& name) {
             return names_of(h.network.structure().parent_variables(pgm::node_of(h.network, name)));
           })
      .def("interval_edges",
           [](const network_handle& h, const std::string& name) -> std::optional<std::vector<double>> {
             const auto& v = h.network.structure().at(pgm::node_of(h.network, name));
             if (!v.has_intervals()) return std::nullopt;
             return v.edges();
           })
      .def_property_readonly("edges", [](const network_handle& h) { return to_pairs(h.network.structure().edges()); })
      .def_property_readonly("free_parameters", [](const network_handle& h) { return h.network.free_parameters(); })
      .def_property_readonly("success", [](const network_handle& h) { return h.success; })
      .def_property_readonly("notes", [](const network_handle& h) { return h.notes; })
      .def("table", &table_of)
      .def("write",
           [](const network_handle& h, const std::filesystem::path& path) {
             // The counts go along, in any format (BIF, XMLBIF, NET: as a property peers ignore).
             write_network(h.network, path, {.statistics = h.statistics ? &*h.statistics : nullptr});
           })
      .def_property_readonly("has_counts", [](const network_handle& h) { return h.statistics.has_value(); })
      .def("to_json", [](const network_handle& h) { return pgm::to_json(h.network).dump(2); })
      .def("to_dot", [](const network_handle& h, const std::vector<std::string>& success,
                        const std::vector<std::string>& controllable) {
        return pgm::to_dot(h.network.structure(), {.success = success, .controllable = controllable});
      });

  m.def("read_network", &read_network_file);
  add_markov(m);
  add_decisions(m);
  add_dynamic(m);
  m.def("network_from_tables", &network_from_tables);
  m.def("parse_edge_list", [](const std::string& text) { return to_pairs(pgm::parse_edge_list(text)); });
  m.def("backends", &pgm::sim::backends);
  // The library's "did you mean" and its message for an unknown name, for Python's own checks.
  m.def("closest_name", [](const std::string& word, const std::vector<std::string>& known) {
    return pgm::text::closest_name(word, known);
  });
  m.def("unknown_name_message",
        [](const std::string& kind, const std::string& name, const std::vector<std::string>& known) {
          return std::string(pgm::unknown_name(kind, name, known).what());
        });

  m.def(
      "fit",
      [](const py::list& columns, const std::vector<std::string>& available, const edge_pairs& edges,
         const std::string& estimator, const std::string& prior,
         const std::vector<std::tuple<std::string, std::string, std::string>>& prior_settings, const std::string& empty,
         unsigned threads, const std::optional<edges_by_name>& intervals,
         const std::optional<std::string>& intervals_file, const network_handle* prior_model,
         const std::string& strategy, const std::string& map, std::optional<double> w_prior, const std::string& success,
         const std::string& match, const std::optional<em_arguments>& em,
         const std::vector<std::pair<std::string, std::vector<std::string>>>& latent,
         const std::vector<std::pair<std::string, std::vector<std::string>>>& named_states, bool keep_counts) {
        fit_arguments args;
        args.keep_counts = keep_counts;
        args.states = named_states;
        args.estimator = {estimator, prior, {}};
        for (const auto& [keyword, key, value] : prior_settings)
          args.estimator.settings.push_back({keyword, key, value});
        args.empty = empty;
        args.threads = threads;
        args.intervals = intervals;
        args.intervals_file = intervals_file;
        args.prior_model = prior_model;
        args.transfer.strategy = strategy;
        args.transfer.map = map;
        args.transfer.weight = w_prior;
        args.transfer.success = success;
        args.transfer.matching = pgm::parse_state_matching(match);
        if (em) args.em = em_options_of(*em, threads);
        for (const auto& [name, states] : latent) args.latent.push_back({name, states});
        return fit_frame(columns, available, edges, args);
      },
      py::arg("columns"), py::arg("available"), py::arg("edges"), py::arg("estimator"), py::arg("prior"),
      py::arg("prior_settings"), py::arg("empty"), py::arg("threads"), py::arg("intervals"), py::arg("intervals_file"),
      py::arg("prior_model").none(true), py::arg("strategy"), py::arg("map"), py::arg("w_prior"), py::arg("success"),
      py::arg("match"), py::arg("em").none(true), py::arg("latent"), py::arg("states"), py::arg("keep_counts"));
  m.def("update", &update_frame);

  add_inference(m);
  add_causal(m);
  m.def("predict", &predict_plan);
  m.def("slice_table", &slice_of);
  m.def("prevent", &prevent_plan);

  m.def("learn_structure",
        [](const py::list& columns, const std::string& algorithm,
           const std::vector<std::tuple<std::string, std::string, std::string>>& settings, const std::string& tiers,
           const std::string& forbid, const std::string& require, unsigned threads, const edge_pairs& start,
           const std::optional<edge_pairs>& prior_edges, const std::string& map, double prior_weight) {
          return learn_frame(
              columns, {algorithm, settings, tiers, forbid, require, threads, start, prior_edges, map, prior_weight});
        });
  m.def("learner_defaults", [] { return declared_defaults(pgm::structure_learners()); });
  m.def("prior_defaults", [] { return declared_defaults(pgm::parameter_priors()); });
  m.def("prior_listing", [] { return pgm::parameter_priors().listing(); });
  m.def("learner_listing", [] { return pgm::structure_learners().listing(); });
  m.def("score", &score_frame);
  m.def("discretize", &discretize_frame);
  m.def("simulate", &simulate_task);
  m.def("experiment",
        [](const std::string& scenario, std::size_t repetitions, std::uint64_t seed, const std::string& backend,
           unsigned threads, const std::string& distance, bool automatic, const std::optional<std::string>& tasks_dir) {
          return run_experiments({scenario, repetitions, seed, backend, threads, distance, automatic, tasks_dir});
        });
}
