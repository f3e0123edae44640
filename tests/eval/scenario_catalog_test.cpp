// The scenario catalog: which scenarios a folder offers, in the order their files give, and
// the errors for repeated and unknown names.

#include "pgm/eval/scenario_catalog.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/folder_test.hpp"

namespace scenario_catalog_tests {
namespace {

using namespace pgm;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

class scenario_catalog_test : public pgm::testing::folder_test {
 protected:
  /// A valid scenario file `<file>.json` naming scenario `name`, with `extra` keys.
  void scenario_file(const std::string& file, const std::string& name, const std::string& extra = "") const {
    this->file(file + ".json", R"({"format": "pgm-scenario", "version": 1, "name": ")" + name +
                                   R"(", "title": "T", "prior": {"task": "one", "rows": 3, "node": "ok1"},
      "target": {"node": "ok2", "tasks": [{"task": "two", "train_rows": 4, "ground_truth_rows": 4}]},
      "map": "ok2=ok1", "strategies": ["direct"], "weights": [0, 5])" +
                                   extra + "}");
  }
};

TEST_F(scenario_catalog_test, the_shipped_scenarios_run_in_the_papers_order_from_their_files) {
  const auto folder = find_scenario_folder({std::filesystem::path(PGM_SOURCE_DIR) / "tasks"});
  const scenario_catalog catalog(folder);
  EXPECT_THAT(catalog.names(),
              ElementsAre("2-stack-sim", "2-stack-reality", "2-stack-sim-to-real", "sphere-dropping", "stack-to-drop"));
  for (const auto& s : catalog.scenarios()) EXPECT_TRUE(s.order.has_value()) << s.name;
}

TEST_F(scenario_catalog_test, order_sorts_and_scenarios_without_one_follow_by_file_name) {
  scenario_file("a", "alpha");
  scenario_file("b", "beta", R"(, "order": 2)");
  scenario_file("c", "gamma", R"(, "order": 1)");
  scenario_file("d", "delta");
  file("notes.txt", "not a scenario");
  const scenario_catalog catalog(dir_);
  EXPECT_THAT(catalog.names(), ElementsAre("gamma", "beta", "alpha", "delta"));
  EXPECT_EQ(catalog.at("beta").order, 2U);
  EXPECT_THAT(select_scenarios("all", dir_), ::testing::SizeIs(4));
  EXPECT_EQ(select_scenarios("alpha", dir_).at(0).source, dir_ / "a.json");
}

TEST_F(scenario_catalog_test, an_order_must_be_a_whole_number) {
  scenario_file("a", "alpha", R"(, "order": -1)");
  EXPECT_THAT([&] { static_cast<void>(scenario_catalog(dir_)); },
              ThrowsMessage<data_error>(HasSubstr("a.json: /order: expected a whole number")));
}

TEST_F(scenario_catalog_test, two_files_with_one_name_are_an_error_naming_both) {
  scenario_file("a", "same");
  scenario_file("b", "same");
  EXPECT_THAT([&] { static_cast<void>(scenario_catalog(dir_)); },
              ThrowsMessage<data_error>(HasSubstr("the scenario name 'same' is used by both")));
  EXPECT_THAT([&] { static_cast<void>(select_scenarios("all", dir_)); },
              ThrowsMessage<data_error>(AllOf(HasSubstr("a.json"), HasSubstr("b.json"))));
}

TEST_F(scenario_catalog_test, an_unknown_name_lists_the_known_ones_in_run_order) {
  scenario_file("a", "alpha");
  scenario_file("b", "beta", R"(, "order": 1)");
  EXPECT_THAT([&] { static_cast<void>(select_scenarios("bogus", dir_)); },
              ThrowsMessage<unknown_name>(HasSubstr("unknown scenario 'bogus' (known: beta, alpha, all)")));
}

TEST_F(scenario_catalog_test, a_scenario_in_its_own_file_is_read_alone) {
  scenario_file("alpha", "alpha");
  file("broken.json", "{ not json");
  const auto chosen = select_scenarios("alpha", dir_);
  ASSERT_EQ(chosen.size(), 1U);
  EXPECT_EQ(chosen[0].name, "alpha");
  // Found by its name inside another file, the whole folder is read, and the broken file fails.
  scenario_file("other-file", "beta");
  EXPECT_THAT([&] { static_cast<void>(select_scenarios("beta", dir_)); },
              ThrowsMessage<parse_error>(HasSubstr("broken.json")));
}

TEST_F(scenario_catalog_test, a_task_folder_without_scenarios_is_an_error_naming_the_folders) {
  EXPECT_EQ(find_scenario_folder({dir_ / "none", std::filesystem::path(PGM_SOURCE_DIR) / "tasks"}),
            std::filesystem::path(PGM_SOURCE_DIR) / "tasks" / "scenarios");
  EXPECT_THAT([&] { static_cast<void>(find_scenario_folder({dir_})); },
              ThrowsMessage<io_error>(HasSubstr("no scenarios folder under the task folders (" + dir_.string())));
}

}  // namespace
}  // namespace scenario_catalog_tests
