// Sparse tables (issue 25): a family with more parent configurations than rows keeps only the
// configurations seen, and answers the others by the estimator's rule. Checked against the dense
// table of the same counts (to the bit), counts taken by brute force, and hand values.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <sstream>

#include "pgm/core/cpt.hpp"
#include "pgm/inference/inference_engine.hpp"
#include "pgm/inference/likelihood_weighting.hpp"
#include "pgm/inference/sampling.hpp"
#include "pgm/inference/variable_elimination.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/csv_counts.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/learn/estimate.hpp"
#include "pgm/learn/fit.hpp"
#include "pgm/learn/score_registry.hpp"

namespace pgm::sparse_table_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

std::vector<variable> binary_parents(std::size_t n) {
  std::vector<variable> parents;
  for (std::size_t i = 0; i < n; ++i) parents.emplace_back("p" + std::to_string(i), std::vector<std::string>{"0", "1"});
  return parents;
}

const variable child("y", {"a", "b", "c"});

// rows × (parents + 1) random codes; the child depends on the first parent. In the first
// `quiet_rows` rows every parent but the first is 0.
dataset random_data(std::size_t parents, std::size_t rows, std::uint64_t seed, std::size_t quiet_rows = 0) {
  std::mt19937_64 random(seed);
  std::vector<std::vector<unsigned>> codes(parents + 1, std::vector<unsigned>(rows));
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t p = 0; p < parents; ++p) {
      codes[p + 1][r] = p > 0 && r < quiet_rows ? 0 : static_cast<unsigned>(random() % 2);
    }
    codes[0][r] = static_cast<unsigned>((codes[1][r] + random() % 2) % 3);
  }
  dataset data;
  data.add(discrete_column(child, codes[0]));
  const auto ps = binary_parents(parents);
  for (std::size_t p = 0; p < parents; ++p) data.add(discrete_column(ps[p], codes[p + 1]));
  return data;
}

count_table count_all(const dataset& data, std::size_t parents) {
  std::vector<std::string> names;
  for (std::size_t p = 0; p < parents; ++p) names.push_back("p" + std::to_string(p));
  return count_family(data, "y", names);
}

TEST(sparse_table_test, a_cpt_stored_sparse_answers_every_configuration_and_densifies) {
  const variable a("a", {"0", "1", "2"});
  const variable y("y", {"n", "p"});
  const cpt<double> sparse(y, {a}, sparse_columns<double>{{1}, {0.25, 0.75}, {0.5, 0.5}});
  EXPECT_TRUE(sparse.is_sparse());
  EXPECT_THAT(sparse.column(config_index(1)), ElementsAre(0.25, 0.75));
  EXPECT_THAT(sparse.column(config_index(2)), ElementsAre(0.5, 0.5));
  EXPECT_EQ(sparse.probability("p", {"1"}), 0.75);
  EXPECT_EQ(sparse.dense(), cpt<double>(y, {a}, {0.5, 0.5, 0.25, 0.75, 0.5, 0.5}));
  EXPECT_THAT([&] { static_cast<void>(sparse.values()); },
              ThrowsMessage<table_too_large>(HasSubstr("the table of 'y' is stored sparse (1 of 3")));
}

TEST(sparse_table_test, a_sparse_cpt_is_validated_as_a_dense_one) {
  const variable a("a", {"0", "1", "2"});
  const variable y("y", {"n", "p"});
  auto make = [&](sparse_columns<double> columns) { return cpt<double>(y, {a}, std::move(columns)); };
  EXPECT_THAT(
      [&] {
        make({{3}, {0.5, 0.5}, {0.5, 0.5}});
      },
      ThrowsMessage<model_error>(HasSubstr("stores the configuration 3, out of range")));
  EXPECT_THAT(
      [&] {
        make({{2, 1}, {0.5, 0.5, 0.5, 0.5}, {0.5, 0.5}});
      },
      ThrowsMessage<model_error>(HasSubstr("out of ascending order")));
  EXPECT_THAT(
      [&] {
        make({{1}, {0.5, 0.6}, {0.5, 0.5}});
      },
      ThrowsMessage<model_error>(HasSubstr("the distribution of 'y' given a=1 sums to 1.1")));
  EXPECT_THAT(
      [&] {
        make({{1}, {0.5, 0.5}, {0.2, 0.2}});
      },
      ThrowsMessage<model_error>(HasSubstr("given any configuration not stored sums to 0.4")));
  EXPECT_THAT([&] { make({{1}, {0.5, 0.5}, {1.0}}); }, ThrowsMessage<model_error>(HasSubstr("needs 2 values")));
}

TEST(sparse_table_test, counts_past_the_dense_limit_are_kept_sparse_and_equal_brute_force_counts) {
  // 26 binary parents: 2^26 configurations × 3 states, four times pgm's limit of a dense table.
  const auto data = random_data(26, 5000, 7);
  const auto counts = count_all(data, 26);
  ASSERT_TRUE(counts.is_sparse());
  std::map<std::size_t, std::vector<std::uint64_t>> expected;
  for (std::size_t r = 0; r < data.rows(); ++r) {
    std::size_t u = 0;
    for (std::size_t p = 0; p < 26; ++p) u = 2 * u + data.discrete("p" + std::to_string(p)).code(r);
    auto& column = expected.try_emplace(u, 3, 0).first->second;
    ++column[data.discrete("y").code(r)];
  }
  ASSERT_EQ(counts.stored_configurations().size(), expected.size());
  std::size_t i = 0;
  for (const auto& [u, column] : expected) {
    EXPECT_EQ(counts.stored_configurations()[i], u);
    EXPECT_THAT(counts.stored_column(i++), ::testing::ElementsAreArray(column));
  }
  EXPECT_EQ(counts.total(), 5000u);
  EXPECT_THAT(counts.column(config_index(1)), ElementsAre(0u, 0u, 0u));  // not among 5000 of 2^26
  EXPECT_THAT([&] { static_cast<void>(counts.counts()); },
              ThrowsMessage<table_too_large>(HasSubstr("the counts of 'y' are kept sparse")));
}

TEST(sparse_table_test, scores_of_a_sparse_family_sum_over_the_configurations_seen) {
  // 40 binary parents: 2^40 configurations, of which 300 rows see at most 300. A score that
  // visited every configuration would take hours (issue 49); those not seen add nothing.
  const auto data = random_data(40, 300, 11);
  const auto counts = count_all(data, 40);
  ASSERT_TRUE(counts.is_sparse());
  double loglik = 0.0, bdeu = 0.0;
  const double alpha = 2.0 / (3.0 * std::pow(2.0, 40));  // iss 2 over 3 × 2^40 cells
  for (std::size_t i = 0; i < counts.stored_configurations().size(); ++i) {
    const auto column = counts.stored_column(i);
    double n = 0;
    for (auto m : column) n += static_cast<double>(m);
    bdeu += std::lgamma(3 * alpha) - std::lgamma(3 * alpha + n);
    for (auto m : column) {
      if (m == 0) continue;
      loglik += static_cast<double>(m) * std::log(static_cast<double>(m) / n);
      bdeu += std::lgamma(alpha + static_cast<double>(m)) - std::lgamma(alpha);
    }
  }
  EXPECT_NEAR(make_score("loglik")(counts), loglik, 1e-9 * std::abs(loglik));
  EXPECT_NEAR(make_score("bdeu[iss=2]")(counts), bdeu, 1e-9 * std::abs(bdeu));
  const double parameters = 2.0 * std::pow(2.0, 40);
  EXPECT_NEAR(make_score("bic")(counts), loglik - std::log(300.0) / 2 * parameters, 1e-3);
}

TEST(sparse_table_test, sparse_counts_add_up_as_dense_ones_do) {
  const auto data = random_data(26, 3000, 11);
  std::vector<std::string> names;
  for (std::size_t p = 0; p < 26; ++p) names.push_back("p" + std::to_string(p));
  auto first = count_family(data, "y", names, {}, {0, 1000});
  first += count_family(data, "y", names, {}, {1000, 3000});
  EXPECT_EQ(first, count_family(data, "y", names));
}

TEST(sparse_table_test, a_sparse_table_holds_no_more_values_than_a_dense_one_may) {
  // A child of 5,000 states under a parent of 5,000: every row its own configuration, 2.5·10^7
  // values even stored sparse.
  std::vector<std::string> states;
  for (int i = 0; i < 5000; ++i) states.push_back(std::to_string(i));
  count_table counts(variable("y", states), {variable("x", states)});
  ASSERT_TRUE(counts.is_sparse());
  std::vector<count_table::cell> cells;
  for (std::size_t i = 0; i < 5000; ++i) cells.push_back({.configuration = i, .state = i, .count = 1});
  EXPECT_THAT([&] { counts.add(cells); },
              ThrowsMessage<table_too_large>(HasSubstr("the table of 'y' would have 25000000 cells (5000 states × "
                                                       "5000 parent configurations), more than pgm's limit")));
}

// Families of 2^17 configurations (under the dense limit, so both forms exist) from fewer rows.
TEST(sparse_table_test, estimates_from_few_rows_are_sparse_and_equal_the_dense_estimate_to_the_bit) {
  const auto data = random_data(17, 2000, 3);
  const auto counts = count_all(data, 17);
  ASSERT_FALSE(counts.is_sparse());
  const estimate_options dense{.sparse = false};
  for (const parameter_prior& prior :
       std::vector<parameter_prior>{no_prior{}, k2_prior{}, dirichlet_prior{0.5}, bdeu_prior{10.0}}) {
    const auto sparse = estimate(counts, prior);
    ASSERT_TRUE(sparse.is_sparse());
    EXPECT_LE(sparse.stored_configurations().size(), 2000u);
    EXPECT_EQ(sparse.dense(), estimate(counts, prior, dense));
  }
}

TEST(sparse_table_test, estimates_from_sparse_counts_follow_the_rule_by_hand) {
  count_table counts(child, binary_parents(26));
  ASSERT_TRUE(counts.is_sparse());
  counts.add({{.configuration = 5, .state = 0, .count = 3}, {.configuration = 5, .state = 2, .count = 1}});
  const auto mle = estimate_mle(counts);
  EXPECT_THAT(mle.column(config_index(5)), ElementsAre(0.75, 0.0, 0.25));
  EXPECT_THAT(mle.rest(), ElementsAre(1.0 / 3, 1.0 / 3, 1.0 / 3));
  const auto k2 = estimate(counts, k2_prior{});
  EXPECT_THAT(k2.column(config_index(5)), ElementsAre(4.0 / 7, 1.0 / 7, 2.0 / 7));
  EXPECT_THAT(k2.column(config_index(6)), ElementsAre(1.0 / 3, 1.0 / 3, 1.0 / 3));
  EXPECT_THAT([&] { static_cast<void>(estimate_mle(counts, {.empty = empty_configuration::fail})); },
              ThrowsMessage<data_error>(HasSubstr("no data for 'y' given p0=0")));
  EXPECT_THAT([&] { static_cast<void>(estimate(counts, pseudo_counts_prior{{1.0}})); },
              ThrowsMessage<table_too_large>(HasSubstr("the prior 'pseudo-counts' gives a pseudo-count")));
}

TEST(sparse_table_test, eq8_with_a_sparse_prior_table) {
  count_table counts(child, binary_parents(26));
  counts.add({{.configuration = 5, .state = 0, .count = 3}, {.configuration = 5, .state = 2, .count = 1}});
  const cpt<double> f(child, binary_parents(26),
                      sparse_columns<double>{{5, 9}, {0.5, 0.25, 0.25, 0.2, 0.2, 0.6}, {0.1, 0.1, 0.8}});
  const auto theta = estimate(counts, weighted_prior{f, 2.0});
  // (w·f + M) / (w + M[u]) where there are rows, f itself elsewhere.
  EXPECT_THAT(theta.column(config_index(5)), ElementsAre((1.0 + 3) / 6, 0.5 / 6, (0.5 + 1) / 6));
  EXPECT_THAT(theta.column(config_index(9)), ElementsAre(0.2, 0.2, 0.6));
  EXPECT_THAT(theta.column(config_index(7)), ElementsAre(0.1, 0.1, 0.8));
  // w = 0 is MLE.
  EXPECT_THAT(estimate(counts, weighted_prior{f, 0.0}).column(config_index(5)),
              ::testing::ElementsAreArray(estimate_mle(counts).column(config_index(5))));
  EXPECT_THAT(estimate(counts, weighted_prior{f, 0.0}).column(config_index(9)), ElementsAre(1.0 / 3, 1.0 / 3, 1.0 / 3));
}

// y with every parent given.
network_structure star(std::size_t parents) {
  std::vector<variable> variables{child};
  std::vector<named_edge> edges;
  for (const auto& p : binary_parents(parents)) {
    variables.push_back(p);
    edges.push_back({p.name(), "y"});
  }
  return network_structure(variables, edges);
}

// P(y = state | evidence) by likelihood weighting.
double lw_probability(const bayesian_network& network, const evidence& observed, std::size_t state,
                      std::size_t samples) {
  likelihood_weighting engine(network, {.samples = samples, .seed = 9});
  set_evidence(engine, observed);
  return marginal(engine, "y").table.values()[state];
}

// A network y ← p0..p16 fitted from 2000 rows: y's table sparse, the parents' dense.
bayesian_network sparse_network() { return fit(star(17), random_data(17, 2000, 5)); }

TEST(sparse_table_test, sampling_reads_a_sparse_table_as_it_is_and_equals_the_dense_network) {
  const auto network = sparse_network();
  ASSERT_TRUE(network.table("y").is_sparse());
  const auto dense = network.dense("the test");
  ASSERT_FALSE(dense.table("y").is_sparse());
  EXPECT_EQ(sample(network, 500, 42).discrete("y").codes(), sample(dense, 500, 42).discrete("y").codes());
  const evidence observed{{"p0", "1"}, {"p3", "0"}};
  EXPECT_EQ(lw_probability(network, observed, 0, 20000), lw_probability(dense, observed, 0, 20000));
  // Exact inference makes the table dense (it is within the limit) and agrees.
  EXPECT_EQ(query(network, {"y"}, observed).table.values()[2], query(dense, {"y"}, observed).table.values()[2]);
}

TEST(sparse_table_test, evidence_reduces_a_family_past_the_dense_limit_before_anything_is_dense) {
  // y ← p0..p23: 3·2^24 cells dense, past the limit; fitted from 2000 rows it is stored sparse.
  const auto network = fit(star(24), random_data(24, 2000, 5));
  const auto& table = network.table("y");
  ASSERT_TRUE(table.is_sparse());
  ASSERT_GT(table.size(), max_table_cells);
  // Every parent observed: P(y | u) is the column of u, stored or the rest.
  evidence all;
  std::vector<std::size_t> codes(24);
  for (std::size_t k = 0; k < 24; ++k) {
    codes[k] = (k * 7 + 3) % 2;
    all.emplace("p" + std::to_string(k), std::to_string(codes[k]));
  }
  const auto column = table.column(config_index(table.parent_radix().encode(codes)));
  const auto exact = query(network, {"y"}, all);
  for (std::size_t x = 0; x < 3; ++x) EXPECT_NEAR(exact.table.values()[x], column[x], 1e-15);
  // Two parents free: Σ over them of P(p22) P(p23) P(y | u), by hand.
  auto some = all;
  some.erase("p22");
  some.erase("p23");
  std::vector<double> expected(3, 0.0);
  for (std::size_t a = 0; a < 2; ++a) {
    for (std::size_t b = 0; b < 2; ++b) {
      codes[22] = a;
      codes[23] = b;
      const double weight = network.table("p22").values()[a] * network.table("p23").values()[b];
      const auto c = table.column(config_index(table.parent_radix().encode(codes)));
      for (std::size_t x = 0; x < 3; ++x) expected[x] += weight * c[x];
    }
  }
  const auto partial = query(network, {"y"}, some);
  for (std::size_t x = 0; x < 3; ++x) EXPECT_NEAR(partial.table.values()[x], expected[x], 1e-15);
  // With nothing observed the family stays whole: refused, saying what would make it fit.
  EXPECT_THAT([&] { static_cast<void>(query(network, {"y"}, {})); },
              ThrowsMessage<table_too_large>(HasSubstr("the table of 'y' with the evidence entered still has 50331648 "
                                                       "cells, more than pgm's limit of 16777216")));
  // A parent's posterior given y: y's table is reduced by y's state, then the parents are summed.
  const auto parent = query(network, {"p0"},
                            {{"y", "a"},
                             {"p1", "0"},
                             {"p2", "1"},
                             {"p3", "0"},
                             {"p4", "0"},
                             {"p5", "0"},
                             {"p6", "0"},
                             {"p7", "0"},
                             {"p8", "0"},
                             {"p9", "0"}});
  EXPECT_NEAR(parent.table.values()[0] + parent.table.values()[1], 1.0, 1e-15);
}

TEST(sparse_table_test, json_keeps_a_sparse_table_sparse_and_bif_writes_it_dense) {
  const auto network = sparse_network();
  const auto json = to_json(network);
  std::ostringstream streamed;
  write_model_json(streamed, network);
  EXPECT_EQ(streamed.str(), json.dump(2) + "\n");
  const auto read = parse_model_json(json.dump(), "m.json").network();
  EXPECT_TRUE(read.table("y").is_sparse());
  EXPECT_EQ(read, network);
  EXPECT_EQ(to_bif(network), to_bif(network.dense("the test")));
}

TEST(sparse_table_test, a_sparse_table_in_json_is_checked_with_its_json_path) {
  auto model = [](const std::string& y) {
    return R"({"format":"pgm-model","version":1,"variables":[{"name":"a","states":["0","1","2"]},)"
           R"({"name":"y","states":["n","p"]}],"edges":[["a","y"]],"tables":[)"
           R"({"variable":"a","parents":[],"values":[[0.2,0.3,0.5]]},{"variable":"y","parents":["a"],)" +
           y + "}]}";
  };
  const auto read =
      parse_model_json(model(R"("given":[["2"],["0"]],"values":[[0.25,0.75],[1,0]],"rest":[0.5,0.5])"), "m.json")
          .network();
  EXPECT_THAT(read.table("y").stored_configurations(), ElementsAre(0u, 2u));
  EXPECT_THAT(read.table("y").column(config_index(0)), ElementsAre(1.0, 0.0));
  EXPECT_THAT(read.table("y").column(config_index(1)), ElementsAre(0.5, 0.5));
  auto message = [&](const std::string& y) {
    try {
      static_cast<void>(parse_model_json(model(y), "m.json"));
    } catch (const pgm::error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(message(R"("given":[["3"]],"values":[[0.5,0.5]],"rest":[0.5,0.5])"),
              HasSubstr("/tables/1/given/0/0: '3' is not a state of 'a'"));
  EXPECT_THAT(message(R"("given":[["1"],["1"]],"values":[[0.5,0.5],[0.5,0.5]],"rest":[0.5,0.5])"),
              HasSubstr("/tables/1/given/1: this configuration is given twice"));
  EXPECT_THAT(message(R"("given":[["1"]],"values":[[0.5,0.5],[0.5,0.5]],"rest":[0.5,0.5])"),
              HasSubstr("/tables/1/values: expected one column per configuration in \"given\" (1), got 2"));
  EXPECT_THAT(message(R"("given":[["1"]],"values":[[1]],"rest":[0.5,0.5])"),
              HasSubstr("/tables/1/values/0: expected 2 probabilities, one per state of 'y'"));
  EXPECT_THAT(message(R"("given":[["1"]],"values":[[0.5,0.5]],"rest":[0.5,0.6])"),
              HasSubstr("given any configuration not stored sums to 1.1, not 1"));
  EXPECT_THAT(message(R"("given":[["1"]],"values":[[0.5,0.5]])"), HasSubstr("/tables/1: the key 'rest' is missing"));
}

TEST(sparse_table_test, a_format_without_a_sparse_form_refuses_a_table_past_the_limit) {
  count_table counts(child, binary_parents(26));
  counts.add({{.configuration = 5, .state = 0, .count = 3}});
  std::vector<cpt<double>> tables{estimate_mle(counts)};
  for (const auto& p : binary_parents(26)) tables.emplace_back(p, std::vector<variable>{});
  const bayesian_network network(star(26), tables);
  EXPECT_THAT([&] { static_cast<void>(to_bif(network)); },
              ThrowsMessage<table_too_large>(HasSubstr("writing BIF, which has no sparse form (pgm's JSON model has), "
                                                       "needs every table dense, and the table of 'y'")));
  EXPECT_THAT([&] { static_cast<void>(query(network, {"y"})); },
              ThrowsMessage<table_too_large>(HasSubstr("use the sampling engines (lw, gibbs)")));
  // Likelihood weighting answers: P(y) = 1/3 each but in one configuration of 2^26.
  EXPECT_NEAR(lw_probability(network, {}, 0, 3000), 1.0 / 3, 0.05);
  EXPECT_EQ(parse_model_json(to_json(network).dump(), "m.json").network(), network);
}

// count_csv counts a family past the limit as rows, merged over chunks and threads (a family
// starts dense while its parents show one label each and turns sparse when they show two),
// equal to counting the data set.
TEST(sparse_table_test, counting_csv_equals_counting_the_data_set) {
  const auto data = random_data(26, 3000, 13, 1500);
  std::ostringstream out;
  write_csv(data, out);
  const auto text = out.str();
  std::vector<std::string> parents;
  for (std::size_t p = 0; p < 26; ++p) parents.push_back("p" + std::to_string(p));
  const auto expected = count_family(parse_csv(text, "d.csv", {.default_kind = column_kind::discrete}), "y", parents);
  for (const std::size_t chunk : {std::size_t{0}, std::size_t{300}}) {
    family_count_request request;
    request.columns = parents;
    request.columns.push_back("y");
    request.families.push_back({"y", parents});
    request.threads = 2;
    request.chunk_bytes = chunk;
    request.window_bytes = chunk * 4;
    csv_reader input(text, "d.csv");  // reads `text` in place
    const auto counted = count_csv(input, request);
    ASSERT_TRUE(counted.families[0].is_sparse());
    EXPECT_EQ(counted.families[0].stored_configurations().size(), expected.stored_configurations().size());
    EXPECT_EQ(counted.families[0], expected);
  }
}

}  // namespace
}  // namespace pgm::sparse_table_tests
