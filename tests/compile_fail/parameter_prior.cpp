// A prior without a name is not a ParameterPrior: register_parameter_prior refuses it.
#include <pgm/learn/parameter_prior_registry.hpp>

struct nameless_prior {
#ifdef PGM_CONTROL
  [[nodiscard]] static std::string_view name() { return "nameless"; }
#endif
  [[nodiscard]] static std::vector<double> pseudo_counts(const pgm::variable&, const std::vector<pgm::variable>&) {
    return {};
  }
};

static const pgm::register_parameter_prior<nameless_prior> registered("nameless", "no name of its own");
