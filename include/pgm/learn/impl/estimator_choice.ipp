#pragma once
// The definitions of pgm/learn/estimator_choice.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>

#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/learn/estimator_choice.hpp"

namespace pgm {

PGM_DECL parameter_prior prior_of(const estimator_choice& choice) {
  if (choice.estimator == "mle") {
    const bool set = std::any_of(choice.settings.begin(), choice.settings.end(),
                                 [](const component_setting& setting) { return setting.value.has_value(); });
    if (choice.prior != default_parameter_prior || set) {
      throw error("a prior and its options apply to the bayes estimator, not mle");
    }
    return no_prior{};
  }
  if (choice.estimator != "bayes") throw unknown_name("estimator", choice.estimator, known_estimators());
  const auto& registry = parameter_priors();
  return registry.make(registry.with_settings(choice.prior, choice.settings));
}

}  // namespace pgm
