// UAI model files (pgm/io/uai.hpp): a model read back from what it writes is the same model, and
// a small model's partition function is computed, as `pgm solve` would, in either representation.

#include "pgm/io/uai.hpp"

#include "harness.hpp"
#include "pgm/inference/solve.hpp"

PGM_FUZZ_HARNESS(uai) {
  const auto text = pgm::fuzz::text_of(data, size);
  const auto read = pgm::fuzz::outcome_of([&] { return pgm::parse_uai(text, "m.uai").model; });
  if (!read.value) return 0;
  const auto again = pgm::fuzz::outcome_of([&] { return pgm::parse_uai(pgm::to_uai(*read.value), "m.uai").model; });
  pgm::fuzz::expect_same(read, again, "a model read back from its own text differs");
  return pgm::fuzz::expect_value_or_error([&] {
    pgm::solve_options options;
    options.engine = pgm::solve_engine::jt;             // exact or refused: a loopy model's bp may run long
    options.memory_limit_bytes = std::size_t{1} << 20;  // small inputs, small tables
    static_cast<void>(pgm::log_partition(*read.value, {}, options));
  });
}
