// A score that reads more than a family's counts is not a FamilyScore (a search calls it on
// counts alone): register_score refuses it.
#include <pgm/learn/score_registry.hpp>

struct data_score {
#ifdef PGM_CONTROL
  double operator()(const pgm::count_table& counts) const;
#else
  double operator()(const pgm::count_table& counts, const pgm::dataset& data) const;
#endif
};

static const pgm::register_score<data_score> registered("data", "reads the data again");
