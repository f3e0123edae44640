// Variable elimination against brute-force enumeration of the joint, on random networks and
// the published sachs network, plus the factor operations it is built from and its errors.

#include "pgm/inference/variable_elimination.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "pgm/inference/factor.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/testing/random_network.hpp"
#include "support/enumeration.hpp"

namespace pgm::variable_elimination_tests {
namespace {

using ::testing::DoubleNear;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

const variable_id a(0), b(1), c(2);

TEST(factor_test, product_aligns_shared_variables) {
  const factor f({a, b}, {2, 2}, {1, 2, 3, 4});  // f(a, b), b fastest
  const factor g({b, c}, {2, 3}, {1, 10, 100, 2, 20, 200});
  const auto h = f * g;
  EXPECT_THAT(h.scope(), ElementsAre(a, b, c));
  const std::size_t s[] = {1, 1, 2};  // f(1,1)·g(1,2) = 4·200
  EXPECT_EQ(h.at(s), 800.0);
  const std::size_t t[] = {0, 1, 0};  // f(0,1)·g(1,0) = 2·2
  EXPECT_EQ(h.at(t), 4.0);
}

TEST(factor_test, sum_out_reduce_and_permute) {
  const factor f({a, b}, {2, 3}, {1, 2, 3, 4, 5, 6});
  EXPECT_EQ(f.sum_out(a), factor({b}, {3}, {5, 7, 9}));
  EXPECT_EQ(f.sum_out(b), factor({a}, {2}, {6, 15}));
  EXPECT_EQ(f.reduce(b, 2), factor({a}, {2}, {3, 6}));
  EXPECT_EQ(f.reduce(a, 1), factor({b}, {3}, {4, 5, 6}));
  const variable_id order[] = {b, a};
  EXPECT_EQ(f.permuted(order), factor({b, a}, {3, 2}, {1, 4, 2, 5, 3, 6}));
  EXPECT_EQ(f.sum_out(c), f);
}

TEST(factor_test, rejects_bad_shapes) {
  EXPECT_THROW(factor({a, b}, {2, 2}, {1, 2, 3}), model_error);
  EXPECT_THROW(factor({a, a}, {2, 2}, {1, 2, 3, 4}), model_error);
}

void expect_matches_enumeration(const bayesian_network& net, std::span<const variable_id> q,
                                std::span<const observation> e, elimination_heuristic h, double tolerance = 1e-12) {
  auto expected = testing::enumerate_joint(net, q, e);
  double total = 0;
  for (double v : expected) total += v;
  auto got = joint_with_evidence(net, q, e, h);
  ASSERT_EQ(got.size(), expected.size());
  EXPECT_NEAR(got.sum(), total, tolerance);
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(got.values()[i], expected[i], tolerance);
}

TEST(variable_elimination_test, matches_enumeration_on_random_networks) {
  std::mt19937_64 random(7);
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const auto net = testing::random_network(seed, {.nodes = 9, .max_parents = 3, .min_states = 2, .max_states = 3});
    std::vector<variable_id> nodes;
    for (std::size_t i = 0; i < net.size(); ++i) nodes.push_back(index_at<variable_id>(i));
    std::shuffle(nodes.begin(), nodes.end(), random);
    const auto queried = 1 + random() % 3;
    const auto observed = random() % 3;
    std::vector<variable_id> q(nodes.begin(), nodes.begin() + static_cast<long>(queried));
    std::vector<observation> e;
    for (std::size_t k = 0; k < observed; ++k) {
      const auto id = nodes[queried + k];
      e.push_back({id, index_at<state_index>(random() % net.variables()[id.value()].cardinality())});
    }
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_matches_enumeration(net, q, e, elimination_heuristic::min_fill);
    expect_matches_enumeration(net, q, e, elimination_heuristic::min_degree);
  }
}

TEST(variable_elimination_test, posterior_by_name_is_normalized) {
  const auto net = testing::random_network(3, {.nodes = 6});
  const auto p = query(net, {"v5", "v2"}, {{"v0", "s1"}});
  EXPECT_NEAR(p.table.sum(), 1.0, 1e-12);
  const variable_id q[] = {net.id("v5"), net.id("v2")};
  const observation e[] = {{net.id("v0"), state_index(1)}};
  const auto raw = testing::enumerate_joint(net, q, e);
  double total = 0;
  for (double v : raw) total += v;
  EXPECT_NEAR(p.evidence_probability, total, 1e-12);
  EXPECT_NEAR(p.probability({"s0", "s1"}), raw[1] / total, 1e-12);
}

bayesian_network coin_and_lamp() {
  const variable coin("coin", {"heads", "tails"});
  const variable lamp("lamp", {"off", "on"});
  return bayesian_network::from_tables(
      {cpt<double>(coin, {}, {1.0, 0.0}), cpt<double>(lamp, {coin}, {0.3, 0.7, 0.5, 0.5})});
}

TEST(variable_elimination_test, reports_unknown_names_and_impossible_evidence) {
  const auto net = coin_and_lamp();
  EXPECT_THAT([&] { static_cast<void>(query(net, {"lamb"})); },
              ::testing::ThrowsMessage<model_error>(HasSubstr("no variable 'lamb' (variables: coin, lamp)")));
  EXPECT_THAT(
      [&] {
        static_cast<void>(query(net, {"lamp"}, {{"coin", "edge"}}));
      },
      ::testing::ThrowsMessage<model_error>(HasSubstr("no state 'edge'")));
  EXPECT_THAT(
      [&] {
        static_cast<void>(query(net, {"lamp"}, {{"lamp", "on"}}));
      },
      ::testing::ThrowsMessage<model_error>(HasSubstr("both queried and observed")));
  EXPECT_THAT(
      [&] {
        static_cast<void>(query(net, {"lamp"}, {{"coin", "tails"}}));
      },
      ::testing::ThrowsMessage<impossible_evidence>(HasSubstr("coin=tails has probability 0")));
  const auto p = query(net, {"coin"}, {{"lamp", "on"}});
  EXPECT_NEAR(p.probability({"heads"}), 1.0, 1e-15);
}

TEST(variable_elimination_test, sachs_matches_enumeration) {
  const auto path = std::filesystem::path(PGM_NETWORKS_DIR) / "sachs.bif";
  const auto net = read_bif(path);
  // The published tables print 8-10 digits, so their columns sum to one within ~1e-7;
  // enumeration multiplies in the tables VE prunes (non-ancestors), hence the tolerance.
  const double tolerance = 1e-6;
  const variable_id q[] = {net.id("Akt"), net.id("Erk")};
  const observation e[] = {{net.id("PKA"), state_index(2)}, {net.id("Raf"), state_index(0)}};
  expect_matches_enumeration(net, q, e, elimination_heuristic::min_fill, tolerance);
  const variable_id all[] = {net.id("Plcg"), net.id("PIP3")};
  expect_matches_enumeration(net, all, {}, elimination_heuristic::min_degree, tolerance);
}

TEST(variable_elimination_test, elimination_order_avoids_fill_on_a_chain) {
  // a - b - c chain: eliminating b first would join a and c; min-fill takes an end first.
  const std::vector<factor> factors{factor({a, b}, {2, 2}, {1, 1, 1, 1}), factor({b, c}, {2, 2}, {1, 1, 1, 1})};
  const auto order = elimination_order(factors, {b, a, c});
  EXPECT_NE(order.front(), b);
}

}  // namespace
}  // namespace pgm::variable_elimination_tests
