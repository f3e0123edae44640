// The optional Eigen adapter: a table seen as a matrix with one column per parent
// configuration, without a copy.

#include "pgm/adapters/eigen.hpp"

#include <gtest/gtest.h>

namespace pgm::eigen_tests {
namespace {

const variable on_top("onTop1", {"0", "1"});
const variable x_off("xOff1", {"l", "c", "r"});
const variable y_off("yOff1", {"l", "r"});

TEST(eigen_test, columns_are_the_distributions_of_the_parent_configurations) {
  // Columns for (l,l) (l,r) (c,l) (c,r) (r,l) (r,r).
  const cpt<double> t(on_top, {x_off, y_off}, {0.9, 0.1, 0.8, 0.2, 0.3, 0.7, 0.25, 0.75, 0.5, 0.5, 0.0, 1.0});
  const auto m = as_eigen(t);
  EXPECT_EQ(m.rows(), 2);
  EXPECT_EQ(m.cols(), 6);
  EXPECT_DOUBLE_EQ(m(1, 3), t.probability("1", {"c", "r"}));
  EXPECT_DOUBLE_EQ(m(0, 1), 0.8);
  EXPECT_TRUE(((m.colwise().sum().array() - 1.0).abs() < 1e-12).all());
  EXPECT_EQ(m.data(), t.values().data());  // a view, not a copy
}

TEST(eigen_test, float_tables_and_tables_without_parents) {
  const cpt<float> t(on_top, {}, {0.25F, 0.75F});
  const auto m = as_eigen(t);
  EXPECT_EQ(m.rows(), 2);
  EXPECT_EQ(m.cols(), 1);
  EXPECT_FLOAT_EQ(m(1, 0), 0.75F);
}

}  // namespace
}  // namespace pgm::eigen_tests
