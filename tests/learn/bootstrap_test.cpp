#include "pgm/learn/bootstrap.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "pgm/inference/sampling.hpp"
#include "pgm/io/bif.hpp"

namespace pgm::bootstrap_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(bootstrap_test, l1_threshold_by_hand) {
  // F: 1/4 on [0, 0.2), 1/2 on [0.2, 0.9), 3/4 on [0.9, 1): widths 0.2, 0.7, 0.1, so the
  // weighted median of F is 1/2, and the smallest strength with F >= 1/2 is 0.2.
  EXPECT_DOUBLE_EQ(detail::l1_threshold({0.9, 0.0, 1.0, 0.2}), 0.2);
  // Mostly absent arcs: F = 2/3 on [0, 1); the 2/3 quantile is 0.
  EXPECT_DOUBLE_EQ(detail::l1_threshold({0, 0, 0, 0, 1, 1}), 0.0);
  EXPECT_DOUBLE_EQ(detail::l1_threshold({}), 0.0);
}

TEST(bootstrap_test, strengths_directions_and_the_averaged_network) {
  const auto net = read_bif(std::filesystem::path(PGM_NETWORKS_DIR) / "asia.bif");
  const auto data = sample(net, 3000, 8);
  const auto names = data.names();
  const auto hc = make_structure_learner("hc");
  const auto one = bootstrap_structure(data, names, hc, {.threads = 1}, {.replicates = 12, .seed = 3});
  const auto two = bootstrap_structure(data, names, hc, {.threads = 2}, {.replicates = 12, .seed = 3});
  ASSERT_EQ(one.arcs.size(), names.size() * (names.size() - 1));
  for (std::size_t k = 0; k < one.arcs.size(); ++k) {
    EXPECT_EQ(one.arcs[k].strength, two.arcs[k].strength);
    EXPECT_EQ(one.arcs[k].direction, two.arcs[k].direction);
  }
  EXPECT_EQ(one.averaged, two.averaged);
  auto find = [&](const std::string& a, const std::string& b) {
    for (const auto& arc : one.arcs) {
      if (arc.from == a && arc.to == b) return arc;
    }
    return arc_strength{};
  };
  // Strength is symmetric, directions add up to 1 where the pair was ever adjacent.
  for (const auto& arc : one.arcs) {
    const auto back = find(arc.to, arc.from);
    EXPECT_EQ(arc.strength, back.strength);
    if (arc.strength > 0) {
      EXPECT_DOUBLE_EQ(arc.direction + back.direction, 1.0);
    }
    EXPECT_EQ(arc.strength * 12, std::round(arc.strength * 12));
  }
  // smoke - bronc and either - xray are strong in asia: found in every resample.
  EXPECT_EQ(find("smoke", "bronc").strength, 1.0);
  EXPECT_EQ(find("either", "xray").strength, 1.0);
  // The averaged network is a DAG whose arcs pass the threshold.
  dag averaged(names);
  for (const auto& e : one.averaged) {
    averaged.add_edge(e.from, e.to);
    const auto arc = find(e.from, e.to);
    EXPECT_TRUE(arc.strength > one.threshold || arc.strength == 1.0);
    EXPECT_GE(arc.direction, 0.5);
  }
  EXPECT_GE(one.averaged.size(), 4u);
  // Another seed, other resamples.
  const auto other = bootstrap_structure(data, names, hc, {}, {.replicates = 12, .seed = 4});
  bool differs = false;
  for (std::size_t k = 0; k < one.arcs.size(); ++k) differs = differs || other.arcs[k].strength != one.arcs[k].strength;
  EXPECT_TRUE(differs);
  EXPECT_THAT([&] { static_cast<void>(bootstrap_structure(data, names, hc, {}, {.replicates = 0})); },
              ThrowsMessage<model_error>(HasSubstr("at least one replicate")));
  EXPECT_THAT([&] { static_cast<void>(bootstrap_structure(data, names, hc, {}, {.replicates = 2, .threshold = 2.0})); },
              ThrowsMessage<model_error>(HasSubstr("between 0 and 1, got 2")));
}

}  // namespace
}  // namespace pgm::bootstrap_tests
