#pragma once
/// \file
/// "Fit this model from this source" in one call: the structure (edges over the source's
/// columns, or a model's structure with its states), the columns read and binned as asked, every
/// family counted by the source (a data set, a streamed CSV file, NumPy columns:
/// pgm/learn/family_source.hpp), the intervals kept, the priors transferred from a related
/// task's network (eq. 7–9) where one is given, and every table estimated. `pgm fit`, the
/// Python module and the experiment all fit through it.

#include <algorithm>
#include <exception>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/data/discretizer.hpp"
#include "pgm/data/family_counts.hpp"
#include "pgm/learn/expectation_maximization.hpp"
#include "pgm/learn/family_source.hpp"
#include "pgm/learn/fit.hpp"
#include "pgm/learn/fit_statistics.hpp"
#include "pgm/transfer/transfer_settings.hpp"

namespace pgm {

/// A variable in no column of the data, fitted by EM.
struct latent_variable {
  std::string name;
  /// Its states; empty takes a model structure's.
  std::vector<std::string> states;
};

struct fit_request {
  /// The structure: edges over the source's columns (the variables are the columns they name,
  /// in the source's order, their states the values seen), or a model's structure, whose
  /// columns must hold its variables' states.
  std::variant<std::vector<named_edge>, network_structure> structure;
  /// Priors, the empty-configuration rule, counting threads.
  fit_options options;
  /// Raw numeric columns binned into these intervals as they are read.
  discretization bin;
  /// The intervals that already discretized columns hold, kept with the model;
  /// `intervals_source` names where they came from, in messages.
  discretization intervals;
  std::string intervals_source = "intervals";
  /// With edges: columns whose states are given (in order), not taken from the values seen;
  /// every one is a state, also one no row has, and a value among none of them is an error.
  /// Saved `intervals` give their columns' states alike.
  discretization states;
  /// What a missing value is and what happens to it.
  missing_values missing;
  /// A related task's network: every node the map of `transfer` reaches gets its transferred
  /// prior (eq. 8), the weight w chosen from the counts unless given.
  const bayesian_network* prior_network = nullptr;
  transfer_settings transfer;
  /// Fit by EM (pgm/learn/expectation_maximization.hpp) instead of counting once: the missing
  /// values are then kept whatever `missing.policy` says, and the source must give its rows
  /// (row_source).
  std::optional<em_options> em;
  /// Latent variables, in no column of the source (EM only). With edges over the columns each
  /// needs its states; with a model structure each names one of its variables, whose states
  /// are the model's (states given must be the same).
  std::vector<latent_variable> latent;
  /// Keep the counts and priors in fit_result::statistics, so that the network can be
  /// updated with new data later (a copy of every count table).
  bool keep_statistics = false;
};

struct fit_result {
  /// The fitted network; empty where `holds_network` is false.
  bayesian_network network;
  /// False on the processes of a group other than the first, which counted their part of the
  /// data and hold no result.
  bool holds_network = true;
  /// What the source read: rows, rows dropped for a missing value, each family's counts (over
  /// the network's variables), values outside the binning edges.
  family_counts counts;
  /// Which priors were transferred, with which weights, when a prior network was given.
  std::optional<transfer_report> transfer;
  /// How EM went, when it fitted (its network is `network`, and `counts` holds the
  /// available-case counts, those of latent families empty).
  std::optional<em_result> em;
  /// The counts and priors the tables were estimated from, for adding data later
  /// (pgm/learn/fit_statistics.hpp); not for a fit by EM, whose counts are expectations.
  std::optional<fit_statistics> statistics;
};

/// The columns named by `edges`, in order of first appearance.
[[nodiscard]] PGM_DECL std::vector<std::string> columns_of(const std::vector<named_edge>& edges);

namespace detail {

/// Each node's family by name, in node order, parents in the structure's order.
[[nodiscard]] PGM_DECL std::vector<family_names> families_of(const network_structure& structure);

/// Whether `name` is among the request's latent variables.
[[nodiscard]] PGM_DECL const latent_variable* latent_named(const fit_request& request, std::string_view name);

/// The variable whose states column `name` holds, when the request gives them (saved intervals,
/// or states named), else nullptr.
[[nodiscard]] PGM_DECL const variable* known_states(const fit_request& request, std::string_view name);

/// The EM path of fit(): the source's rows read once, the latent variables added to the
/// structure, the transferred priors chosen from the available-case counts.
template <row_source Source>
[[nodiscard]] fit_result fit_by_em(Source& source, const fit_request& request) {
  for (const auto& v : request.latent) {
    if (v.states.size() > max_latent_states) {
      throw model_error("the latent variable '" + v.name + "' has " + std::to_string(v.states.size()) +
                        " states, more than pgm's limit of " + std::to_string(max_latent_states) +
                        " for a latent variable (docs/limits.md)");
    }
  }
  for (const auto& column : source.columns()) {
    if (latent_named(request, column)) {
      throw data_error(source.name() + ": '" + column + "' is declared latent but is a column of the data");
    }
  }
  family_count_request reading;
  reading.missing = request.missing;
  reading.missing.policy = missing_policy::available;
  reading.threads = request.options.counting.threads;
  network_structure structure;
  const auto* edges = std::get_if<std::vector<named_edge>>(&request.structure);
  if (!edges) {
    structure = std::get<network_structure>(request.structure);
    for (const auto& v : request.latent) {
      if (!structure.contains(v.name)) throw model_error("the latent variable '" + v.name + "' is not in the model");
      if (!v.states.empty() && v.states != structure.at(v.name).states()) {
        throw model_error("the latent variable '" + v.name + "' is given the states {" +
                          text::list_for_message(v.states) + "}, the model {" +
                          text::list_for_message(structure.at(v.name).states()) + "}");
      }
    }
    for (const auto& v : structure.variables()) {
      if (request.bin.contains(v.name())) structure.update_variable(request.bin.at(v.name()));
    }
    for (const auto& v : structure.variables()) {
      if (latent_named(request, v.name())) continue;
      reading.columns.push_back(v.name());
      (request.bin.contains(v.name()) ? reading.intervals : reading.variables).emplace(v.name(), v);
    }
  } else {
    const auto named = columns_of(*edges);
    for (const auto& v : request.latent) {
      // A latent variable in no edge would be an isolated node no data can inform.
      if (std::find(named.begin(), named.end(), v.name) == named.end()) {
        throw model_error("the latent variable '" + v.name + "' is in no edge");
      }
    }
    for (const auto& name : named) {
      if (latent_named(request, name)) continue;
      reading.columns.push_back(name);
      if (request.bin.contains(name)) {
        reading.intervals.emplace(name, request.bin.at(name));
      } else if (const auto* known = known_states(request, name)) {
        reading.variables.emplace(name, *known);
      }
    }
  }
  fit_result result;
  const auto data = source.read(reading, result.counts);
  if (edges) {
    std::vector<variable> variables;
    for (const auto& name : data.names()) variables.push_back(data.discrete(name).var());
    for (const auto& v : request.latent) {
      if (v.states.empty()) throw model_error("the latent variable '" + v.name + "' needs its states");
      variables.emplace_back(v.name, v.states);
    }
    structure = network_structure(std::move(variables), *edges);
  }
  if (!request.intervals.empty()) {
    structure = with_intervals(std::move(structure), request.intervals, request.intervals_source);
  }
  auto options = request.options;
  for (std::size_t i = 0; i < structure.size(); ++i) {
    const variable_id node = index_at<variable_id>(i);
    const auto parents = structure.parent_variables(node);
    const bool latent_family = latent_named(request, structure.at(node).name()) ||
                               std::any_of(parents.begin(), parents.end(), [&](const variable& p) {
                                 return latent_named(request, p.name()) != nullptr;
                               });
    result.counts.families.push_back(latent_family ? count_table(structure.at(node), parents)
                                                   : count_node(structure, node, data, options.counting));
  }
  for (const auto& name : data.names()) result.counts.variables.push_back(data.discrete(name).var());
  if (request.prior_network) {
    result.transfer = add_transferred_priors(options, structure, std::span<const count_table>(result.counts.families),
                                             *request.prior_network, request.transfer);
  }
  auto em = expectation_maximization(structure, data, options, *request.em);
  result.network = std::move(em.network);
  result.em = std::move(em);
  return result;
}

}  // namespace detail

/// Fits `request`'s structure from `source`. Errors in the data (a missing column, a value that
/// is not a state, a missing value under the policy error) are reported before errors in the
/// structure (a cycle), as when the data were read first. Throws data_error, model_error,
/// not_a_dag.
template <family_source Source>
[[nodiscard]] fit_result fit(Source& source, const fit_request& request) {
  if (request.em) {
    if constexpr (row_source<Source>) {
      return detail::fit_by_em(source, request);
    } else {
      throw model_error(source.name() + ": EM reads the data at every iteration and needs them in memory");
    }
  }
  if (!request.latent.empty()) throw model_error("latent variables are fitted by EM only");
  family_count_request counting;
  counting.missing = request.missing;
  counting.threads = request.options.counting.threads;
  network_structure structure;
  const auto* edges = std::get_if<std::vector<named_edge>>(&request.structure);
  std::exception_ptr structure_error;
  if (!edges) {
    structure = std::get<network_structure>(request.structure);
    for (const auto& v : structure.variables()) {
      if (request.bin.contains(v.name())) structure.update_variable(request.bin.at(v.name()));
    }
    for (const auto& v : structure.variables()) {
      counting.columns.push_back(v.name());
      (request.bin.contains(v.name()) ? counting.intervals : counting.variables).emplace(v.name(), v);
    }
    counting.families = detail::families_of(structure);
  } else {
    counting.columns = columns_of(*edges);
    for (const auto& name : counting.columns) {
      if (request.bin.contains(name)) {
        counting.intervals.emplace(name, request.bin.at(name));
      } else if (const auto* known = detail::known_states(request, name)) {
        counting.variables.emplace(name, *known);
      }
    }
    // The families come from the structure over the source's columns in its order (as
    // structure_from_data builds it), with placeholder states until the data give theirs.
    std::vector<variable> placeholders;
    for (const auto& name : source.columns()) {
      if (std::find(counting.columns.begin(), counting.columns.end(), name) != counting.columns.end()) {
        placeholders.emplace_back(name, std::vector<std::string>{"?"});
      }
    }
    if (placeholders.size() == counting.columns.size()) {  // else counting reports the missing column
      try {
        counting.families = detail::families_of(network_structure(placeholders, *edges));
      } catch (const error&) {
        structure_error = std::current_exception();
      }
    }
  }
  fit_result result;
  auto counted = source.count(counting);
  if (!source.holds_counts()) {
    result.holds_network = false;
    return result;
  }
  if (structure_error) std::rethrow_exception(structure_error);
  if (edges) structure = network_structure(counted.variables, *edges);
  if (!request.intervals.empty()) {
    structure = with_intervals(std::move(structure), request.intervals, request.intervals_source);
  }
  // The counts under the structure's variables, which may carry intervals and tags.
  std::vector<count_table> counts;
  for (std::size_t i = 0; i < structure.size(); ++i) {
    const variable_id node = index_at<variable_id>(i);
    auto parents = structure.parent_variables(node);
    const auto& family = counted.families.at(i);
    bool same_family = family.child().name() == structure.at(node).name() && family.parents().size() == parents.size();
    for (std::size_t k = 0; same_family && k < parents.size(); ++k) {
      same_family = family.parents()[k].name() == parents[k].name();
    }
    if (!same_family) throw std::logic_error("the counted family of '" + family.child().name() + "' is out of order");
    counts.push_back(family.with_variables(structure.at(node), std::move(parents)));
  }
  auto options = request.options;
  if (request.prior_network) {
    result.transfer = add_transferred_priors(options, structure, std::span<const count_table>(counts),
                                             *request.prior_network, request.transfer);
  }
  result.network = fit(structure, std::span<const count_table>(counts), options);
  if (request.keep_statistics) {
    result.statistics =
        statistics_of(structure, std::span<const count_table>(counts), static_cast<double>(counted.rows), options);
  }
  counted.families = std::move(counts);
  result.counts = std::move(counted);
  return result;
}

/// What update() needs besides the model: how to read the new rows, and how much the old
/// counts still weigh.
struct update_request {
  missing_values missing;
  unsigned threads = 0;
  /// The old counts are multiplied by this, in (0, 1], before the new ones are added.
  double decay = 1.0;
};

/// The network `structure` (the model's: its states are those the new rows must hold) after
/// the rows of `source` are added to `statistics`, each table estimated again under the prior
/// it was fitted with. With decay 1 this equals, to the last bit, fitting the old and the new
/// rows together. The result's `statistics` are the updated ones, its `counts` the new rows'.
template <family_source Source>
[[nodiscard]] fit_result update(Source& source, const network_structure& structure, const fit_statistics& statistics,
                                const update_request& request) {
  if (!(request.decay > 0.0 && request.decay <= 1.0)) {
    throw model_error("the decay must be in (0, 1], got " + text::format_double(request.decay));
  }
  fit_request counting;
  counting.structure = structure;
  counting.missing = request.missing;
  counting.options.counting.threads = request.threads;
  auto result = fit(source, counting);
  if (!result.holds_network) return result;
  auto next = updated(statistics, std::span<const count_table>(result.counts.families),
                      static_cast<double>(result.counts.rows), request.decay);
  result.network = estimate_network(structure, next);
  result.statistics = std::move(next);
  return result;
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/pipeline/impl/fit_pipeline.ipp"
#endif
