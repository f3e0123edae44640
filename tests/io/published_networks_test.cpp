// The published networks of the bnlearn repository, shipped in tests/data/networks (README.md
// there gives their source).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "pgm/inference/sampling.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/net.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/io/xmlbif.hpp"
#include "pgm/learn/fit.hpp"

namespace pgm::published_networks_tests {
namespace {

struct published {
  const char* file;
  std::size_t nodes;
  std::size_t values;  // every number in the tables
  std::size_t max_parents;
};

// ctest lists parameters through gtest's printer; a name reads better than raw bytes.
void PrintTo(const published& p, std::ostream* out) { *out << p.file; }

class published_network_test : public ::testing::TestWithParam<published> {
 protected:
  std::filesystem::path path() const { return std::filesystem::path(PGM_NETWORKS_DIR) / GetParam().file; }
};

TEST_P(published_network_test, reads_with_the_published_size) {
  const auto net = read_bif(path());
  EXPECT_EQ(net.size(), GetParam().nodes);
  std::size_t values = 0;
  std::size_t max_parents = 0;
  for (const auto& t : net.tables()) {
    values += t.size();
    max_parents = std::max(max_parents, t.parents().size());
  }
  EXPECT_EQ(values, GetParam().values);
  EXPECT_EQ(max_parents, GetParam().max_parents);
}

TEST_P(published_network_test, bif_and_json_round_trips_are_exact) {
  const auto net = read_bif(path());
  EXPECT_EQ(parse_bif(to_bif(net), "again.bif"), net);
  EXPECT_EQ(parse_model_json(to_json(net).dump(), "again.json").network(), net);
}

TEST_P(published_network_test, round_trips_through_every_format_and_across_them_are_exact) {
  const auto net = read_bif(path());
  EXPECT_EQ(parse_xmlbif(to_xmlbif(net), "again.xml"), net);
  EXPECT_EQ(parse_net(to_net(net), "again.net"), net);
  // BIF -> XMLBIF -> NET -> JSON -> BIF, each step reading what the previous one wrote.
  auto step = net;
  for (const auto* name : {"xmlbif", "net", "json", "bif"}) {
    const network_format format(name);
    step = parse_network(to_text(step, format), format, "step");
    EXPECT_EQ(step, net) << name_of(format);
  }
  EXPECT_EQ(to_bif(step), to_bif(net));
}

INSTANTIATE_TEST_SUITE_P(bnlearn_repository, published_network_test,
                         ::testing::Values(published{"sachs.bif", 11, 178 + 89, 3},
                                           published{"water.bif", 32, 13484, 5},
                                           published{"pathfinder.bif", 109, 97851, 5}),
                         [](const auto& param_info) {
                           return std::string(std::filesystem::path(param_info.param.file).stem());
                         });

TEST(published_network_fit_test, sachs_is_recovered_from_its_own_samples) {
  const auto file = std::filesystem::path(PGM_NETWORKS_DIR) / "sachs.bif";
  const auto truth = read_bif(file);
  const auto data = sample(truth, 500000, 2024);
  const auto fitted = fit(truth.structure(), data);
  for (const auto& table : truth.tables()) {
    const auto& estimate = fitted.table(table.child().name());
    const auto counts = count_node(truth.structure(), truth.id(table.child().name()), data);
    for (std::size_t u = 0; u < table.configurations(); ++u) {
      const auto m = counts.total(config_index(u));
      if (m < 2000) continue;  // rare configurations are checked by the property tests
      for (std::size_t x = 0; x < table.child_cardinality(); ++x) {
        const double p = table(state_index(static_cast<std::uint32_t>(x)), config_index(u));
        const double sd = std::sqrt(p * (1 - p) / static_cast<double>(m));
        EXPECT_NEAR(estimate(state_index(static_cast<std::uint32_t>(x)), config_index(u)), p, 5 * sd + 1e-9)
            << table.child().name() << " u=" << u;
      }
    }
  }
}

}  // namespace
}  // namespace pgm::published_networks_tests
