#include "pgm/pipeline/fit_pipeline.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "pgm/inference/sampling.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/csv_source.hpp"
#include "pgm/testing/random_network.hpp"

namespace pgm::fit_pipeline_tests {
namespace {

using ::testing::HasSubstr;
using testing::random_network;
using ::testing::ThrowsMessage;

std::string csv_text(const dataset& data) {
  std::ostringstream out;
  write_csv(data, out);
  return out.str();
}

dataset parse_discrete(const std::string& text, missing_values missing = {}) {
  csv_options options;
  options.default_kind = column_kind::discrete;
  options.missing = std::move(missing);
  return parse_csv(text, "data.csv", options);
}

std::vector<named_edge> edges_of(const network_structure& structure) {
  std::vector<named_edge> edges;
  for (std::size_t i = 0; i < structure.size(); ++i) {
    const variable_id node = index_at<variable_id>(i);
    for (const auto& parent : structure.parent_variables(node))
      edges.push_back({parent.name(), structure.at(node).name()});
  }
  return edges;
}

void expect_same_tables(const bayesian_network& a, const bayesian_network& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const variable_id node = index_at<variable_id>(i);
    EXPECT_EQ(a.structure().at(node), b.structure().at(node));
    const auto values_a = a.table(node).values();
    const auto values_b = b.table(node).values();
    EXPECT_EQ(std::vector<double>(values_a.begin(), values_a.end()),
              std::vector<double>(values_b.begin(), values_b.end()))
        << a.structure().at(node).name();
  }
}

fit_result fit_csv(const std::string& text, const fit_request& request) {
  csv_reader input(std::string_view(text), "data.csv");
  csv_source source(input);
  return fit(source, request);
}

fit_result fit_data(const dataset& data, const fit_request& request) {
  dataset_source source(data);
  return fit(source, request);
}

// Edges over the columns: a streamed CSV file and the data set read from it give the network
// that fit(structure_from_data(...), data) gives, on random networks.
TEST(fit_pipeline, every_source_fits_what_the_data_set_fit_gives) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const auto network = random_network(seed);
    const auto text = csv_text(sample(network, 3000, seed));
    const auto data = parse_discrete(text);
    const auto edges = edges_of(network.structure());
    const auto expected = fit(structure_from_data(data, edges), data);
    fit_request request;
    request.structure = edges;
    const auto streamed = fit_csv(text, request);
    const auto in_memory = fit_data(data, request);
    expect_same_tables(streamed.network, expected);
    expect_same_tables(in_memory.network, expected);
    EXPECT_EQ(streamed.counts.rows, 3000U);
    EXPECT_EQ(in_memory.counts.rows, 3000U);
  }
}

// A model's structure: the columns take its states (including states no row has), so the
// tables equal those fitted from the sampled data set, which carries the model's variables.
TEST(fit_pipeline, a_models_structure_keeps_its_states_from_every_source) {
  for (std::uint64_t seed = 11; seed <= 14; ++seed) {
    const auto network = random_network(seed);
    const auto sampled = sample(network, 200, seed);  // few rows: some states unseen
    const auto text = csv_text(sampled);
    const auto expected = fit(network.structure(), sampled);
    fit_request request;
    request.structure = network.structure();
    expect_same_tables(fit_csv(text, request).network, expected);
    expect_same_tables(fit_data(parse_discrete(text), request).network, expected);
  }
}

TEST(fit_pipeline, missing_values_follow_the_policy_alike_in_every_source) {
  const std::string text = "a,b,c\n0,1,x\nNA,1,y\n1,0,x\n1,NA,y\n0,0,y\n1,1,x\n";
  fit_request request;
  request.structure = parse_edge_list("a->b,b->c");
  for (const auto policy : {missing_policy::drop, missing_policy::available}) {
    request.missing.policy = policy;
    const auto data = parse_discrete(text, {{"NA"}, missing_policy::available});
    const auto streamed = fit_csv(text, request);
    const auto in_memory = fit_data(data, request);
    expect_same_tables(streamed.network, in_memory.network);
    EXPECT_EQ(streamed.counts.rows, in_memory.counts.rows);
    EXPECT_EQ(streamed.counts.dropped, in_memory.counts.dropped);
    for (std::size_t i = 0; i < 3; ++i) {
      const auto a = streamed.counts.families[i].counts();
      const auto b = in_memory.counts.families[i].counts();
      EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end()));
    }
  }
  request.missing.policy = missing_policy::drop;
  const auto dropped = fit_csv(text, request);
  EXPECT_EQ(dropped.counts.rows, 4U);
  EXPECT_EQ(dropped.counts.dropped, 2U);
  request.missing.policy = missing_policy::error;
  const auto data = parse_discrete(text, {{"NA"}, missing_policy::available});
  EXPECT_THAT([&] { static_cast<void>(fit_data(data, request)); },
              ThrowsMessage<data_error>(HasSubstr("row 2: the value of 'a' is missing")));
}

TEST(fit_pipeline, raw_columns_are_binned_and_intervals_kept_alike_in_every_source) {
  const std::string text = "x,y\n0.1,a\n0.4,b\n0.6,a\n0.9,b\n1.5,b\n-2,a\n";
  csv_options options;
  options.kinds["x"] = column_kind::continuous;
  options.kinds["y"] = column_kind::discrete;
  const auto data = parse_csv(text, "data.csv", options);
  fit_request request;
  request.structure = parse_edge_list("x->y");
  request.bin.emplace("x", variable::intervals("x", {0.0, 0.5, 1.0}));
  const auto streamed = fit_csv(text, request);
  const auto in_memory = fit_data(data, request);
  expect_same_tables(streamed.network, in_memory.network);
  EXPECT_EQ(streamed.counts.outside.at("x"), 2U);
  EXPECT_EQ(in_memory.counts.outside.at("x"), 2U);
  EXPECT_EQ(streamed.network.structure().at("x").edges(), (std::vector<double>{0.0, 0.5, 1.0}));
}

// Codes of saved intervals (pgm discretize --method edges on new data): every interval is a state,
// also those no row falls in, whose column of the table is the empty-configuration rule's.
TEST(fit_pipeline, saved_intervals_give_every_state_also_those_no_row_has) {
  const std::string text = "x,y\n2,a\n3,b\n2,a\n4,b\n";
  fit_request request;
  request.structure = parse_edge_list("x->y");
  request.intervals.emplace("x", variable::intervals("x", {0.0, 1.0, 2.0, 3.0, 4.0, 5.0}));
  for (const auto& result : {fit_csv(text, request), fit_data(parse_discrete(text), request)}) {
    const auto& x = result.network.structure().at("x");
    EXPECT_EQ(x.states(), (std::vector<std::string>{"0", "1", "2", "3", "4"}));
    EXPECT_EQ(x.edges(), (std::vector<double>{0.0, 1.0, 2.0, 3.0, 4.0, 5.0}));
    const auto& marginal = result.network.table(node_of(result.network, "x")).values();
    EXPECT_EQ(std::vector<double>(marginal.begin(), marginal.end()), (std::vector<double>{0, 0, 0.5, 0.25, 0.25}));
    const auto& y = result.network.table(node_of(result.network, "y"));
    EXPECT_EQ(y(state_index(0), config_index(0)), 0.5);  // x = 0: no rows, uniform
    EXPECT_EQ(y(state_index(0), config_index(2)), 1.0);
  }
  request.intervals.clear();
  request.intervals.emplace("x", variable::intervals("x", {0.0, 1.0, 2.0}));  // 2 states: "3" is none of them
  EXPECT_THROW(static_cast<void>(fit_csv(text, request)), data_error);
}

// Data errors come before structure errors, as when the data are read first.
TEST(fit_pipeline, a_missing_column_is_reported_before_a_cycle) {
  const std::string text = "a,b\n0,1\n1,0\n";
  fit_request request;
  request.structure = parse_edge_list("a->b,b->c,c->a");
  EXPECT_THAT([&] { static_cast<void>(fit_csv(text, request)); }, ThrowsMessage<data_error>(HasSubstr("'c'")));
  request.structure = parse_edge_list("a->b,b->a");
  EXPECT_THROW(static_cast<void>(fit_csv(text, request)), not_a_dag);
  EXPECT_THROW(static_cast<void>(fit_data(parse_discrete(text), request)), not_a_dag);
}

TEST(fit_pipeline, a_value_that_is_not_a_models_state_is_refused_by_every_source) {
  const std::string text = "a,b\n0,1\n2,0\n";
  const network_structure structure({variable("a", {"0", "1"}), variable("b", {"0", "1"})}, parse_edge_list("a->b"));
  fit_request request;
  request.structure = structure;
  EXPECT_THROW(static_cast<void>(fit_csv(text, request)), data_error);
  EXPECT_THAT([&] { static_cast<void>(fit_data(parse_discrete(text), request)); },
              ThrowsMessage<data_error>(HasSubstr("'2', which is not a state of 'a'")));
}

// A transferred prior through the pipeline equals the prior added by hand and fitted; with
// w = 0 it is the MLE (eq. 7).
TEST(fit_pipeline, a_prior_network_transfers_as_add_transferred_priors_does) {
  const auto network = random_network(21);
  const auto sampled = sample(network, 500, 21);
  const auto text = csv_text(sampled);
  fit_request request;
  request.structure = network.structure();
  request.prior_network = &network;
  for (const auto& v : network.structure().variables()) {
    request.transfer.map += (request.transfer.map.empty() ? "" : ",") + v.name() + "=" + v.name();
  }
  request.transfer.strategy = "direct";
  request.transfer.weight = 5.0;
  request.transfer.success = "s1";
  const auto fitted = fit_csv(text, request);
  ASSERT_TRUE(fitted.transfer.has_value());
  EXPECT_EQ(fitted.transfer->nodes.size(), network.size());

  fit_options options;
  static_cast<void>(add_transferred_priors(options, network.structure(), sampled, network, request.transfer));
  expect_same_tables(fitted.network, fit(network.structure(), sampled, options));

  request.transfer.weight = 0.0;
  expect_same_tables(fit_csv(text, request).network, fit(network.structure(), sampled));
}

}  // namespace
}  // namespace pgm::fit_pipeline_tests
