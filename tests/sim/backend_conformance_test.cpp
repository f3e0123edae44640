// The back-end conformance kit (pgm/testing/backend_conformance.hpp) over every registered
// back-end on every shipped task it simulates: the analytic one, Bullet (when built) and the
// ideal-drop example of docs/extending.md (dropping tasks only).

#include "pgm/testing/backend_conformance.hpp"

#include "pgm/sim/task_lookup.hpp"

namespace pgm::backend_conformance_tests {

using testing::backend_case;
using testing::backend_conformance;

std::vector<backend_case> cases() {
  const auto shipped = sim::list_tasks(sim::default_task_directories());
  auto result = testing::registered_backend_cases(shipped);
  for (auto& c : result) {
    // The example of docs/extending.md drops spheres only.
    if (c.backend == "ideal-drop") std::erase_if(c.tasks, [](const std::string& t) { return !t.starts_with("drop-"); });
  }
  return result;
}

INSTANTIATE_TEST_SUITE_P(registered, backend_conformance, ::testing::ValuesIn(cases()), testing::backend_case_name);

}  // namespace pgm::backend_conformance_tests
