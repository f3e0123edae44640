// A semiring that does not say whether its ⊕ is idempotent is not a Semiring: joint_in refuses it.
#include <pgm/inference/variable_elimination.hpp>

struct min_sum {
  using value_type = double;
#ifdef PGM_CONTROL
  static constexpr bool idempotent = true;
#endif
  static constexpr double zero() { return 1e300; }
  static constexpr double one() { return 0.0; }
  static constexpr double plus(double a, double b) { return a < b ? a : b; }
  static constexpr double times(double a, double b) { return a + b; }
  static double from_probability(double p);
  static double to_probability(double a);
};

pgm::factor_of<min_sum> cheapest(const pgm::markov_network& model, std::span<const pgm::variable_id> query) {
  return pgm::joint_in<min_sum>(model, query, pgm::evidence_set{});
}
