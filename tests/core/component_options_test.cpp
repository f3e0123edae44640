#include "pgm/core/component_options.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/component_registry.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"

namespace pgm::component_options_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

using settings = std::vector<std::pair<std::string, std::string>>;

TEST(component_options_test, a_choice_is_a_name_and_its_settings) {
  EXPECT_EQ(parse_component_spec("bic", "score").name, "bic");
  EXPECT_TRUE(parse_component_spec("bic", "score").settings.empty());
  EXPECT_TRUE(parse_component_spec("bic[]", "score").settings.empty());
  const auto spec = parse_component_spec("  BP [ tol = 1e-9 , maxiter=100 ] ", "engine");
  EXPECT_EQ(spec.name, "BP");
  EXPECT_EQ(spec.settings, (settings{{"tol", "1e-9"}, {"maxiter", "100"}}));
  // A value may be a choice of its own, its commas its own.
  const auto nested =
      parse_component_spec("mmhc[test=g2[correction=yates,min_rows_per_cell=5], alpha=0.05]", "learner");
  EXPECT_EQ(nested.settings, (settings{{"test", "g2[correction=yates,min_rows_per_cell=5]"}, {"alpha", "0.05"}}));
  EXPECT_EQ(parse_component_spec("hc[start=hc[start=pc[alpha=0.1]]]", "learner").settings,
            (settings{{"start", "hc[start=pc[alpha=0.1]]"}}));
}

TEST(component_options_test, a_malformed_choice_says_where_and_what_was_expected) {
  const auto refused = [](const char* text, const char* what) {
    EXPECT_THAT([&] { static_cast<void>(parse_component_spec(text, "score")); },
                ThrowsMessage<model_error>(HasSubstr(what)))
        << text;
  };
  refused("", "expected a name at column 1");
  refused("[iss=1]", "expected a name at column 1");
  refused("bdeu[iss=1", "expected ']' at column 11");
  refused("bdeu[iss=1]x", "unexpected text after ']' at column 12");
  refused("bdeu[iss]", "expected KEY=VALUE at column 6");
  refused("bdeu[iss=1,,k=2]", "expected KEY=VALUE at column 12");
  refused("bdeu[=1]", "expected an option's name before '=' at column 6");
  refused("bdeu[iss=]", "expected a value for 'iss' at column 10");
  refused("bdeu[iss=1,iss=2]", "'iss' is set twice at column 12");
  refused("bdeu[a=[1]", "expected ']' at column 11");
  refused("bdeu[a[1]=2]", "expected KEY=VALUE at column 6");
  refused("mmhc[test=g2[k=1]]]", "unexpected text after ']' at column 19");
  refused("bd,eu", "unexpected ',' at column 3");
  refused("bdeu]", "unexpected ']' at column 5");
  EXPECT_THAT([] { static_cast<void>(parse_component_spec("x[", "score")); },
              ThrowsMessage<model_error>(HasSubstr("the score 'x[' is not NAME or NAME[KEY=VALUE,...]")));
}

std::vector<option_declaration> declared() {
  return {number_option("tol", 1e-9, "stop below this change").greater_than(0.0).less_than(1.0),
          count_option("maxiter", 100, "the most sweeps").at_least(1.0),
          flag_option("damped", false, "halve each update"),
          word_option("schedule", "parallel", {"parallel", "sequential"}, "the update order")};
}

TEST(component_options_test, values_start_at_their_declared_defaults_and_are_checked_when_set) {
  option_values values(declared());
  EXPECT_EQ(values.number("tol"), 1e-9);
  EXPECT_EQ(values.count("maxiter"), 100u);
  EXPECT_FALSE(values.flag("damped"));
  EXPECT_EQ(values.word("schedule"), "parallel");
  EXPECT_EQ(values.text(), "tol=1e-09,maxiter=100,damped=false,schedule=parallel");
  values.set("tol", "0.5", "engine", "bp");
  values.set("maxiter", "7", "engine", "bp");
  values.set("damped", "true", "engine", "bp");
  values.set("schedule", "sequential", "engine", "bp");
  EXPECT_EQ(values.text(), "tol=0.5,maxiter=7,damped=true,schedule=sequential");
  EXPECT_EQ(spec_text("bp", values), "bp[tol=0.5,maxiter=7,damped=true,schedule=sequential]");
  EXPECT_EQ(spec_text("bic", option_values{}), "bic");

  const auto refused = [&](const char* key, const char* value, const char* what) {
    EXPECT_THAT([&] { values.set(key, value, "engine", "bp"); }, ThrowsMessage<model_error>(HasSubstr(what)))
        << key << "=" << value;
  };
  refused("tol", "1", "option tol of the engine 'bp' must be a number > 0 and < 1, got '1'");
  refused("tol", "1,5", "got '1,5' (a comma is no decimal mark");
  refused("tol", "nan", "must be a number > 0 and < 1");
  refused("maxiter", "0", "option maxiter of the engine 'bp' must be a whole number >= 1, got '0'");
  refused("maxiter", "-3", "a whole number >= 1, got '-3'");
  refused("maxiter", "2.5", "a whole number >= 1");
  refused("damped", "yes", "option damped of the engine 'bp' must be true or false, got 'yes'");
  refused("schedule", "random", "option schedule of the engine 'bp' must be one of parallel, sequential, got 'random'");
  EXPECT_THAT(
      [&] { values.set("maxiters", "1", "engine", "bp"); },
      ThrowsMessage<unknown_name>(HasSubstr("unknown bp option 'maxiters'; did you mean 'maxiter'? (known: tol, "
                                            "maxiter, damped, schedule)")));
  EXPECT_EQ(values.text(), "tol=0.5,maxiter=7,damped=true,schedule=sequential");  // a refused value changes nothing
}

TEST(component_options_test, ranges_read_as_a_person_would_write_them) {
  EXPECT_EQ(number_option("a", 1, "").expected(), "a number");
  EXPECT_EQ(number_option("a", 1, "").at_least(0).expected(), "a number >= 0");
  EXPECT_EQ(number_option("a", 1, "").at_least(0).at_most(1).expected(), "a number from 0 to 1");
  EXPECT_EQ(number_option("a", 0.5, "").greater_than(0).at_most(1).expected(), "a number > 0 and <= 1");
  EXPECT_EQ(count_option("n", 3, "").expected(), "a whole number >= 0");
}

struct tool {
  std::string name;
  double tol;
};

TEST(component_options_test, a_registry_builds_from_a_choice_with_its_aliases) {
  component_registry<tool> tools("tool");
  tools.add("bp", {"loopy belief propagation", declared(), [](const component_choice& choice) {
                     return tool{choice.text(), choice.options.number("tol")};
                   }});
  tools.add("exact", {"junction tree", {}, [](const component_choice& choice) { return tool{choice.text(), 0.0}; }});
  tools.add_alias("loopy", "bp");
  EXPECT_EQ(tools.make("loopy[tol=0.25]").name, "bp[tol=0.25,maxiter=100,damped=false,schedule=parallel]");
  EXPECT_EQ(tools.make("bp").tol, 1e-9);
  EXPECT_EQ(tools.names(), (std::vector<std::string>{"bp", "exact"}));
  EXPECT_EQ(tools.accepted_names(), (std::vector<std::string>{"bp", "exact", "loopy"}));
  EXPECT_EQ(tools.listing(),
            (std::vector<std::string>{"bp[tol=1e-09,maxiter=100,damped=false,schedule=parallel]", "exact"}));
  EXPECT_THAT([&] { static_cast<void>(tools.make("exac")); },
              ThrowsMessage<unknown_name>(HasSubstr("unknown tool 'exac'; did you mean 'exact'? (known: bp, exact)")));
  EXPECT_THAT([&] { static_cast<void>(tools.make("exact[tol=1]")); },
              ThrowsMessage<model_error>(HasSubstr("the tool 'exact' takes no options, got 'tol'")));
  EXPECT_THAT([&] { tools.add("loopy", {}); }, ThrowsMessage<model_error>(HasSubstr("named 'loopy' is registered")));
  EXPECT_THAT([&] { tools.add_alias("exact", "bp"); },
              ThrowsMessage<model_error>(HasSubstr("named 'exact' is registered")));
}

component_registry<tool>& tool_registry() {
  static component_registry<tool> registry = [] {
    component_registry<tool> built("tool");
    built.add("bp", {"loopy belief propagation", declared(), [](const component_choice& choice) {
                       return tool{choice.text(), choice.options.number("tol")};
                     }});
    built.add("exact", {"junction tree", {}, [](const component_choice& choice) { return tool{choice.text(), 0.0}; }});
    return built;
  }();
  return registry;
}

TEST(component_options_test, a_component_option_chooses_from_another_registry) {
  const auto inner = component_option("inner", &tool_registry, "exact", "the tool inside");
  EXPECT_EQ(inner.expected(), "a tool, one of bp[tol=1e-09,maxiter=100,damped=false,schedule=parallel], exact");
  option_values values({inner});
  EXPECT_EQ(values.component("inner"), "exact");
  values.set("inner", "bp[tol=0.5]", "wrapper", "w");
  EXPECT_EQ(values.component("inner"), "bp[tol=0.5]");
  EXPECT_EQ(tool_registry().make(values.component("inner")).tol, 0.5);
  EXPECT_EQ(spec_text("w", values), "w[inner=bp[tol=0.5]]");
  // The inner registry's own message, after the option it was given to.
  EXPECT_THAT(
      [&] { values.set("inner", "bp[tol=2]", "wrapper", "w"); },
      ThrowsMessage<model_error>(HasSubstr(
          "option inner of the wrapper 'w': option tol of the tool 'bp' must be a number > 0 and < 1, got '2'")));
  EXPECT_THAT([&] { values.set("inner", "exac", "wrapper", "w"); },
              ThrowsMessage<model_error>(HasSubstr("unknown tool 'exac'; did you mean 'exact'?")));
  EXPECT_THAT([&] { static_cast<void>(values.word("inner")); },
              ThrowsMessage<model_error>(HasSubstr("did not declare as read")));
}

TEST(component_options_test, a_count_without_a_limit_reads_and_writes_unlimited) {
  const auto limit = count_option("max_parents", std::numeric_limits<std::size_t>::max(), "");
  EXPECT_EQ(limit.default_text, "unlimited");
  EXPECT_EQ(limit.expected(), "a whole number >= 0, or unlimited");
  option_values values({limit});
  EXPECT_EQ(values.count("max_parents"), std::numeric_limits<std::size_t>::max());
  values.set("max_parents", "3", "learner", "hc");
  EXPECT_EQ(values.text(), "max_parents=3");
  values.set("max_parents", "unlimited", "learner", "hc");
  EXPECT_EQ(values.text(), "max_parents=unlimited");
  // Only a count declared so takes "unlimited".
  EXPECT_FALSE(option_value_refusal(count_option("n", 3, ""), "unlimited").empty());
  EXPECT_TRUE(option_value_refusal(count_option("n", 3, ""), "4").empty());
}

TEST(component_options_test, a_setting_joins_a_choice_once) {
  const auto& tools = tool_registry();
  EXPECT_EQ(tools.with_setting("bp", "tol", "0.5"), "bp[tol=0.5]");
  EXPECT_EQ(tools.with_setting("bp[maxiter=3]", "tol", "0.5"), "bp[maxiter=3,tol=0.5]");
  EXPECT_THAT([&] { static_cast<void>(tools.with_setting("bp[tol=0.5]", "tol", "0.25")); },
              ThrowsMessage<model_error>(HasSubstr("sets tol, which 'bp[tol=0.5]' sets already; give it once")));
  EXPECT_THAT([&] { static_cast<void>(tools.with_setting("exact", "tol", "0.5")); },
              ThrowsMessage<model_error>(HasSubstr("sets the option tol, which the tool exact has not")));
  EXPECT_THAT([&] { static_cast<void>(tools.with_setting("bp", "tol", "5")); },
              ThrowsMessage<model_error>(HasSubstr("must be a number > 0 and < 1, got '5'")));
}

}  // namespace
}  // namespace pgm::component_options_tests
