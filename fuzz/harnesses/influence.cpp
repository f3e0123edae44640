// Influence diagrams (pgm/io/influence_file.hpp, pgm/io/xmlbif.hpp): the same bytes read as
// XMLBIF and as pgm's JSON model; a diagram read back from what it writes, in either format, is
// the same diagram; and a small one solves without any error but a pgm::error.

#include <cstdint>

#include "harness.hpp"
#include "pgm/decide/solve_decisions.hpp"
#include "pgm/io/influence_file.hpp"
#include "pgm/io/xmlbif.hpp"

namespace {

void check(const pgm::fuzz::outcome<pgm::influence_diagram>& read) {
  if (!read.value) return;
  const auto& diagram = *read.value;
  pgm::fuzz::expect_same(read, pgm::fuzz::outcome_of([&] {
                           return pgm::parse_xmlbif_influence_diagram(pgm::to_xmlbif(diagram), "fuzz.xml");
                         }),
                         "an influence diagram read back from its own XMLBIF differs");
  pgm::fuzz::expect_same(
      read, pgm::fuzz::outcome_of([&] { return pgm::parse_influence_json(pgm::to_json(diagram).dump(), "fuzz.json"); }),
      "an influence diagram read back from its own JSON differs");
  double configurations = 1;
  for (const auto& v : diagram.variables()) configurations *= static_cast<double>(v.cardinality());
  if (configurations <= 1e5) {
    static_cast<void>(pgm::fuzz::outcome_of([&] { return pgm::solve_decisions(diagram).meu; }));
    static_cast<void>(
        pgm::fuzz::outcome_of([&] { return pgm::solve_decisions(diagram, {}, {.limited_memory = true}).meu; }));
  }
}

}  // namespace

PGM_FUZZ_HARNESS(influence) {
  const auto text = pgm::fuzz::text_of(data, size);
  check(pgm::fuzz::outcome_of([&] { return pgm::parse_xmlbif_influence_diagram(text, "fuzz.xml"); }));
  check(pgm::fuzz::outcome_of([&] { return pgm::parse_influence_json(text, "fuzz.json"); }));
  return 0;
}
