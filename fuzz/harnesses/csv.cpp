// The in-memory CSV reader (pgm/io/csv.hpp). The first byte picks the delimiter, the column
// kind and a chunk size; the rest is the file. The reader promises the same result for any
// number of threads and any chunk size, errors included, so the input is read twice: whole on
// one thread, and in small chunks on two.

#include "pgm/io/csv.hpp"

#include "harness.hpp"

PGM_FUZZ_HARNESS(csv) {
  if (size == 0) return 0;
  const unsigned choice = data[0];
  const auto text = pgm::fuzz::text_of(data + 1, size - 1);
  pgm::csv_options options;
  options.delimiter = (choice & 3u) == 1 ? ';' : (choice & 3u) == 2 ? '\t' : ',';
  const unsigned kind = (choice >> 2) & 3u;
  options.default_kind = kind == 1   ? pgm::column_kind::continuous
                         : kind == 2 ? pgm::column_kind::discrete
                                     : pgm::column_kind::automatic;
  options.allow_empty = (choice & 0x10u) != 0;
  options.threads = 1;
  const auto read = [&] { return pgm::fuzz::outcome_of([&] { return pgm::parse_csv(text, "fuzz.csv", options); }); };
  const auto whole = read();
  options.threads = 2;
  options.chunk_bytes = 1 + (choice >> 5) * 7;
  pgm::fuzz::expect_same(whole, read(), "reading in chunks on two threads gives another result");
  return 0;
}
