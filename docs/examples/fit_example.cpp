// The README's library example: fit a network from a discretized CSV and save it as BIF.
// Usage: fit_example trials.csv fitted.bif
#include <iostream>
#include <pgm/pgm.hpp>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: fit_example trials.csv fitted.bif\n";
    return 2;
  }
  try {
    // Every column as discrete states, e.g. the bin indices `pgm discretize` writes.
    const auto data = pgm::read_csv(argv[1], {.default_kind = pgm::column_kind::discrete});
    const auto structure = pgm::structure_from_data(data, pgm::parse_edge_list("xOff1->onTop1,yOff1->onTop1"));
    const auto net = pgm::fit(structure, data, {.prior = pgm::k2_prior{}});
    pgm::write_network(net, argv[2]);
  } catch (const pgm::error& e) {
    std::cerr << "fit_example: " << e.what() << '\n';
    return 1;
  }
}
