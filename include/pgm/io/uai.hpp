#pragma once
/// \file
/// The UAI inference competitions' formats (the field's benchmark; libDAI, Merlin, toulbar2,
/// JunctionTrees.jl and pgmpy read them):
///
/// | file | holds |
/// |---|---|
/// | `.uai` | a model: `MARKOV` (any factors) or `BAYES` (one table per variable, the child last in its scope) |
/// | `.evid` | observed states: the 2014 one-line form `k v1 s1 … vk sk`, or the older form `N` then `N` such samples |
/// | `.query` | the query variables of marginal MAP: `k v1 … vk` |
/// | `.PR`, `.MAR`, `.MAP`, `.MMAP` | an answer: the task's name, then log10 Z; the marginals; an assignment |
///
/// A model file lists the variables' cardinalities, then each factor's scope, then each factor's
/// table (its number of entries, then the entries, the scope's last variable fastest). UAI keeps
/// no names: variables read as v0, v1, … with states 0, 1, …. Errors name the file, line and
/// column and what was expected. A `.uai` file is also a network format (pgm/io/network_format.hpp)
/// for Bayesian networks: `pgm convert alarm.bif alarm.uai` writes `BAYES`.
///
/// Compiled into the library (src/lib/io/uai.cpp, pgm::pgm).

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/markov_network.hpp"
#include "pgm/core/strong_index.hpp"

namespace pgm {

/// What a `.uai` file says it holds.
enum class uai_kind { markov, bayes };

/// A `.uai` model: its factors as a Markov network (a BAYES file's tables are its factors, so
/// Z = 1), and which kind the file declared.
struct uai_model {
  uai_kind kind = uai_kind::markov;
  markov_network model;
};

/// Parses a `.uai` model; `source` names it in errors (parse_error for the text, model_error for
/// what does not fit: a scope naming a variable that does not exist, a table of the wrong length,
/// a cardinality of 0, a negative or NaN value, a BAYES file whose tables are not distributions).
[[nodiscard]] uai_model parse_uai(std::string_view text, const std::string& source);

/// A `.uai` or `.uai.gz` file.
[[nodiscard]] uai_model read_uai(const std::filesystem::path& path);

/// A BAYES model as a Bayesian network (variables v0, v1, … with states 0, 1, …). Throws
/// model_error for a MARKOV model, or tables that are not one distribution per child.
[[nodiscard]] bayesian_network to_bayesian_network(const uai_model& model, const std::string& source);

/// A Markov network's text as a `MARKOV` file.
[[nodiscard]] std::string to_uai(const markov_network& model);

/// A Bayesian network's text as a `BAYES` file (names are lost: UAI has none).
[[nodiscard]] std::string to_uai(const bayesian_network& network);

/// The samples of a `.evid` file, each a list of (variable, state) checked against `model`
/// (an unknown variable or state, or a variable observed twice in a sample, is an error naming
/// it). An empty file or `0` is one sample with nothing observed.
[[nodiscard]] std::vector<std::vector<std::pair<variable_id, std::size_t>>> parse_uai_evidence(
    std::string_view text, const std::string& source, const markov_network& model);

/// The query variables of a `.query` file, checked against `model`.
[[nodiscard]] std::vector<variable_id> parse_uai_query(std::string_view text, const std::string& source,
                                                       const markov_network& model);

/// A result file: its task's name (PR, MAR, MAP, MMAP) and its numbers after the name.
struct uai_result {
  std::string task;
  std::vector<double> numbers;
};

/// Parses a result file as the competitions publish them (for comparing answers).
[[nodiscard]] uai_result parse_uai_result(std::string_view text, const std::string& source);

/// The result files' text, every number to 17 significant digits.
[[nodiscard]] std::string uai_pr_text(double log10_partition);
/// MAR: the number of variables, then each one's cardinality and probabilities.
[[nodiscard]] std::string uai_mar_text(const std::vector<std::vector<double>>& marginals);
/// MAP and MMAP: the number of assigned variables, then their states.
[[nodiscard]] std::string uai_assignment_text(std::string_view task, std::span<const std::size_t> states);

}  // namespace pgm
