// Fits a two-node network through the installed or fetched library and checks one value, and
// that the generated headers (version, where the tasks are installed) came along.
#include <iostream>
#include <pgm/config.hpp>
#include <pgm/pgm.hpp>
#include <pgm/version.hpp>
#include <string_view>

int main() {
  const pgm::variable a("a", {"no", "yes"});
  const pgm::variable b("b", {"no", "yes"});
  pgm::dataset data;
  data.add(pgm::discrete_column(a, std::vector<unsigned>{0, 1, 1, 1}));
  data.add(pgm::discrete_column(b, std::vector<unsigned>{0, 0, 1, 1}));
  const auto network = pgm::fit(pgm::network_structure({a, b}, {{"a", "b"}}), data);
  const double p = network.table("b").probability("yes", {"yes"});
  std::cout << "pgm " << pgm::version << ": P(b=yes | a=yes) = " << p << '\n';
  const std::string_view tasks(pgm::config::installed_tasks_dir);
  return p * 3 == 2 && !std::string_view(pgm::version).empty() && tasks.ends_with("pgm/tasks") ? 0 : 1;
}
