#pragma once
/// \file
/// The built-in structure learners, each a StructureLearner (pgm/learn/structure_learner.hpp)
/// that declares its options: PC-stable (pgm/learn/pc.hpp); hill climbing and tabu search
/// (pgm/learn/hill_climbing.hpp), which may start from another learner's result
/// ("hc[start=pc[alpha=0.05]]"); the hybrid in which PC-stable's skeleton restricts the
/// candidate parents of hill climbing (bnlearn's rsmax2 with PC as the restrict phase, "mmhc");
/// and the empty graph, which keeps only the required edges.

#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/component_options.hpp"
#include "pgm/learn/hill_climbing.hpp"
#include "pgm/learn/pc.hpp"
#include "pgm/learn/structure_learner.hpp"

namespace pgm {

/// PC-stable: its CPDAG, and one DAG of its class. Options test, alpha and max_conditioning.
class pc_learner {
 public:
  [[nodiscard]] PGM_DECL static std::vector<option_declaration> options();

  pc_learner() = default;
  explicit pc_learner(pc_options settings) : settings_(std::move(settings)) {}
  PGM_DECL explicit pc_learner(const option_values& options);

  /// Throws model_error when the problem has a start network or a structure prior.
  [[nodiscard]] PGM_DECL structure_result learn(const structure_problem& problem) const;

  [[nodiscard]] const pc_options& settings() const noexcept { return settings_; }

 private:
  pc_options settings_;
};

/// Hill climbing, or with a tabu list tabu search, from the problem's start network or from
/// the result of the learner `start`.
class hill_climbing_learner {
 public:
  /// score, max_parents, restarts, perturb, seed, max_iterations and start.
  [[nodiscard]] PGM_DECL static std::vector<option_declaration> options();

  hill_climbing_learner() = default;
  PGM_DECL explicit hill_climbing_learner(search_options settings, std::optional<structure_learner> start = {});
  PGM_DECL explicit hill_climbing_learner(const option_values& options);

  /// Throws model_error when both the problem and the options give a start.
  [[nodiscard]] PGM_DECL structure_result learn(const structure_problem& problem) const;

  [[nodiscard]] const search_options& settings() const noexcept { return settings_; }
  /// The learner whose result the search starts from, when the options name one.
  [[nodiscard]] const std::optional<structure_learner>& start() const noexcept { return start_; }

 protected:
  /// The search from `problem`, its candidate parents restricted to `candidates` (n × n, empty:
  /// any).
  [[nodiscard]] PGM_DECL structure_result search(const structure_problem& problem,
                                                 std::vector<unsigned char> candidates) const;

  search_options settings_;
  std::optional<structure_learner> start_;
};

/// Tabu search (bnlearn's tabu()): hill climbing's options and tabu (the list's length, 10) and
/// max_tabu (10).
class tabu_search_learner : public hill_climbing_learner {
 public:
  [[nodiscard]] PGM_DECL static std::vector<option_declaration> options();

  PGM_DECL tabu_search_learner();
  PGM_DECL explicit tabu_search_learner(const option_values& options);
  using hill_climbing_learner::learn;
};

/// PC-stable's skeleton, then hill climbing among its adjacencies: PC's options and hill
/// climbing's.
class hybrid_learner : public hill_climbing_learner {
 public:
  [[nodiscard]] PGM_DECL static std::vector<option_declaration> options();

  hybrid_learner() = default;
  PGM_DECL explicit hybrid_learner(const option_values& options);

  [[nodiscard]] PGM_DECL structure_result learn(const structure_problem& problem) const;

  [[nodiscard]] const pc_options& restriction() const noexcept { return restrict_; }

 private:
  pc_options restrict_;
};

/// The empty graph, with the required edges: the baseline, and where a search starts.
struct empty_learner {
  [[nodiscard]] PGM_DECL structure_result learn(const structure_problem& problem) const;
};

static_assert(StructureLearner<pc_learner> && StructureLearner<hill_climbing_learner> &&
              StructureLearner<tabu_search_learner> && StructureLearner<hybrid_learner> &&
              StructureLearner<empty_learner>);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/structure_learners.ipp"
#endif
