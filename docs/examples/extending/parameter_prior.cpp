// A parameter prior of one's own: any type with a name() and the pseudo-counts of a family,
// used wherever the built-in priors are (fit_options::prior, node_priors, estimate). Its options
// declared and registered in one line, it is chosen by name as the built-in ones are:
// make_parameter_prior("centred[scale=2]"), `pgm fit --prior` in a program that links it, and
// saved statistics keep it by that name.
//
// "centred" encodes what one believes before any trial: the nearer the release offsets lie to
// the centre, the likelier success. Each parent configuration gets `strength` pseudo-counts,
// split between success and failure by exp(-(d / scale)^2), d the distance of the offsets'
// interval midpoints from the centre.

#include <cmath>
#include <filesystem>
#include <iostream>
#include <pgm/data/discretizer.hpp>
#include <pgm/learn/fit.hpp>
#include <pgm/learn/parameter_prior.hpp>
#include <pgm/learn/parameter_prior_registry.hpp>
#include <pgm/sim/simulator.hpp>
#include <pgm/sim/task_file.hpp>

namespace {

struct centred_prior {
  double strength;  // pseudo-counts per parent configuration
  double scale;     // cm

  static std::vector<pgm::option_declaration> options() {
    return {
        pgm::number_option("strength", 10.0, "pseudo-counts per parent configuration").greater_than(0.0),
        pgm::number_option("scale", 4.0, "distance from the centre, in cm, at which success is 1/e").greater_than(0.0)};
  }
  explicit centred_prior(const pgm::option_values& options)
      : strength(options.number("strength")), scale(options.number("scale")) {}

  [[nodiscard]] static std::string_view name() { return "centred"; }

  [[nodiscard]] std::vector<double> pseudo_counts(const pgm::variable& child,
                                                  const std::vector<pgm::variable>& parents) const {
    const std::size_t states = child.cardinality();
    std::vector<std::size_t> radices;
    for (const auto& p : parents) radices.push_back(p.cardinality());
    const pgm::mixed_radix configurations(radices);
    std::vector<double> alpha(configurations.size() * states, strength / static_cast<double>(states));
    const auto success = child.find_state("1");
    if (!success || states != 2) return alpha;  // not an outcome: spread evenly
    for (std::size_t u = 0; u < configurations.size(); ++u) {
      const auto codes = configurations.decode(u);
      double squared = 0;
      for (std::size_t i = 0; i < parents.size(); ++i) {
        const auto& quantity = parents[i].tags().quantity;
        if (quantity != "x-offset" && quantity != "y-offset") continue;
        const double offset = parents[i].midpoint(pgm::state_index(codes[i])).value_or(0.0);
        squared += offset * offset;
      }
      const double p = std::exp(-squared / (scale * scale));
      alpha[u * states + success->value()] = strength * p;
      alpha[u * states + (1 - success->value())] = strength * (1 - p);
    }
    return alpha;
  }
};

static_assert(pgm::ParameterPrior<centred_prior>);
const pgm::register_parameter_prior<centred_prior> registered("centred", "success likelier near the centre");

}  // namespace

int main() {
  try {
    const auto task = pgm::sim::load_task(std::filesystem::path(PGM_EXAMPLE_DIR) / "tasks" / "drop-mug.json");
    const auto raw = pgm::sim::simulate(task, {.rows = 300, .seed = 2});  // few trials: the prior matters
    const std::vector<std::string> binned{"xOff", "yOff", "scalingFactor"};
    const auto data = pgm::apply_discretization(raw, pgm::fit_discretization(raw, binned, pgm::binning::quantile, 3));
    const auto structure = pgm::structure_from_data(data, task.structure);

    // Success at the centre (bin 1 of 3 for both offsets) and in a corner, in the largest mugs.
    for (const auto* text : {"none", "k2", "centred"}) {
      const auto network = pgm::fit(structure, data, {.prior = pgm::make_parameter_prior(text)});
      const auto& table = network.table("inside");
      std::cout << text << ": P(inside=1 | centre) = " << table.probability("1", {"1", "1", "2"})
                << ", P(inside=1 | corner) = " << table.probability("1", {"0", "0", "2"}) << '\n';
    }
  } catch (const pgm::error& e) {
    std::cerr << "parameter_prior: " << e.what() << '\n';
    return 1;
  }
}
