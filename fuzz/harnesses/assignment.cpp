// Assignments (--set, --controllable values; pgm/decide/assignment.hpp) against a small network
// with an interval variable and a labelled one, resolved to states as the decide commands do;
// the same bytes are also read as --evidence (pgm/inference/posterior_table.hpp).

#include "pgm/decide/assignment.hpp"

#include "harness.hpp"
#include "pgm/inference/posterior_table.hpp"
#include "pgm/io/bif.hpp"

namespace {

const pgm::bayesian_network& assignment_network() {
  static const auto net = pgm::parse_bif(R"(network n { }
variable x { type discrete [ 3 ] { low, mid, high }; property edges = -1, 0, 0.5, 2 ; }
variable y { type discrete [ 2 ] { 0, 1 }; }
probability ( x ) { table 0.2, 0.3, 0.5 ; }
probability ( y | x ) { (low) 0.2, 0.8 ; (mid) 0.5, 0.5 ; (high) 0.6, 0.4 ; }
)",
                                         "assignment.bif");
  return net;
}

}  // namespace

PGM_FUZZ_HARNESS(assignment) {
  const auto text = pgm::fuzz::text_of(data, size);
  pgm::fuzz::expect_value_or_error([&] { static_cast<void>(pgm::parse_evidence(text)); });
  return pgm::fuzz::expect_value_or_error([&] {
    static_cast<void>(pgm::resolve(assignment_network(), pgm::parse_assignment(text, assignment_network())));
  });
}
