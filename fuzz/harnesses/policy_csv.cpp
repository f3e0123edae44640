// Policies as CSV (pgm/io/policy_csv.hpp) against a small influence diagram, with perfect recall
// and limited memory, with and without evidence: a policy read has an action in range for every
// configuration of what it observes, and is worth a finite expected utility or a pgm::error.

#include "pgm/io/policy_csv.hpp"

#include <cmath>

#include "harness.hpp"
#include "pgm/decide/solve_decisions.hpp"

namespace {

// A (2 states) -> B (3) <- D1; D2 observes B; U(A, D2).
const pgm::influence_diagram& small_diagram() {
  static const auto diagram = [] {
    pgm::influence_diagram d;
    const auto a = d.add_chance(pgm::variable("A", {"a0", "a1"}));
    const auto d1 = d.add_decision(pgm::variable("D1", {"go", "stay"}));
    const auto b = d.add_chance(pgm::variable("B", {"b0", "b1", "b2"}));
    const auto d2 = d.add_decision(pgm::variable("D2", {"x", "y"}));
    d.set_table(a, {}, {0.4, 0.6});
    d.set_table(b, {a, d1}, {0.2, 0.3, 0.5, 0.6, 0.2, 0.2, 0.1, 0.1, 0.8, 0.3, 0.3, 0.4});
    d.set_observed(d2, {b});
    d.add_utility("U", {a, d2}, {10, -5, 0, 20});
    d.add_utility("V", {d1}, {-1, 0});
    return d;
  }();
  return diagram;
}

void check(std::string_view text, const pgm::evidence& observed, bool limited_memory) {
  const auto& d = small_diagram();
  const auto read =
      pgm::fuzz::outcome_of([&] { return pgm::parse_policy_csv(text, "p.csv", d, observed, limited_memory); });
  if (!read.value) return;
  for (const auto& policy : *read.value) {
    std::size_t configurations = 1;
    for (const auto id : policy.observed) configurations *= d.at(id).cardinality();
    if (policy.actions.size() != configurations) pgm::fuzz::violated("a policy without one action per configuration");
    for (const auto action : policy.actions) {
      if (action >= d.at(policy.decision).cardinality()) pgm::fuzz::violated("an action out of range was accepted");
    }
  }
  const auto worth = pgm::fuzz::outcome_of([&] { return pgm::expected_utility(d, *read.value, observed); });
  if (worth.value && !std::isfinite(*worth.value)) pgm::fuzz::violated("a policy worth a non-finite utility");
}

}  // namespace

PGM_FUZZ_HARNESS(policy_csv) {
  const auto text = pgm::fuzz::text_of(data, size);
  for (const bool limited : {false, true}) {
    check(text, {}, limited);
    check(text, {{"A", "a1"}}, limited);
  }
  return 0;
}
