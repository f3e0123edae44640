// A learner that returns a bare DAG rather than a structure_result is not a StructureLearner:
// register_structure_learner refuses it.
#include <pgm/learn/structure_learner_registry.hpp>

struct bare_learner {
#ifdef PGM_CONTROL
  [[nodiscard]] pgm::structure_result learn(const pgm::structure_problem& problem) const;
#else
  [[nodiscard]] pgm::dag learn(const pgm::structure_problem& problem) const;
#endif
};

static const pgm::register_structure_learner<bare_learner> registered("bare", "a DAG and nothing else");
