// A user's own structure score, written outside the library's headers: "heavy-bic" is BIC with
// its penalty per free parameter multiplied by `weight`, for sparser networks than BIC's.
// docs/extending.md walks through it; `pgm learn-structure --score heavy-bic[weight=3]` finds
// it in a program built with -DPGM_PLUGIN_SOURCES=docs/examples/extending/heavy_bic.cpp.

#include <cmath>
#include <pgm/learn/score_registry.hpp>
#include <vector>

namespace {

struct heavy_bic {
  // Declared once: `--score heavy-bic[weight=3]`, the help's list and Python's score= read this.
  static std::vector<pgm::option_declaration> options() {
    return {pgm::number_option("weight", 2.0, "times BIC's penalty per free parameter").greater_than(0.0)};
  }
  explicit heavy_bic(const pgm::option_values& options) : weight(options.number("weight")) {}

  // A family's term from its counts alone; called from several threads at once.
  double operator()(const pgm::count_table& counts) const {
    const double penalty = weight * std::log(static_cast<double>(counts.total())) / 2.0;
    return pgm::family_loglik(counts) - penalty * pgm::family_parameters(counts);
  }

  double weight;
};

static_assert(pgm::FamilyScore<heavy_bic>);

const pgm::register_score<heavy_bic> registered("heavy-bic", "BIC with its penalty times weight");

}  // namespace
