// Query files (`pgm query --queries`; pgm/io/query_batch.hpp) answered on a small network
// by the junction tree, as the program answers them; the same bytes are also read as --soft
// (pgm/inference/posterior_table.hpp) and resolved against the network.

#include "pgm/io/query_batch.hpp"

#include <sstream>

#include "harness.hpp"
#include "pgm/inference/engine_registry.hpp"
#include "pgm/io/bif.hpp"

namespace {

const pgm::bayesian_network& query_network() {
  static const auto net = pgm::parse_bif(R"(network n { }
variable rain { type discrete [ 2 ] { yes, no }; }
variable grass { type discrete [ 3 ] { dry, damp, wet }; }
variable sun { type discrete [ 2 ] { on, off }; }
probability ( rain ) { table 0.2, 0.8 ; }
probability ( grass | rain ) { (yes) 0.1, 0.2, 0.7 ; (no) 0.6, 0.3, 0.1 ; }
probability ( sun | rain ) { (yes) 0.0, 1.0 ; (no) 0.5, 0.5 ; }
)",
                                         "garden.bif");
  return net;
}

}  // namespace

PGM_FUZZ_HARNESS(query_batch) {
  const auto text = pgm::fuzz::text_of(data, size);
  pgm::fuzz::expect_value_or_error(
      [&] { static_cast<void>(pgm::resolve_evidence(query_network(), {}, pgm::parse_soft_evidence(text))); });
  return pgm::fuzz::expect_value_or_error([&] {
    auto engine = pgm::make_engine("jt", query_network());
    std::ostringstream out;
    bool header = true;
    for (const auto& request : pgm::parse_query_batch(text, "queries.csv")) {
      engine.set_evidence(pgm::resolve_evidence(query_network(), request.observed, request.soft));
      const auto ids = pgm::resolve_query(query_network(), request.query, engine.evidence());
      try {
        pgm::write_query_record(out, request, engine.joint(ids), {}, header);
      } catch (const pgm::impossible_evidence&) {
      }
      header = false;
    }
  });
}
