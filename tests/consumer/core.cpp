// Links pgm::core alone (no libpgm, no zlib, no XML parser): every module's umbrella but io's
// and eval's compiles, and a network fitted from data in memory answers a query.
#include <iostream>
#include <pgm/causal.hpp>
#include <pgm/core.hpp>
#include <pgm/data.hpp>
#include <pgm/decide.hpp>
#include <pgm/inference.hpp>
#include <pgm/learn.hpp>
#include <pgm/sim.hpp>
#include <pgm/transfer.hpp>

int main() {
  const pgm::variable a("a", {"no", "yes"});
  const pgm::variable b("b", {"no", "yes"});
  pgm::dataset data;
  data.add(pgm::discrete_column(a, std::vector<unsigned>{0, 1, 1, 1}));
  data.add(pgm::discrete_column(b, std::vector<unsigned>{0, 0, 1, 1}));
  const auto network = pgm::fit(pgm::network_structure({a, b}, {{"a", "b"}}), data);
  // P(b = yes) = 1/4 · 0 + 3/4 · 2/3 = 1/2.
  const double p = pgm::query(network, {"b"}).probability({"yes"});
  std::cout << "pgm::core: P(b=yes) = " << p << '\n';
  return p * 2 == 1 ? 0 : 1;
}
