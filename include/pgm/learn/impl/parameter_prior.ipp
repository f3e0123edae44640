#pragma once
// The definitions of pgm/learn/parameter_prior.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <cmath>

#include "pgm/core/text.hpp"
#include "pgm/learn/parameter_prior.hpp"

namespace pgm::detail {

PGM_DECL void check_pseudo_count(double value, const char* what) {
  if (!std::isfinite(value) || value < 0.0) {
    throw model_error(std::string(what) + " must be a finite number ≥ 0, got " + text::format_double(value));
  }
}

/// The choice of the prior `name` with its one option `key` set to `value`.
[[nodiscard]] inline component_choice choice_with(std::string_view name, std::vector<option_declaration> declarations,
                                                  std::string_view key, double value) {
  option_values values(std::move(declarations));
  values.set(key, text::format_double(value), "prior", name);
  return {std::string(name), std::move(values)};
}

/// |Val(Pa)|, the number of the parents' configurations, as a double: it may pass 2⁶⁴.
[[nodiscard]] inline double configurations_of(const std::vector<variable>& parents) {
  double configurations = 1.0;
  for (const auto& parent : parents) configurations *= static_cast<double>(parent.cardinality());
  return configurations;
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL std::vector<double> family_pseudo_counts::spelled_out(std::size_t cells) const {
  if (const auto* alpha = uniform_alpha()) return std::vector<double>(cells, *alpha);
  if (const auto* weighted_form = weighted()) {
    const auto f = weighted_form->table.values();
    std::vector<double> alpha(f.begin(), f.end());
    for (auto& a : alpha) a *= weighted_form->weight;
    return alpha;
  }
  return *this->cells();
}

PGM_DECL std::vector<option_declaration> dirichlet_prior::options() {
  return {number_option("alpha", dirichlet_prior().alpha, "the pseudo-count of every cell").at_least(0.0)};
}

PGM_DECL dirichlet_prior::dirichlet_prior(const option_values& options) : alpha(options.number("alpha")) {}

PGM_DECL component_choice dirichlet_prior::choice() const {
  return detail::choice_with(name(), options(), "alpha", alpha);
}

PGM_DECL family_pseudo_counts dirichlet_prior::pseudo_counts(const variable&, const std::vector<variable>&) const {
  return family_pseudo_counts::uniform(alpha);  // estimate() checks it
}

PGM_DECL std::vector<option_declaration> bdeu_prior::options() {
  return {number_option("ess", bdeu_prior().equivalent_sample_size,
                        "the equivalent sample size N': every cell gets N' / (J·|Val(Pa)|)")
              .at_least(0.0)};
}

PGM_DECL bdeu_prior::bdeu_prior(const option_values& options) : equivalent_sample_size(options.number("ess")) {}

PGM_DECL component_choice bdeu_prior::choice() const {
  return detail::choice_with(name(), options(), "ess", equivalent_sample_size);
}

PGM_DECL family_pseudo_counts bdeu_prior::pseudo_counts(const variable& child,
                                                        const std::vector<variable>& parents) const {
  detail::check_pseudo_count(equivalent_sample_size, "the equivalent sample size");
  const double alpha =
      equivalent_sample_size / (static_cast<double>(child.cardinality()) * detail::configurations_of(parents));
  detail::check_pseudo_count(alpha, "the Dirichlet pseudo-count alpha");
  return family_pseudo_counts::uniform(alpha);
}

}  // namespace pgm
