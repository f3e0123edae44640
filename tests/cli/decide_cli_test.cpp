// `pgm predict`, `pgm prevent` and `pgm decide` as a user meets them: help, the printed
// prediction, explanation and suggestion, the move of highest expected utility, an influence
// diagram's policies, and each kind of bad input ending in one line and exit code 1.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "pgm/io/network_file.hpp"
#include "support/program_test.hpp"

namespace pgm::decide_cli_tests {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

class decide_cli_test : public pgm::testing::program_test {
 protected:
  void SetUp() override {
    program_test::SetUp();
    const auto x = variable::intervals("xOff1", {-3, -0.4, 0.4, 3}, {"x-offset", "cm", "cubeUp1"});
    const auto y = variable::intervals("yOff1", {-3, -0.4, 0.4, 3}, {"y-offset", "cm", "cubeUp1"});
    const variable colour("colour", {"Red", "Blue"});
    const variable on_top("onTop1", {"0", "1"});
    const double p[] = {0.1, 0.3, 0.1, 0.6, 0.95, 0.5, 0.1, 0.2, 0.1};
    std::vector<double> values;
    for (double v : p) {
      values.push_back(1 - v);
      values.push_back(v);
    }
    const double third = 1.0 / 3.0;
    const auto net = bayesian_network::from_tables(
        {cpt<double>(x, {}, {third, third, third}), cpt<double>(y, {}, {third, third, third}),
         cpt<double>(colour, {}, {0.5, 0.5}), cpt<double>(on_top, {x, y}, values)});
    write_network(net, model());
    write_network(net, dir_ / "model.bif");
  }
  fs::path model() const { return dir_ / "model.json"; }

  void expect_error(const std::string& arguments, const std::string& message) const {
    const auto r = run(arguments);
    EXPECT_EQ(r.code, 1) << arguments;
    EXPECT_THAT(r.err, HasSubstr(message)) << arguments;
  }
};

TEST_F(decide_cli_test, help) {
  for (const std::string command : {"predict", "prevent"}) {
    const auto r = run(command + " --help");
    EXPECT_EQ(r.code, 0);
    EXPECT_THAT(r.out, HasSubstr("--assign"));
  }
}

TEST_F(decide_cli_test, predict_prints_the_probability) {
  const auto r = run("predict --model " + model().string() + " --assign 'xOff1=0.3,yOff1=-1.2,colour=Red'");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("success: onTop1=1"));
  EXPECT_THAT(r.out, HasSubstr("xOff1 = 0.3 cm -> state 1 [-0.4, 0.4) cm"));
  EXPECT_THAT(r.out, HasSubstr("predicted success probability: 0.6\n"));
  const auto bif =
      run("predict --model " + (dir_ / "model.bif").string() + " --assign 'xOff1=@1,yOff1=@1' --success onTop1=0");
  EXPECT_EQ(bif.code, 0) << bif.err;
  EXPECT_THAT(bif.out, HasSubstr("predicted success probability: 0.05\n"));
  const auto summed = run("predict --model " + model().string() + " --assign xOff1=0 --marginalize");
  EXPECT_THAT(summed.out, HasSubstr("yOff1 summed out"));
  EXPECT_THAT(summed.out, HasSubstr("predicted success probability: 0.683333"));
}

TEST_F(decide_cli_test, prevent_explains_and_suggests) {
  const auto r =
      run("prevent --model " + model().string() + " --assign 'xOff1=-1,yOff1=0.1' --controllable xOff1,yOff1");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("predicted success probability: 0.3\n"));
  EXPECT_THAT(r.out, HasSubstr("failure predicted"));
  EXPECT_THAT(r.out, HasSubstr("xOff1: 0 [-3, -0.4) cm -> 1 [-0.4, 0.4) cm (move +1.7 cm)"));
  EXPECT_THAT(r.out, HasSubstr("xOff1 = 0 cm (interval 1 [-0.4, 0.4) cm)"));
  EXPECT_THAT(r.out, HasSubstr("yOff1 = 0.1 cm (interval 1 [-0.4, 0.4) cm) (unchanged)"));
  EXPECT_THAT(r.out, HasSubstr("predicted success after prevention: 0.95"));
  // A run that failed at 0.3 had its noise below 0.7; at 0.95 it fails below 0.05 only.
  EXPECT_THAT(r.out, HasSubstr("the change would have made it succeed with probability 0.928571 (counterfactual"));
  const auto fine = run("prevent --model " + model().string() + " --assign 'xOff1=0,yOff1=0' --distance units");
  EXPECT_EQ(fine.code, 0) << fine.err;
  EXPECT_THAT(fine.out, HasSubstr("no failure predicted"));
  EXPECT_THAT(fine.err, HasSubstr("every parent of 'onTop1' may move"));
  const auto low =
      run("prevent --model " + model().string() + " --assign 'xOff1=2,yOff1=-1' --controllable yOff1 --epsilon 0.5");
  EXPECT_THAT(low.out, HasSubstr("no change reaches epsilon; the best one"));
}

TEST_F(decide_cli_test, bad_input_is_one_clear_line) {
  const auto m = " --model " + model().string();
  expect_error("predict" + m + " --assign 'xOff=0,yOff1=0'", "no variable 'xOff'");
  expect_error("predict" + m + " --assign 'xOff1=0,yOff1=0,colour=Pink'", "no state 'Pink'");
  expect_error("predict" + m + " --assign 'xOff1=0,yOff1=0,colour=0.5'", "'colour' has no interval edges");
  expect_error("predict" + m + " --assign 'xOff1=nan,yOff1=0'", "nan is not a finite number");
  expect_error("predict" + m + " --assign 'xOff1=0'", "no value is given for yOff1");
  expect_error("predict" + m + " --assign 'xOff1=0,yOff1=0' --success onTop1=2", "no state '2'");
  expect_error("prevent" + m + " --assign 'xOff1=0' --controllable yOff1", "controllable variable 'yOff1'");
  expect_error("prevent" + m + " --assign 'xOff1=0,yOff1=0' --controllable zz", "no variable 'zz'");
  expect_error("prevent" + m + " --assign 'xOff1=0,yOff1=0,colour=Red' --controllable colour --distance units",
               "'colour' has no interval edges");
  expect_error("predict --model " + (dir_ / "absent.json").string() + " --assign x=1", "absent.json");
  // Success is a prediction above epsilon, which no probability exceeds at 1: a usage error,
  // before the model is read (the library refuses it too: prevent_test).
  for (const std::string epsilon : {"2", "1", "-0.5", "nan"}) {
    const auto r = run("prevent" + m + " --assign 'xOff1=0,yOff1=0' --epsilon " + epsilon);
    EXPECT_EQ(r.code, 2) << epsilon;
    EXPECT_THAT(r.err, HasSubstr("--epsilon: expected a number in [0, 1)")) << epsilon;
  }
  // Given but empty is not the same as absent (every parent).
  expect_error("prevent" + m + " --assign 'xOff1=0,yOff1=0' --controllable ''",
               "no variable is controllable, so nothing can be changed: name at least one");
}

TEST_F(decide_cli_test, prevent_with_a_reward_weighs_the_gain_against_the_cost) {
  const auto plan = "prevent --model " + model().string() + " --assign 'xOff1=-1,yOff1=0.1' --controllable xOff1,yOff1";
  // Moving xOff1 one bin raises success from 0.3 to 0.95: worth 65 of a reward of 100.
  const auto cheap = run(plan + " --reward 100 --move-cost xOff1=10,yOff1=10 --format json");
  ASSERT_EQ(cheap.code, 0) << cheap.err;
  const auto moved = nlohmann::json::parse(cheap.out);
  EXPECT_EQ(moved["plan"]["xOff1"], "1");
  EXPECT_EQ(moved["moves"], nlohmann::json::array({"xOff1"}));
  EXPECT_NEAR(moved["expected_utility"].get<double>(), 85, 1e-12);
  EXPECT_NEAR(moved["success_probability"].get<double>(), 0.95, 1e-15);
  EXPECT_NEAR(moved["cost"].get<double>(), 10, 1e-15);
  EXPECT_NEAR(moved["counterfactual_success"].get<double>(), 0.65 / 0.7, 1e-15);
  const auto dear = run(plan + " --reward 100 --move-cost xOff1=70,yOff1=70");
  EXPECT_EQ(dear.code, 0) << dear.err;
  EXPECT_THAT(dear.out, HasSubstr("expected utility 30 (success 0.3, cost 0)"));
  EXPECT_THAT(dear.out, HasSubstr("keep the plan"));
  // Per unit: the move is 1.7 cm.
  const auto units = run(plan + " --reward 100 --move-cost xOff1=10 --per units");
  EXPECT_THAT(units.out, HasSubstr("expected utility 78 (success 0.95, cost 17)"));
  EXPECT_THAT(units.out, HasSubstr("xOff1: 0 [-3, -0.4) cm -> 1 [-0.4, 0.4) cm (move +1.7 cm)"));
  expect_error(plan + " --reward 100 --move-cost colour=1", "'colour', which is not a controllable parent");
  expect_error(plan + " --reward 100 --move-cost xOff1", "expected NAME=COST, found 'xOff1'");
  EXPECT_EQ(run(plan + " --move-cost xOff1=1").code, 2);  // needs --reward
}

TEST_F(decide_cli_test, decide_solves_the_oil_wildcatter) {
  const auto oil = std::string(PGM_SOURCE_DIR) + "/tests/data/decisions/oil_wildcatter.xml";
  const auto help = run("decide --help");
  EXPECT_EQ(help.code, 0);
  EXPECT_THAT(help.out, HasSubstr("--limited-memory"));
  const auto text = run("decide --model " + oil + " --policy-out " + (dir_ / "policy.csv").string());
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("maximum expected utility: 22.5\nTest: yes\n"));
  EXPECT_THAT(text.out, HasSubstr("Test=yes, Seismic=diffuse -> no"));
  std::ifstream policy(dir_ / "policy.csv");
  const std::string csv((std::istreambuf_iterator<char>(policy)), std::istreambuf_iterator<char>());
  EXPECT_THAT(csv, HasSubstr("decision,observed,action\nTest,,yes\nDrill,\"Test=yes,Seismic=closed\",yes\n"));
  const auto json = run("decide --model " + oil + " --format json --value-of-information Oil --before Drill");
  ASSERT_EQ(json.code, 0) << json.err;
  const auto document = nlohmann::json::parse(json.out);
  EXPECT_EQ(document["meu"].get<double>(), 22.5);
  EXPECT_EQ(document["value_of_information"].get<double>(), 32.5);
  EXPECT_EQ(document["policies"]["Drill"][2],
            (nlohmann::json{{"Test", "yes"}, {"Seismic", "diffuse"}, {"action", "no"}}));
  EXPECT_EQ(document["local_optimum"], false);
  const auto limited = nlohmann::json::parse(run("decide --model " + oil + " --limited-memory --format json").out);
  EXPECT_EQ(limited["local_optimum"], true);
  EXPECT_LT(limited["start_expected_utility"].get<double>(), 22.5);
  expect_error("decide --model " + oil + " --evidence Seismic=open", "'Seismic' depends on the decision 'Test'");
  expect_error("decide --model " + oil + " --evidence Oil=damp", "no state 'damp'");
  expect_error("decide --model " + model().string(), "not an influence diagram");
  expect_error("decide --model " + (dir_ / "model.bif").string(), "expected a file ending in .xml");
  EXPECT_EQ(run("decide --model " + oil + " --before Drill").code, 2);
}

TEST_F(decide_cli_test, a_policy_written_reads_back_worth_the_meu) {
  const auto oil = std::string(PGM_SOURCE_DIR) + "/tests/data/decisions/oil_wildcatter.xml";
  const auto policy = (dir_ / "policy.csv").string();
  for (const std::string evidence : {"", " --evidence Oil=soaking"}) {
    const auto solved = run("decide --model " + oil + evidence + " --format json --policy-out " + policy);
    ASSERT_EQ(solved.code, 0) << solved.err;
    const auto given = run("decide --model " + oil + evidence + " --format json --policy-in " + policy);
    ASSERT_EQ(given.code, 0) << given.err;
    EXPECT_EQ(nlohmann::json::parse(given.out)["expected_utility"], nlohmann::json::parse(solved.out)["meu"])
        << evidence;
  }
  const auto text = run("decide --model " + oil + " --policy-in " + policy + " --evidence Oil=soaking");
  EXPECT_THAT(text.out, HasSubstr("expected utility of the policies in " + policy + ": "));
  std::ofstream(dir_ / "blind.csv") << "decision,observed,action\nTest,,no\nDrill,,yes\n";
  // Never testing, drilling blind: 0.5·-70 + 0.3·50 + 0.2·200 = 20.
  const auto blind = run("decide --model " + oil + " --policy-in " + (dir_ / "blind.csv").string() + " --format json");
  ASSERT_EQ(blind.code, 0) << blind.err;
  EXPECT_NEAR(nlohmann::json::parse(blind.out)["expected_utility"].get<double>(), 20.0, 1e-12);
  std::ofstream(dir_ / "bad.csv") << "decision,observed,action\nTest,,no\nDrill,Oil=dry,yes\n";
  expect_error("decide --model " + oil + " --policy-in " + (dir_ / "bad.csv").string(),
               "bad.csv:3:7: 'Oil' is not known when 'Drill' is taken");
  EXPECT_EQ(run("decide --model " + oil + " --policy-in " + policy + " --policy-out " + policy).code, 2);
  EXPECT_EQ(run("decide --model " + oil + " --policy-in " + policy + " --value-of-information Oil --before Drill").code,
            2);
}

TEST_F(decide_cli_test, counterfactual_bounds_necessity_and_sufficiency) {
  // P(onTop1 = 0 | xOff1) is 2.5/3 at bin 0 and 0.95/3 at bin 1, each bin a third: PN ≥
  // (2.5/9 + 0.95/9 − 0.95/3) / (2.5/9) = 0.24, the third bin keeping it from 0.62.
  const auto ask = "counterfactual --model " + model().string() + " --cause xOff1=0 --alternative 1 --effect onTop1=0";
  const auto text = run(ask);
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("had xOff1 been 1 | xOff1=0, onTop1=0) in [0.24, 1]"));
  const auto json = nlohmann::json::parse(run(ask + " --format json").out);
  EXPECT_NEAR(json["pn_lower"].get<double>(), 0.24, 1e-15);
  for (const auto* bound : {"ps_lower", "ps_upper", "pns_lower", "pns_upper"}) EXPECT_TRUE(json[bound].is_number());
  expect_error(ask + " --evidence onTop1=1", "evidence on 'onTop1'");
  expect_error("counterfactual --model " + model().string() + " --cause xOff1 --alternative 1 --effect onTop1=0",
               "--cause: expected VARIABLE=STATE");
  expect_error("counterfactual --model " + model().string() + " --cause xOff1=0 --alternative 9 --effect onTop1=0",
               "no state '9'");
}

TEST_F(decide_cli_test, counterfactual_distributions_on_a_structural_model_or_a_network_read_as_one) {
  // docs/causal.md's tower: it fell at offset 2, so its unit was noise 1 or 2 (0.3 : 0.2), and
  // at offset 0 noise 1 stands.
  const auto page = slurp(std::filesystem::path(PGM_SOURCE_DIR) / "docs" / "causal.md");
  const auto start = page.find("```json\n") + 8;
  const auto tower = file("tower.json", page.substr(start, page.find("```", start) - start)).string();
  const auto ask = "counterfactual --model " + tower + " --evidence xOff1=2,onTop1=0 --do xOff1=0 --query onTop1";
  const auto csv = run(ask);
  ASSERT_EQ(csv.code, 0) << csv.err;
  EXPECT_EQ(csv.out, "onTop1,probability\n0,0.4\n1,0.6\n");
  const auto json = nlohmann::json::parse(run(ask + " --format json").out);
  EXPECT_NEAR(json["distribution"][1]["probability"].get<double>(), 0.6, 1e-15);
  EXPECT_NEAR(json["evidence_probability"].get<double>(), 0.25, 1e-15);  // P(xOff1 = 2, fell) = 0.5 · 0.5
  EXPECT_EQ(json["do"], nlohmann::json({{"xOff1", "0"}}));
  // Every other command reads it as the network it implies.
  const auto query = run("query --model " + tower + " --query onTop1 --evidence xOff1=2");
  EXPECT_EQ(query.out, "onTop1,probability\n0,0.5\n1,0.5\n");
  EXPECT_THAT(query.err, HasSubstr("holds a structural model: read as the causal network it implies"));

  // A network is read as monotone only when asked: (x=0, y=1) succeeds with 0.3, (1, 1) with 0.95.
  const auto network =
      " --model " + model().string() + " --evidence xOff1=0,yOff1=1,onTop1=0 --do xOff1=1 --query onTop1";
  expect_error("counterfactual" + network, "does not determine counterfactuals");
  const auto monotone = run("counterfactual" + network + " --assume monotone --format json");
  ASSERT_EQ(monotone.code, 0) << monotone.err;
  const auto stood = nlohmann::json::parse(monotone.out)["distribution"][1];
  EXPECT_EQ(stood["onTop1"], "1");
  EXPECT_NEAR(stood["probability"].get<double>(), 0.65 / 0.7, 1e-15);
  // pgm convert writes that structural model; read back, it answers the same.
  const auto structural = (dir_ / "monotone.json").string();
  const auto converted = run("convert " + model().string() + " " + structural + " --structural monotone");
  ASSERT_EQ(converted.code, 0) << converted.err;
  EXPECT_THAT(converted.out, HasSubstr("(a structural model, monotone): 4 variables"));
  const auto back = run("counterfactual --model " + structural +
                        " --evidence xOff1=0,yOff1=1,onTop1=0 --do xOff1=1 --query onTop1 --format json");
  EXPECT_EQ(back.out, monotone.out);
  expect_error("convert " + model().string() + " " + (dir_ / "m.bif").string() + " --structural monotone",
               "name the output .json");

  const auto misused = [&](const std::string& arguments, const std::string& message) {
    const auto r = run(arguments);
    EXPECT_EQ(r.code, 2) << arguments;  // a usage error, as the parser's own
    EXPECT_THAT(r.err, HasSubstr(message)) << arguments;
  };
  misused(ask + " --cause xOff1=2", "choose one");
  misused("counterfactual --model " + tower + " --do xOff1=0", "--query");
  misused(ask + " --assume monotone", "needs no --assume");
  misused(ask + " --format text", "prints as csv or json");
  expect_error("counterfactual --model " + tower + " --evidence xOff1=2,onTop1=0 --do xOff1=0 --query nowhere",
               "nowhere");
}

// pgm prevent --dynamic on docs/dynamic.md's model, by hand: the transition's b | a, b@-1 gives
// P(b@1 = high | a@0 = on, b@0 = high) = 0.2 · 0.5 + 0.8 · 0.9 = 0.82 with a@1 left to its table
// (0.2, 0.8), and 0.9 with a@1 set on.
TEST_F(decide_cli_test, prevent_over_time_sets_the_next_step) {
  const auto page = slurp(std::filesystem::path(PGM_SOURCE_DIR) / "docs" / "dynamic.md");
  const auto start = page.find("```json\n") + 8;
  const auto model = file("tower.json", page.substr(start, page.find("```", start) - start)).string();
  const auto episode = file("e.csv", "episode,t,a,b\ne1,0,on,high\n").string();
  const auto base = "prevent --dynamic --model " + model + " --controllable a --success b=high --data ";
  const auto json = run(base + episode + " --format json");
  ASSERT_EQ(json.code, 0) << json.err;
  const auto answer = nlohmann::json::parse(json.out);
  EXPECT_EQ(answer["step"], 1);
  EXPECT_EQ(answer["horizon"], 2);
  EXPECT_EQ(answer["planned"], false);
  EXPECT_NEAR(answer["before"].get<double>(), 0.82, 1e-15);
  EXPECT_EQ(answer["best"], nlohmann::json({{"a", "on"}}));
  EXPECT_NEAR(answer["after"].get<double>(), 0.9, 1e-15);
  // A plan of a = off at step 1 is worth 0.5 there; over three steps the text says which.
  const auto planned = file("p.csv", "episode,t,a,b\ne1,0,on,high\ne1,1,off,\n").string();
  const auto text = run(base + planned + " --steps 3");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("success: b=high at steps 1 to 2\npredicted success as planned: "));
  EXPECT_THAT(text.out, HasSubstr("best setting at step 1: a=on\n"));
  const auto one = nlohmann::json::parse(run(base + planned + " --format json").out);
  EXPECT_EQ(one["planned"], true);
  EXPECT_NEAR(one["before"].get<double>(), 0.5, 1e-15);
  EXPECT_NEAR(one["after"].get<double>(), 0.9, 1e-15);

  expect_failure(base + episode + " --steps 1", "the horizon of 1 steps ends before step 1");
  expect_failure("prevent --dynamic --model " + model + " --controllable b --success b=high --data " + episode,
                 "the success variable 'b' is controllable");
  expect_failure("prevent --dynamic --model " + model + " --controllable c --success b=high --data " + episode,
                 "--controllable: 'c' is not a variable of the model");
  expect_failure(base + episode + " --assign a=on", "--dynamic: --assign does not apply");
  expect_failure("prevent --dynamic --model " + model + " --success b=high --data " + episode,
                 "--dynamic needs --controllable");
  expect_failure("prevent --model " + model + " --assign a=on --data " + episode,
                 "--data and --steps apply with --dynamic");
}

}  // namespace
}  // namespace pgm::decide_cli_tests
