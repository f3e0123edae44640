#pragma once
/// \file
/// `transfer_problem`: everything a transfer strategy reads — the prior task's table of the
/// transferred node X′ (and its network, for marginalizing unassigned parents), the target node
/// X with its parents and states, and the correspondence map — and `transferred_prior`, what
/// it returns: f(θ′_{·|u′}) for every target configuration u, with the u′ each came from.

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/correspondence.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/transfer/state_map.hpp"

namespace pgm {

struct transfer_options {
  state_matching matching = state_matching::midpoint;
  /// The target child's success state, which Minimal-Replacement compares (eq. 9).
  std::string success_state = "1";
};

/// The inputs of a transfer. It refers to the prior network (or table), which must outlive it.
class transfer_problem {
 public:
  /// Transfers the table of `prior_node` of `prior_network` to `target_child` given
  /// `target_parents`.
  PGM_DECL transfer_problem(const bayesian_network& prior_network, std::string_view prior_node, variable target_child,
                            std::vector<variable> target_parents, correspondence map, transfer_options options = {});

  /// Without the prior network: unassigned prior parents can then only be pinned, not
  /// marginalized.
  PGM_DECL transfer_problem(const cpt<double>& prior_table, variable target_child, std::vector<variable> target_parents,
                            correspondence map, transfer_options options = {});

  [[nodiscard]] const cpt<double>& prior_table() const noexcept { return *prior_table_; }
  [[nodiscard]] const bayesian_network* prior_network() const noexcept { return prior_network_; }
  [[nodiscard]] const variable& target_child() const noexcept { return target_child_; }
  [[nodiscard]] const std::vector<variable>& target_parents() const noexcept { return target_parents_; }
  [[nodiscard]] const correspondence& map() const noexcept { return map_; }
  [[nodiscard]] const transfer_options& options() const noexcept { return options_; }

  /// The target child's success state, or a model_error saying what is missing.
  [[nodiscard]] PGM_DECL std::size_t success_state() const;

 private:
  const cpt<double>* prior_table_;
  const bayesian_network* prior_network_ = nullptr;
  variable target_child_;
  std::vector<variable> target_parents_;
  correspondence map_;
  transfer_options options_;
};

/// Which candidate of Minimal-Replacement a configuration's prior came from.
enum class replacement : std::uint8_t { direct, cross, other };

[[nodiscard]] PGM_DECL const char* to_string(replacement r);

/// One prior configuration u′ and its share in a target configuration's prior.
struct prior_term {
  std::uint32_t configuration;
  double weight;
  friend bool operator==(const prior_term&, const prior_term&) = default;
};

/// The prior table f(θ′) in the target node's shape, with the u′ behind every column.
class transferred_prior {
 public:
  /// `terms` lists each target configuration's prior terms one after the other; `term_counts`
  /// says how many each has.
  PGM_DECL transferred_prior(cpt<double> table, std::vector<variable> prior_parents, std::vector<prior_term> terms,
                             std::vector<std::uint32_t> term_counts, std::vector<replacement> via);

  [[nodiscard]] const cpt<double>& table() const noexcept { return table_; }
  [[nodiscard]] const std::vector<variable>& prior_parents() const noexcept { return prior_parents_; }
  /// The prior configurations u′ that target configuration u's column mixes (one, unless
  /// states were overlap-matched or parents marginalized).
  [[nodiscard]] std::span<const prior_term> sources(config_index u) const {
    return std::span(terms_).subspan(offsets_.at(u.value()), offsets_[u.value() + 1] - offsets_[u.value()]);
  }
  [[nodiscard]] replacement via(config_index u) const { return via_.at(u.value()); }

  /// "xOff1=2, yOff1=3" for u′, with weights when several u′ are mixed.
  [[nodiscard]] PGM_DECL std::string describe_sources(config_index u) const;

 private:
  [[nodiscard]] PGM_DECL mixed_radix prior_radix() const;

  cpt<double> table_;
  std::vector<variable> prior_parents_;
  std::vector<prior_term> terms_;
  std::vector<std::uint32_t> offsets_;
  std::vector<replacement> via_;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/transfer/impl/transfer_problem.ipp"
#endif
