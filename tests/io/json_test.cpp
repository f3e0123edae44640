#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

#include "pgm/io/cpt_csv.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/testing/random_network.hpp"

namespace pgm::json_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(json_model_test, network_round_trip_is_exact) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto net = testing::random_network(seed, {.nodes = 8, .max_parents = 3, .max_states = 5});
    const auto back = parse_model_json(to_json(net).dump(), "m.json");
    ASSERT_TRUE(back.tables);
    EXPECT_EQ(back.network(), net);
  }
}

TEST(json_model_test, the_streamed_writer_writes_what_the_document_dumps) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto net = testing::random_network(seed, {.nodes = 1 + seed % 9, .max_parents = seed % 4});
    std::ostringstream streamed;
    write_model_json(streamed, net);
    EXPECT_EQ(streamed.str(), to_json(net).dump(2) + "\n") << "seed " << seed;
  }
  // Tags, intervals, names that need escaping, and a network of no edges.
  const variable odd("a\"quoted\"name\\", {"s\"1", "ü"});
  const auto intervals = variable::intervals("x", {-1.5, 0.0, 1e-7, 2e300});
  const auto net =
      bayesian_network::from_tables({cpt<double>(odd, {}, {0.25, 0.75}), cpt<double>(intervals, {}, {0.1, 0.2, 0.7})});
  std::ostringstream streamed;
  write_model_json(streamed, net);
  EXPECT_EQ(streamed.str(), to_json(net).dump(2) + "\n");
}

TEST(json_model_test, a_name_that_is_not_utf8_is_refused_not_a_crash) {
  // A BIF or NET file may name states with any bytes; JSON holds only UTF-8.
  const auto network = bayesian_network::from_tables({cpt<double>(variable("A", {"a\x93", "b"}), {}, {0.5, 0.5})});
  EXPECT_THAT([&] { (void)to_json(network).dump(); },
              ThrowsMessage<model_error>(HasSubstr("the state of 'A' 'a\\x93' is not UTF-8 text")));
  std::ostringstream out;
  EXPECT_THROW(write_model_json(out, network), model_error);
}

TEST(json_model_test, structure_only_with_tags_and_edges) {
  const auto x = variable::intervals("xOff1", {-3, 0, 3}, {"x-offset", "cm", "cubeUp1"});
  const network_structure s({x, variable("onTop1", {"0", "1"})}, {{"xOff1", "onTop1"}});
  const auto back = parse_model_json(to_json(s).dump(2), "m.json");
  EXPECT_FALSE(back.tables);
  EXPECT_EQ(back.structure, s);
  EXPECT_THAT([&] { static_cast<void>(back.network()); }, ThrowsMessage<model_error>(HasSubstr("no tables")));
}

TEST(json_model_test, syntax_errors_have_line_and_column) {
  EXPECT_THAT([] { static_cast<void>(parse_model_json("{\n  \"format\": \"pgm-model\",\n  oops\n}", "m.json")); },
              ThrowsMessage<parse_error>(HasSubstr("m.json:3:3: invalid JSON")));
  // The parser's reason is kept with what it read (issue 28: only "'0,<U+000A> N'" was left).
  EXPECT_THAT([] { static_cast<void>(parse_model_json("{\"version\": 0,\n N", "m.json")); },
              ThrowsMessage<parse_error>(HasSubstr("m.json:2:2: invalid JSON: syntax error while parsing object key - "
                                                   "invalid literal; last read: '0,<U+000A> N'; expected string "
                                                   "literal")));
  EXPECT_THAT([] { static_cast<void>(parse_model_json("[1, ]", "m.json")); },
              ThrowsMessage<parse_error>(HasSubstr("m.json:1:5: invalid JSON: syntax error while parsing value - "
                                                   "unexpected ']'; expected '[', '{', or a literal")));
}

TEST(json_model_test, unknown_keys_are_errors_naming_the_nearest_known_one) {
  const auto model = [](const std::string& variable, const std::string& top) {
    return R"({"format":"pgm-model","version":1,"variables":[{"name":"a","states":["0","1"])" + variable + "}]" + top +
           "}";
  };
  EXPECT_NO_THROW(
      static_cast<void>(parse_model_json(model("", R"(,"metadata":{"success":"a=1","mine":2})"), "m.json")));
  EXPECT_THAT([&] { static_cast<void>(parse_model_json(model("", R"(,"egdes":[])"), "m.json")); },
              ThrowsMessage<data_error>(
                  HasSubstr("m.json: /egdes: unknown key 'egdes'; did you mean 'edges'? (the keys "
                            "here: format, version, kind, variables, edges, tables, statistics, metadata, "
                            "learned)")));
  EXPECT_THAT([&] { static_cast<void>(parse_model_json(model(R"(,"tags":{"units":"cm"})", ""), "m.json")); },
              ThrowsMessage<data_error>(HasSubstr("m.json: /variables/0/tags/units: unknown key 'units'; did you "
                                                  "mean 'unit'?")));
  EXPECT_THAT([&] { static_cast<void>(parse_model_json(model(R"(,"colour":"red")", ""), "m.json")); },
              ThrowsMessage<data_error>(HasSubstr("/variables/0/colour: unknown key 'colour' (the keys here: name, "
                                                  "states, edges, tags)")));
  EXPECT_THAT(
      [] {
        static_cast<void>(parse_discretization_json(
            R"({"format":"pgm-discretization","version":1,"variables":[],"bins":3})", "d.json"));
      },
      ThrowsMessage<data_error>(HasSubstr("d.json: /bins: unknown key 'bins'")));
}

TEST(json_model_test, content_errors_name_the_path) {
  EXPECT_THAT([] { static_cast<void>(parse_model_json(R"({"format":"other","version":1})", "m.json")); },
              ThrowsMessage<data_error>(HasSubstr("m.json: /format: expected \"pgm-model\"")));
  EXPECT_THAT(
      [] {
        static_cast<void>(parse_model_json(
            R"({"format":"pgm-model","version":1,"variables":[{"name":"a","states":[1]}]})", "m.json"));
      },
      ThrowsMessage<data_error>(HasSubstr("m.json: /variables/0/states/0: expected a string")));
  EXPECT_THAT(
      [] {
        static_cast<void>(
            parse_model_json(R"({"format":"pgm-model","version":1,"variables":[{"name":"a","states":["0"]},{"name":"b")"
                             R"(,"states":["0"]}],"edges":[["a","b"],["b","a"]]})",
                             "m.json"));
      },
      ThrowsMessage<data_error>(HasSubstr("/edges/1: adding this edge closes the cycle b -> a -> b")));
  EXPECT_THAT(
      [] {
        static_cast<void>(
            parse_model_json(R"({"format":"pgm-model","version":1,"variables":[{"name":"a","states":["0","1"]}])"
                             R"(,"tables":[{"variable":"a","parents":[],"values":[[0.5,0.6]]}]})",
                             "m.json"));
      },
      ThrowsMessage<data_error>(HasSubstr("/tables/0: the distribution of 'a' sums to 1.1")));
  EXPECT_THAT(
      [] {
        static_cast<void>(parse_model_json(
            R"({"format":"pgm-model","version":1,"variables":[{"name":"a","states":["0","1"]},{"name":"b")"
            R"(,"states":["0"]}],"edges":[],"tables":[{"variable":"a","parents":["b"])"
            R"(,"values":[[0.5,0.5]]},{"variable":"b","parents":[],"values":[[1]]}]})",
            "m.json"));
      },
      ThrowsMessage<data_error>(HasSubstr("/tables: the table of 'a' has 1 parents, the graph 0")));
}

TEST(discretization_json_test, round_trip_and_errors) {
  discretization d;
  d.emplace("x", variable::intervals("x", {0, 0.1, 0.30000000000000004}, {"q", "cm", ""}));
  const auto back = parse_discretization_json(to_json(d).dump(), "e.json");
  EXPECT_EQ(back, d);
  EXPECT_THAT(
      [] {
        static_cast<void>(parse_discretization_json(
            R"({"format":"pgm-discretization","version":1,"variables":[{"name":"x","states":["0"]}]})", "e.json"));
      },
      ThrowsMessage<data_error>(HasSubstr("/variables/0: a discretized variable needs interval edges")));
}

TEST(cpt_csv_test, round_trip) {
  const variable a("a", {"lo", "hi"});
  const variable b("b", {"x", "y", "z"});
  const cpt<double> t(b, {a}, {0.1, 0.2, 0.7, 1.0 / 3, 1.0 / 3, 1.0 / 3});
  std::ostringstream out;
  write_cpt_csv(t, out);
  EXPECT_THAT(out.str(), HasSubstr("a,b,probability\nlo,x,0.1\n"));
  EXPECT_EQ(parse_cpt_csv(out.str(), "t.csv", b, {a}), t);
  EXPECT_THAT([&] { static_cast<void>(parse_cpt_csv("a,b,probability\nlo,x,1\n", "t.csv", b, {a})); },
              ThrowsMessage<data_error>(HasSubstr("expected 6 rows, found 1")));
}

}  // namespace
}  // namespace pgm::json_tests
