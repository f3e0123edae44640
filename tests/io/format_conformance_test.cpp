// The format conformance kit (pgm/testing/format_conformance.hpp) over every registered format,
// on random networks and the published networks of tests/data/networks.

#include "pgm/testing/format_conformance.hpp"

namespace pgm::format_conformance_tests {

using testing::format_case;
using testing::format_conformance;

std::vector<format_case> cases() {
  std::vector<std::filesystem::path> published;
  for (const auto* name : {"asia", "sachs", "child", "insurance", "alarm", "hailfinder", "water", "pathfinder"}) {
    published.push_back(std::filesystem::path(PGM_NETWORKS_DIR) / (std::string(name) + ".bif"));
  }
  auto result = testing::registered_format_cases({{.format = "uai", .keeps_names = false}});
  for (auto& c : result) c.networks = published;
  return result;
}

INSTANTIATE_TEST_SUITE_P(registered, format_conformance, ::testing::ValuesIn(cases()), testing::format_case_name);

}  // namespace pgm::format_conformance_tests
