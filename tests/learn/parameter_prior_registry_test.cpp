// Parameter priors by name (pgm/learn/parameter_prior_registry.hpp): each built-in one made from
// its text gives the pseudo-counts eq. 6 reads and writes the text that makes it again; a
// user's prior registered in one line is chosen by its text, estimates as its pseudo-counts
// say, and survives the statistics of a saved model by its name.

#include "pgm/learn/parameter_prior_registry.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pgm/core/component_options.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/csv_source.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/learn/estimate.hpp"
#include "pgm/pipeline/fit_pipeline.hpp"

namespace pgm::parameter_prior_registry_tests {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsSupersetOf;
using ::testing::ThrowsMessage;

const variable child("c", {"x", "y", "z"});
const std::vector<variable> parents{variable("p", {"a", "b"}), variable("q", {"a", "b"})};

TEST(parameter_prior_registry_test, each_built_in_prior_writes_the_text_that_makes_it_again) {
  EXPECT_THAT(parameter_priors().listing(), IsSupersetOf({"bdeu[ess=1]", "dirichlet[alpha=1]", "k2", "none"}));
  for (const auto& text : {"bdeu[ess=12]", "dirichlet[alpha=0.25]", "k2", "none"}) {
    const auto prior = make_parameter_prior(text);
    ASSERT_TRUE(prior.choice().has_value()) << text;
    EXPECT_EQ(prior.choice()->text(), text);
  }
  // Made without the registry, a built-in prior still knows its text.
  EXPECT_EQ(parameter_prior(bdeu_prior{3.5}).choice()->text(), "bdeu[ess=3.5]");
  EXPECT_EQ(parameter_prior().choice()->text(), "none");
}

TEST(parameter_prior_registry_test, the_built_in_priors_give_the_pseudo_counts_of_eq_6) {
  // 3 states × 4 parent configurations: BDeu spreads N' = 12 as 1 per cell.
  const auto cells_of = [](const std::string& text) {
    return make_parameter_prior(text).pseudo_counts(child, parents).spelled_out(12);
  };
  EXPECT_EQ(cells_of("bdeu[ess=12]"), std::vector<double>(12, 1.0));
  EXPECT_EQ(cells_of("dirichlet[alpha=2]"), std::vector<double>(12, 2.0));
  EXPECT_EQ(cells_of("k2"), std::vector<double>(12, 1.0));
  EXPECT_EQ(cells_of("none"), std::vector<double>(12, 0.0));
  EXPECT_THAT(
      [] { (void)make_parameter_prior("dirichlet[alpha=-1]"); },
      ThrowsMessage<model_error>(HasSubstr("option alpha of the prior 'dirichlet' must be a number >= 0, got '-1'")));
  EXPECT_THAT([] { (void)make_parameter_prior("flat"); },
              ThrowsMessage<unknown_name>(HasSubstr("unknown prior 'flat'")));
}

/// A user's prior with an option of its own: state x gets step·(x + 1) pseudo-counts.
struct ramp_prior {
  double step = 1.0;

  static std::vector<option_declaration> options() {
    return {number_option("step", 1.0, "pseudo-counts added per state").greater_than(0.0)};
  }
  explicit ramp_prior(const option_values& options) : step(options.number("step")) {}

  [[nodiscard]] static std::string_view name() { return "ramp"; }
  [[nodiscard]] std::vector<double> pseudo_counts(const variable& of, const std::vector<variable>& given) const {
    std::size_t configurations = 1;
    for (const auto& parent : given) configurations *= parent.cardinality();
    std::vector<double> alpha(of.cardinality() * configurations);
    for (std::size_t c = 0; c < alpha.size(); ++c) alpha[c] = step * static_cast<double>(c % of.cardinality() + 1);
    return alpha;
  }
};

const register_parameter_prior<ramp_prior> registered("ramp", "state x gets step·(x + 1)");

fit_result fit_text(const std::string& text, const network_structure& structure, const parameter_prior& prior) {
  csv_reader input(std::string_view(text), "data.csv");
  csv_source source(input);
  fit_request request;
  request.structure = structure;
  request.options.prior = prior;
  request.keep_statistics = true;
  return fit(source, request);
}

TEST(parameter_prior_registry_test, a_users_prior_is_chosen_by_its_text_and_kept_by_its_name) {
  const auto ramp = make_parameter_prior("ramp[step=2]");
  EXPECT_EQ(ramp.name(), "ramp");
  const network_structure structure({variable("a", {"0", "1"}), variable("b", {"0", "1", "2"})},
                                    parse_edge_list("a->b"));
  const auto fitted = fit_text("a,b\n0,0\n0,2\n1,1\n", structure, ramp);
  // b given a=0: counts (1, 0, 1), pseudo-counts (2, 4, 6): (3, 4, 7) / 14.
  EXPECT_THAT(std::vector<double>(fitted.network.table("b").column(config_index(0)).begin(),
                                  fitted.network.table("b").column(config_index(0)).end()),
              ElementsAre(3.0 / 14, 4.0 / 14, 7.0 / 14));

  const auto document = to_json(fitted.network, *fitted.statistics);
  const auto& written = document["statistics"]["families"][1]["prior"];
  EXPECT_EQ(written, nlohmann::json({{"kind", "ramp"}, {"step", 2.0}}));
  const auto read = parse_model_json(document.dump(), "m.json");
  ASSERT_TRUE(read.statistics.has_value());
  EXPECT_EQ(read.statistics->priors[1].choice()->text(), "ramp[step=2]");
  const auto again = estimate_network(structure, *read.statistics);
  EXPECT_EQ(again.table("b").values().size(), fitted.network.table("b").values().size());
  for (std::size_t i = 0; i < again.table("b").values().size(); ++i) {
    EXPECT_EQ(again.table("b").values()[i], fitted.network.table("b").values()[i]);
  }

  auto damaged = document;
  damaged["statistics"]["families"][1]["prior"]["step"] = 0.0;
  EXPECT_THAT([&] { (void)parse_model_json(damaged.dump(), "m.json"); },
              ThrowsMessage<data_error>(HasSubstr("/statistics/families/1/prior/step: the step must be a number > 0")));
  damaged["statistics"]["families"][1]["prior"] = {{"kind", "ramp"}, {"steep", 1.0}};
  EXPECT_THAT([&] { (void)parse_model_json(damaged.dump(), "m.json"); }, ThrowsMessage<data_error>(HasSubstr("steep")));
}

}  // namespace
}  // namespace pgm::parameter_prior_registry_tests
