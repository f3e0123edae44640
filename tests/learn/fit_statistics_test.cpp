// Updates (pgm/learn/fit_statistics.hpp, update() in pgm/pipeline/fit_pipeline.hpp): fitting D1
// and adding D2 equals fitting D1 ∪ D2 to the last bit, for every prior; the statistics survive
// every model file format; a decay weighs the old counts down.

#include "pgm/learn/fit_statistics.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "pgm/inference/sampling.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/csv_source.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/pipeline/fit_pipeline.hpp"
#include "pgm/testing/random_network.hpp"

namespace pgm::fit_statistics_tests {
namespace {

using ::testing::HasSubstr;
using testing::random_network;
using ::testing::ThrowsMessage;

std::string csv_of_rows(const dataset& data, bool header) {
  std::ostringstream out;
  write_csv(data, out);
  auto text = out.str();
  return header ? text : text.substr(text.find('\n') + 1);
}

/// Fits `text` under the network's structure, keeping the statistics.
fit_result fit_text(const std::string& text, const network_structure& structure, const fit_options& options,
                    missing_values missing = {}) {
  csv_reader input(std::string_view(text), "data.csv");
  csv_source source(input);
  fit_request request;
  request.structure = structure;
  request.options = options;
  request.missing = std::move(missing);
  request.keep_statistics = true;
  return fit(source, request);
}

fit_result update_text(const std::string& text, const network_structure& structure, const fit_statistics& statistics,
                       const update_request& request = {}) {
  csv_reader input(std::string_view(text), "new.csv");
  csv_source source(input);
  return update(source, structure, statistics, request);
}

std::vector<double> table_values(const cpt<double>& table) { return {table.values().begin(), table.values().end()}; }

void expect_same_estimates(const bayesian_network& a, const bayesian_network& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(table_values(a.tables()[i]), table_values(b.tables()[i])) << a.tables()[i].child().name();
  }
}

/// A user's prior (docs/extending.md): pseudo-counts that grow with the state index.
struct growing_pseudo_counts {
  [[nodiscard]] static std::string_view name() { return "growing"; }
  [[nodiscard]] std::vector<double> pseudo_counts(const variable& child, const std::vector<variable>& parents) const {
    std::size_t configurations = 1;
    for (const auto& p : parents) configurations *= p.cardinality();
    std::vector<double> alpha(child.cardinality() * configurations);
    for (std::size_t c = 0; c < alpha.size(); ++c) alpha[c] = 0.1 * static_cast<double>(c % child.cardinality() + 1);
    return alpha;
  }
};

/// Every prior pgm has, and a transferred one (eq. 8) on one node with a weight w given.
std::vector<fit_options> every_prior_kind(const bayesian_network& network) {
  std::vector<fit_options> all(6);
  all[1].prior = dirichlet_prior{0.7};
  all[2].prior = k2_prior{};
  all[3].prior = bdeu_prior{3.0};
  all[4].prior = growing_pseudo_counts{};
  const auto& last = network.tables().back();
  std::vector<double> flat(last.values().size(), 1.0 / static_cast<double>(last.child_cardinality()));
  all[5].prior = bdeu_prior{1.0};
  all[5].node_priors.emplace(last.child().name(),
                             weighted_prior{cpt<double>(last.child(), last.parents(), std::move(flat)), 20.0});
  return all;
}

TEST(fit_statistics, fitting_d1_then_adding_d2_equals_fitting_both_to_the_last_bit_for_every_prior) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto network = random_network(seed);
    const auto first = csv_of_rows(sample(network, 700, seed), true);
    const auto second = csv_of_rows(sample(network, 500, seed + 100), true);
    const auto both = first + csv_of_rows(sample(network, 500, seed + 100), false);
    for (const auto& options : every_prior_kind(network)) {
      const auto d1 = fit_text(first, network.structure(), options);
      ASSERT_TRUE(d1.statistics.has_value());
      expect_same_estimates(estimate_network(network.structure(), *d1.statistics), d1.network);
      const auto updated_model = update_text(second, network.structure(), *d1.statistics);
      const auto all = fit_text(both, network.structure(), options);
      expect_same_estimates(updated_model.network, all.network);
      EXPECT_EQ(updated_model.statistics->rows, 1200.0);
      EXPECT_EQ(updated_model.counts.rows, 500U);
    }
  }
}

TEST(fit_statistics, the_equality_holds_with_missing_values_counted_where_available) {
  const std::string first = "a,b,c\n0,1,x\nNA,1,y\n1,0,x\n1,NA,y\n";
  const std::string second = "a,b,c\n0,0,y\n1,1,NA\n0,1,x\n";
  const std::string both = first + "0,0,y\n1,1,NA\n0,1,x\n";
  const network_structure structure({variable("a", {"0", "1"}), variable("b", {"0", "1"}), variable("c", {"x", "y"})},
                                    parse_edge_list("a->b,b->c"));
  const missing_values available{{"NA"}, missing_policy::available};
  fit_options options;
  options.prior = k2_prior{};
  const auto d1 = fit_text(first, structure, options, available);
  update_request request;
  request.missing = available;
  expect_same_estimates(update_text(second, structure, *d1.statistics, request).network,
                        fit_text(both, structure, options, available).network);
}

TEST(fit_statistics, survive_the_json_model_file_to_the_last_bit) {
  const auto network = random_network(7);
  const auto text = csv_of_rows(sample(network, 300, 7), true);
  for (const auto& options : every_prior_kind(network)) {
    const auto fitted = fit_text(text, network.structure(), options);
    const auto built = to_json(fitted.network, *fitted.statistics).dump(2) + "\n";
    // The streamed writer writes the same text as the document built in memory.
    std::ostringstream streamed;
    write_model_json(streamed, fitted.network, &*fitted.statistics);
    EXPECT_EQ(streamed.str(), built);
    const auto document = parse_model_json(built, "model.json");
    ASSERT_TRUE(document.statistics.has_value());
    EXPECT_EQ(document.statistics->rows, 300.0);
    for (std::size_t i = 0; i < network.size(); ++i) {
      EXPECT_EQ(document.statistics->counts[i], fitted.statistics->counts[i]);
    }
    expect_same_estimates(estimate_network(document.structure, *document.statistics), fitted.network);
  }
  // A network written without statistics reads back without them.
  EXPECT_FALSE(parse_model_json(to_json(network).dump(), "plain.json").statistics.has_value());
}

// BIF, XMLBIF and NET keep them in a network-level property, base64 of the same JSON.
TEST(fit_statistics, survive_every_model_file_format_to_the_last_bit) {
  const auto network = random_network(8);
  const auto text = csv_of_rows(sample(network, 300, 8), true);
  const auto folder = std::filesystem::temp_directory_path() / "pgm_fit_statistics_formats";
  std::filesystem::create_directories(folder);
  for (const auto& options : every_prior_kind(network)) {
    const auto fitted = fit_text(text, network.structure(), options);
    for (const char* name : {"model.bif", "model.xml", "model.net"}) {
      SCOPED_TRACE(name);
      write_network(fitted.network, folder / name, {.statistics = &*fitted.statistics});
      const auto document = read_model(folder / name);
      ASSERT_TRUE(document.statistics.has_value());
      EXPECT_EQ(document.statistics->rows, 300.0);
      for (std::size_t i = 0; i < network.size(); ++i) {
        EXPECT_EQ(document.statistics->counts[i], fitted.statistics->counts[i]);
      }
      expect_same_estimates(estimate_network(document.structure, *document.statistics), fitted.network);
      write_network(fitted.network, folder / name);
      EXPECT_FALSE(read_model(folder / name).statistics.has_value());
    }
  }
  // Base64 of JSON that is not the statistics: refused with the JSON path, naming the property.
  const auto fitted = fit_text(text, network.structure(), {});
  write_network(fitted.network, folder / "model.bif", {.statistics = &*fitted.statistics});
  auto bif = pgm::read_file(folder / "model.bif");
  const auto begin = bif.find("pgm.statistics = ") + 17;
  bif.replace(begin, bif.find(' ', begin) - begin, "eyJyb3dzIjotMX0");  // {"rows":-1}
  std::ofstream(folder / "wrong.bif") << bif;
  EXPECT_THAT([&] { (void)read_model(folder / "wrong.bif"); },
              ThrowsMessage<data_error>(HasSubstr("(property pgm.statistics): /statistics")));
  std::filesystem::remove_all(folder);
}

TEST(fit_statistics, a_decay_weighs_the_old_counts_down_before_adding_the_new) {
  const network_structure structure({variable("a", {"0", "1"}), variable("b", {"0", "1"})}, parse_edge_list("a->b"));
  const auto old = fit_text("a,b\n0,0\n0,0\n0,1\n1,1\n", structure, {});
  update_request request;
  request.decay = 0.5;
  const auto next = update_text("a,b\n0,1\n", structure, *old.statistics, request);
  // b | a=0: old counts (2, 1) halved to (1, 0.5), plus the new (0, 1): (1, 1.5).
  EXPECT_EQ(next.statistics->counts[1].counts()[0], 1.0);
  EXPECT_EQ(next.statistics->counts[1].counts()[1], 1.5);
  EXPECT_EQ(next.network.tables()[1].values()[0], 1.0 / 2.5);
  EXPECT_EQ(next.statistics->rows, 3.0);
  for (const double decay : {0.0, -0.5, 1.5}) {
    request.decay = decay;
    EXPECT_THAT([&] { static_cast<void>(update_text("a,b\n0,1\n", structure, *old.statistics, request)); },
                ThrowsMessage<model_error>(HasSubstr("the decay must be in (0, 1]")));
  }
}

TEST(fit_statistics, new_rows_must_hold_the_models_states) {
  const network_structure structure({variable("a", {"0", "1"}), variable("b", {"0", "1"})}, parse_edge_list("a->b"));
  const auto old = fit_text("a,b\n0,0\n1,1\n", structure, {});
  EXPECT_THAT([&] { static_cast<void>(update_text("a,b\n2,0\n", structure, *old.statistics)); },
              ThrowsMessage<data_error>(HasSubstr("new.csv:2:1: column 'a': '2' is not a state of 'a'")));
}

TEST(fit_statistics, a_damaged_statistics_entry_is_refused_with_its_json_path) {
  const network_structure structure({variable("a", {"0", "1"}), variable("b", {"0", "1"})}, parse_edge_list("a->b"));
  const auto fitted = fit_text("a,b\n0,0\n1,1\n", structure, {});
  const auto document = to_json(fitted.network, *fitted.statistics);
  const auto refused = [&](auto damage, const std::string& message) {
    auto copy = document;
    damage(copy);
    EXPECT_THAT([&] { static_cast<void>(parse_model_json(copy.dump(), "m.json")); },
                ThrowsMessage<data_error>(HasSubstr(message)));
  };
  refused([](auto& d) { d["statistics"]["families"][1]["counts"][0] = {1.0}; },
          "m.json: /statistics/families/1/counts/0: expected 2 values, one per state of 'b'");
  refused([](auto& d) { d["statistics"]["families"][0]["counts"][0][1] = -1.0; },
          "/statistics/families/0/counts/0/1: expected a finite number >= 0");
  refused([](auto& d) { d["statistics"]["families"][0]["prior"] = {{"kind", "bdeux"}}; }, "unknown prior 'bdeux'");
  refused([](auto& d) { d["statistics"]["families"][0]["variable"] = "b"; }, "expected 'a'");
  refused([](auto& d) { d["statistics"]["families"].erase(1); }, "expected 2 families");
  refused([](auto& d) { d.erase("tables"); }, "statistics need the tables");
}

}  // namespace
}  // namespace pgm::fit_statistics_tests
