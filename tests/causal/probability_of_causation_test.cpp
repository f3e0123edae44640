// Probabilities of causation: Tian & Pearl's bounds on a published example, and on random
// structural models the true PN, PS and PNS (by enumeration of the twin worlds) always inside
// the bounds the models' own network gives.

#include "pgm/causal/probability_of_causation.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

namespace pgm::probability_of_causation_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(probability_of_causation_test, pearls_drug_example_makes_the_drug_necessary) {
  // Pearl, Causality (2nd ed., 2009), Sec. 9.3.4: an experiment gives P(death | do(drug)) =
  // 16/1000 and P(death | do(no drug)) = 14/1000; in the observational study half took the drug
  // and 2 of 1000 of them died, against 28 of 1000 of the rest. PN is then exactly 1.
  const causation_terms terms{.cause_effect = 0.5 * 0.002,
                              .cause_no_effect = 0.5 * 0.998,
                              .alternative_effect = 0.5 * 0.028,
                              .alternative_no_effect = 0.5 * 0.972,
                              .effect_if_cause = 0.016,
                              .effect_if_alternative = 0.014};
  const auto b = bound_causation(terms);
  EXPECT_NEAR(b.pn_lower, 1, 1e-12);
  EXPECT_EQ(b.pn_upper, 1);
  // Without the observations, the experiment alone bounds PNS by [0.002, 0.016].
  EXPECT_NEAR(b.pns_lower, 0.002, 1e-15);
  EXPECT_LE(b.pns_upper, 0.016);
}

TEST(probability_of_causation_test, without_a_case_to_explain_it_says_so) {
  EXPECT_THAT([] { (void)bound_causation({.alternative_no_effect = 0.5}); },
              ThrowsMessage<model_error>(HasSubstr("P(cause, effect) is 0")));
  EXPECT_THAT([] { (void)bound_causation({.cause_effect = 0.5}); },
              ThrowsMessage<model_error>(HasSubstr("P(alternative, no effect) is 0")));
}

/// A structural model over Z → X → Y, Z → Y: Z = U_Z, X = f_{U_X}(Z), Y = h_{U_Y}(X, Z), with
/// independent U's, each a response type (a function of the parents) with its probability.
struct structural_model {
  std::size_t x_states;
  std::vector<double> z;       // P(Z = z), two states
  std::vector<double> x_type;  // P(U_X = f), f coding x per z (base x_states, z = 0 fastest)
  std::vector<double> y_type;  // P(U_Y = h), h a bit per (x, z) cell
  [[nodiscard]] std::size_t x_of(std::size_t f, std::size_t z_value) const {
    return z_value == 0 ? f % x_states : f / x_states;
  }
  [[nodiscard]] static std::size_t y_of(std::size_t h, std::size_t x, std::size_t z_value) {
    return (h >> (x * 2 + z_value)) & 1U;
  }
};

std::vector<double> random_distribution(std::mt19937& rng, std::size_t n) {
  std::vector<double> p(n);
  double total = 0;
  // Sparse as well as spread: response types are often few.
  for (auto& v : p) total += v = rng() % 3 == 0 ? 0.0 : std::exponential_distribution<double>(1)(rng);
  if (total == 0) p[0] = total = 1;
  for (auto& v : p) v /= total;
  return p;
}

structural_model random_model(unsigned seed) {
  std::mt19937 rng(seed);
  structural_model m;
  m.x_states = 2 + seed % 2;
  m.z = random_distribution(rng, 2);
  for (auto& v : m.z) v = 0.1 + 0.8 * v;  // both states possible
  const double total = m.z[0] + m.z[1];
  for (auto& v : m.z) v /= total;
  m.x_type = random_distribution(rng, m.x_states * m.x_states);
  m.y_type = random_distribution(rng, std::size_t{1} << (2 * m.x_states));
  return m;
}

/// The model's causal network: P(z), P(x | z), P(y | x, z) as its response types give them.
bayesian_network network_of(const structural_model& m) {
  std::vector<std::string> x_labels;
  for (std::size_t x = 0; x < m.x_states; ++x) x_labels.push_back(std::to_string(x));
  const variable z("Z", {"0", "1"});
  const variable x("X", x_labels);
  const variable y("Y", {"0", "1"});
  std::vector<double> x_table(2 * m.x_states, 0.0);
  for (std::size_t f = 0; f < m.x_type.size(); ++f) {
    for (std::size_t zv = 0; zv < 2; ++zv) x_table[zv * m.x_states + m.x_of(f, zv)] += m.x_type[f];
  }
  std::vector<double> y_table(2 * m.x_states * 2, 0.0);  // parents (X, Z), Z fastest
  for (std::size_t h = 0; h < m.y_type.size(); ++h) {
    for (std::size_t xv = 0; xv < m.x_states; ++xv) {
      for (std::size_t zv = 0; zv < 2; ++zv)
        y_table[(xv * 2 + zv) * 2 + structural_model::y_of(h, xv, zv)] += m.y_type[h];
    }
  }
  return bayesian_network::from_tables(
      {cpt<double>(z, {}, m.z), cpt<double>(x, {z}, x_table), cpt<double>(y, {x, z}, y_table)});
}

struct true_values {
  double pn;
  double ps;
  double pns;
  double cause_effect;
  double alternative_no_effect;
};

/// PN, PS and PNS of the model by enumeration of every (z, U_X, U_Y), in the worlds where Z is
/// `only_z` (or any).
true_values enumerate(const structural_model& m, std::size_t xc, std::size_t xa, std::size_t y, int only_z) {
  double pn_top = 0, pn_bottom = 0, ps_top = 0, ps_bottom = 0, pns = 0, mass = 0;
  for (std::size_t zv = 0; zv < 2; ++zv) {
    if (only_z >= 0 && zv != static_cast<std::size_t>(only_z)) continue;
    for (std::size_t f = 0; f < m.x_type.size(); ++f) {
      for (std::size_t h = 0; h < m.y_type.size(); ++h) {
        const double w = m.z[zv] * m.x_type[f] * m.y_type[h];
        const auto x = m.x_of(f, zv);
        const auto seen = structural_model::y_of(h, x, zv);
        const bool if_cause = structural_model::y_of(h, xc, zv) == y;
        const bool if_alternative = structural_model::y_of(h, xa, zv) == y;
        mass += w;
        if (x == xc && seen == y) {
          pn_bottom += w;
          if (!if_alternative) pn_top += w;
        }
        if (x == xa && seen != y) {
          ps_bottom += w;
          if (if_cause) ps_top += w;
        }
        if (if_cause && !if_alternative) pns += w;
      }
    }
  }
  return {pn_top / pn_bottom, ps_top / ps_bottom, pns / mass, pn_bottom / mass, ps_bottom / mass};
}

TEST(probability_of_causation_test, the_bounds_hold_every_structural_model_that_agrees_with_the_network) {
  std::size_t checked = 0;
  for (unsigned seed = 0; seed < 300; ++seed) {
    SCOPED_TRACE(seed);
    const auto m = random_model(seed);
    const auto network = network_of(m);
    const std::size_t xa = m.x_states - 1;
    for (const int only_z : {-1, 0, 1}) {
      const auto truth = enumerate(m, 0, xa, 1, only_z);
      if (!(truth.cause_effect > 1e-9) || !(truth.alternative_no_effect > 1e-9)) continue;
      evidence observed;
      if (only_z >= 0) observed["Z"] = std::to_string(only_z);
      const auto terms = causation_terms_of(network, "X", "0", std::to_string(xa), "Y", "1", observed);
      EXPECT_NEAR(terms.cause_effect, truth.cause_effect, 1e-12);
      const auto b = bound_causation(terms);
      const double slack = 1e-9;
      EXPECT_LE(b.pn_lower, truth.pn + slack);
      EXPECT_GE(b.pn_upper, truth.pn - slack);
      EXPECT_LE(b.ps_lower, truth.ps + slack);
      EXPECT_GE(b.ps_upper, truth.ps - slack);
      EXPECT_LE(b.pns_lower, truth.pns + slack);
      EXPECT_GE(b.pns_upper, truth.pns - slack);
      ++checked;
    }
  }
  EXPECT_GT(checked, 500u);
}

TEST(probability_of_causation_test, a_question_the_network_cannot_ask_is_refused) {
  const auto network = network_of(random_model(3));
  EXPECT_THAT([&] { (void)causation_terms_of(network, "X", "0", "0", "Y", "1"); },
              ThrowsMessage<model_error>(HasSubstr("is the state the cause took")));
  EXPECT_THAT(
      [&] {
        (void)causation_terms_of(network, "X", "0", "1", "Y", "1", {{"Y", "0"}});
      },
      ThrowsMessage<model_error>(HasSubstr("evidence on 'Y'")));
  EXPECT_THAT([&] { (void)causation_terms_of(network, "X", "0", "1", "X", "1"); },
              ThrowsMessage<model_error>(HasSubstr("is also the effect")));
  EXPECT_THROW((void)causation_terms_of(network, "X", "0", "7", "Y", "1"), model_error);
}

}  // namespace
}  // namespace pgm::probability_of_causation_tests
