// A user's own transfer strategy, written outside the library's headers: "blend" averages the
// Direct- and the Cross-Replacement prior of every configuration, for a prior that neither
// trusts only the first cube nor only the second. docs/extending.md walks through it; a program
// built with -DPGM_PLUGIN_SOURCES=docs/examples/extending/blend.cpp finds it by
// `pgm fit --strategy blend`.

#include <pgm/transfer/registry.hpp>
#include <pgm/transfer/replacement.hpp>

namespace {

struct blend_replacement {
  [[nodiscard]] static constexpr std::string_view name() noexcept { return "blend"; }

  [[nodiscard]] pgm::transferred_prior operator()(const pgm::transfer_problem& problem) const {
    const auto direct = pgm::direct_replacement{}(problem);
    const auto cross = pgm::cross_replacement{}(problem);
    const auto& shape = direct.table();
    std::vector<double> values(shape.size());
    std::vector<pgm::prior_term> terms;
    std::vector<std::uint32_t> counts;
    for (std::size_t u = 0; u < shape.configurations(); ++u) {
      const auto c = pgm::index_at<pgm::config_index>(u);
      const auto d = direct.table().column(c), x = cross.table().column(c);
      for (std::size_t s = 0; s < d.size(); ++s) values[u * d.size() + s] = 0.5 * d[s] + 0.5 * x[s];
      // Both candidates' u′ at half their weight, so explanations show where each half came from.
      for (const auto* part : {&direct, &cross}) {
        for (auto term : part->sources(c)) terms.push_back({term.configuration, 0.5 * term.weight});
      }
      counts.push_back(static_cast<std::uint32_t>(direct.sources(c).size() + cross.sources(c).size()));
    }
    return {pgm::cpt<double>(shape.child(), shape.parents(), std::move(values)), direct.prior_parents(),
            std::move(terms), std::move(counts),
            std::vector<pgm::replacement>(shape.configurations(), pgm::replacement::other)};
  }
};

static_assert(pgm::PriorTransfer<blend_replacement>);

// Joins the registry when the program starts; `pgm fit --strategy blend` finds it by name.
const pgm::register_transfer<blend_replacement> registered;

}  // namespace
