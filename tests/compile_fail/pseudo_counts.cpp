// Pseudo-counts that give no column totals are not PseudoCounts: the Dirichlet kernel refuses them.
#include <pgm/learn/dirichlet.hpp>

struct cells_only {
#ifdef PGM_CONTROL
  [[nodiscard]] double column(std::size_t u) const;
#endif
  [[nodiscard]] std::span<const double> cells(std::size_t u) const;
};

double posterior_column(std::span<const std::uint64_t> counts, const cells_only& alpha, double* out) {
  return pgm::dirichlet_posterior_column(counts, 0, alpha, out);
}
