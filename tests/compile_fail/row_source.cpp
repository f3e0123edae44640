// A source that counts but cannot give its rows is a family_source and not a row_source (what EM
// reads): the concept refuses it.
#include <pgm/learn/family_source.hpp>

struct counting_only {
  [[nodiscard]] std::vector<std::string> columns() const;
  [[nodiscard]] std::string name() const;
  [[nodiscard]] pgm::family_counts count(const pgm::family_count_request& request);
  [[nodiscard]] bool holds_counts() const;
#ifdef PGM_CONTROL
  [[nodiscard]] pgm::dataset read(const pgm::family_count_request& request, pgm::family_counts& result);
#endif
};

static_assert(pgm::family_source<counting_only>);
static_assert(pgm::row_source<counting_only>);
