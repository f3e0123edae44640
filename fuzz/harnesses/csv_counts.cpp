// The streaming CSV counter (pgm/io/csv_counts.hpp): the header is read, the first column
// counted as a child of the next two (when present), in one window on one thread, again in
// tiny windows (one thread: a window that spawned threads would make this harness slow), and
// in tiny chunks on two threads; the counts (or the error) must be the same every time.

#include "pgm/io/csv_counts.hpp"

#include <vector>

#include "harness.hpp"

namespace {

pgm::fuzz::outcome<std::vector<pgm::count_table>> count(std::string_view text, char delimiter, std::size_t chunk,
                                                        std::size_t window, unsigned threads) {
  return pgm::fuzz::outcome_of([&] {
    pgm::csv_reader reader(text, "fuzz.csv", delimiter);
    const auto& header = reader.header();
    pgm::family_count_request request;
    request.columns = header;
    pgm::family_names family;
    family.child = header.at(0);
    for (std::size_t i = 1; i < header.size() && i < 3; ++i) family.parents.push_back(header[i]);
    request.families.push_back(family);
    request.threads = threads;
    request.chunk_bytes = chunk;
    request.window_bytes = window;
    return pgm::count_csv(reader, request).families;
  });
}

}  // namespace

PGM_FUZZ_HARNESS(csv_counts) {
  if (size == 0) return 0;
  const unsigned choice = data[0];
  const auto text = pgm::fuzz::text_of(data + 1, size - 1);
  const char delimiter = (choice & 1u) ? ';' : ',';
  const auto whole = count(text, delimiter, 0, 0, 1);
  const std::size_t small = 1 + (choice >> 1) % 32;
  pgm::fuzz::expect_same(whole, count(text, delimiter, small, 2 * small, 1), "counting in tiny windows differs");
  pgm::fuzz::expect_same(whole, count(text, delimiter, small, 0, 2), "counting in tiny chunks on two threads differs");
  return 0;
}
