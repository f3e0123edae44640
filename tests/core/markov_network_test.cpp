// markov_network and factor_table: what they hold and every error naming what is wrong; the
// GraphicalModel concept both ways, and a Bayesian network read as its factors.

#include "pgm/core/markov_network.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "pgm/core/graphical_model.hpp"
#include "pgm/io/bif.hpp"

namespace pgm {
namespace markov_network_test {

using ::testing::HasSubstr;

template <class F>
std::string error_of(F&& make) {
  try {
    make();
  } catch (const error& e) {
    return e.what();
  }
  return "no error";
}

const variable a("a", {"0", "1"});
const variable b("b", {"x", "y", "z"});

TEST(markov_network_test, holds_variables_and_factors) {
  const markov_network model({a, b}, {factor_table({variable_id(1), variable_id(0)}, {3, 2}, {1, 2, 3, 4, 5, 6}),
                                      factor_table({variable_id(0)}, {2}, {0.5, 0.0})});
  EXPECT_EQ(model.size(), 2U);
  EXPECT_EQ(model.id("b"), variable_id(1));
  EXPECT_EQ(model.at("a").cardinality(), 2U);
  EXPECT_EQ(model.factor_count(), 2U);
  EXPECT_EQ(model.factor_scope(0), (std::vector<variable_id>{variable_id(1), variable_id(0)}));
  EXPECT_EQ(model.factor(1).values(), (std::vector<double>{0.5, 0.0}));
  EXPECT_EQ(model, markov_network(model.variables(), model.factors()));
  EXPECT_THAT(error_of([&] { static_cast<void>(model.id("c")); }), HasSubstr("unknown variable 'c' (known: a, b)"));
}

TEST(markov_network_test, refuses_what_does_not_fit) {
  EXPECT_THAT(error_of([] { markov_network({a, a}, {}); }), HasSubstr("the variable 'a' is declared twice"));
  EXPECT_THAT(error_of([] {
                markov_network({a}, {factor_table({variable_id(3)}, {2}, {1, 1})});
              }),
              HasSubstr("factor 0 names variable 3, but the model has 1 variables"));
  EXPECT_THAT(error_of([] {
                markov_network({a, b}, {factor_table({variable_id(1)}, {2}, {1, 1})});
              }),
              HasSubstr("factor 0 gives 'b' 2 states, but it has 3"));
}

TEST(markov_network_test, a_factor_table_refuses_bad_values_and_shapes) {
  EXPECT_THAT(error_of([] { factor_table({variable_id(0)}, {2}, {1, 2, 3}); }), HasSubstr("needs 2 values, got 3"));
  EXPECT_THAT(error_of([] { factor_table({variable_id(0)}, {2}, {1, -1}); }), HasSubstr("value 1 is -1"));
  EXPECT_THAT(error_of([] { factor_table({variable_id(0)}, {2}, {1, std::nan("")}); }), HasSubstr("must be finite"));
  EXPECT_THAT(error_of([] { factor_table({variable_id(0)}, {2}, {1, INFINITY}); }), HasSubstr("must be finite"));
  EXPECT_THAT(error_of([] {
                factor_table({variable_id(0), variable_id(0)}, {2, 2}, {1, 1, 1, 1});
              }),
              HasSubstr("lists the variable 0 twice"));
  EXPECT_THAT(error_of([] { factor_table({variable_id(0)}, {0}, {}); }), HasSubstr("has no states"));
  EXPECT_THROW(factor_table({variable_id(0), variable_id(1)}, {std::size_t{1} << 20, std::size_t{1} << 20}, {}),
               table_too_large);
  EXPECT_EQ(factor_table().values(), std::vector<double>{1.0});
}

// The concept, both ways: what lacks factors is no model.
struct only_variables {
  const std::vector<variable>& variables() const;
  std::size_t size() const;
  variable_id id(std::string_view) const;
};
static_assert(GraphicalModel<markov_network> && GraphicalModel<bayesian_network>);
static_assert(!GraphicalModel<only_variables> && !GraphicalModel<int>);
static_assert(DirectedModel<bayesian_network> && !DirectedModel<markov_network>);
static_assert(model_kind<markov_network>() == "Markov network");

TEST(markov_network_test, a_bayesian_network_reads_as_its_tables) {
  const auto network = read_bif(std::string(PGM_NETWORKS_DIR) + "/asia.bif");
  ASSERT_EQ(network.factor_count(), network.size());
  for (std::size_t f = 0; f < network.factor_count(); ++f) {
    const variable_id node = index_at<variable_id>(f);
    const auto table = network.factor(f);
    auto scope = network.graph().parents(node);
    scope.push_back(node);
    EXPECT_EQ(table.scope(), scope);
    EXPECT_EQ(network.factor_scope(f), scope);
    EXPECT_TRUE(std::equal(table.values().begin(), table.values().end(), network.table(node).values().begin()));
  }
}

}  // namespace markov_network_test
}  // namespace pgm
