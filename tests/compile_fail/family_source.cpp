// A source that cannot say whether it holds the counts is not a family_source: fit refuses it.
#include <pgm/pipeline/fit_pipeline.hpp>

struct silent_source {
  [[nodiscard]] std::vector<std::string> columns() const;
  [[nodiscard]] std::string name() const;
  [[nodiscard]] pgm::family_counts count(const pgm::family_count_request& request);
#ifdef PGM_CONTROL
  [[nodiscard]] bool holds_counts() const;
#endif
};

pgm::fit_result fitted(silent_source& source, const pgm::fit_request& request) { return pgm::fit(source, request); }
