#pragma once
/// \file
/// Parameter priors for Bayesian estimation (eq. 6): each is a Dirichlet prior, given for a
/// family by its pseudo-counts α[x, u]. The paper's weighted prior (eq. 7/8) sets α[x, u] =
/// w·f(θ'_{x|u'}) from a prior table f that a transfer strategy produced in the target node's
/// shape.
///
/// A prior is any type that models `ParameterPrior` — a `name()` and the pseudo-counts of a
/// family from its variables — and `parameter_prior` holds any of them wherever a prior goes
/// (`fit_options::prior`, `fit_options::node_priors`, `estimate`). The registry
/// (pgm/learn/parameter_prior_registry.hpp) gives them names for `--prior` and Python.

#include <concepts>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/component_options.hpp"
#include "pgm/core/component_registry.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/variable.hpp"

namespace pgm {

/// The pseudo-counts α[x, u] a prior gives one family, in the form the Dirichlet kernel
/// (pgm/learn/dirichlet.hpp) reads without spelling out every cell: the same α in every cell,
/// α cell by cell, or the paper's w·f. Cells are laid out like the family's cpt: configuration
/// major, parents numbered by `mixed_radix` with the last parent fastest.
class family_pseudo_counts {
 public:
  /// The weighted form's table f and weight w.
  struct weighted_table {
    cpt<double> table;
    double weight = 0.0;
  };

  /// α cell by cell; implicit, so a prior may return its cells as they are.
  family_pseudo_counts(std::vector<double> cells)  // NOLINT(google-explicit-constructor)
      : form_(std::move(cells)) {}

  /// The same α in every cell: 0 is MLE, 1 the K2 prior.
  [[nodiscard]] static family_pseudo_counts uniform(double alpha) { return family_pseudo_counts(alpha); }
  /// α[x, u] = w·f[x|u], whose columns sum to w exactly as eq. 8 writes its denominator.
  [[nodiscard]] static family_pseudo_counts weighted(cpt<double> table, double weight) {
    return family_pseudo_counts(weighted_table{std::move(table), weight});
  }

  [[nodiscard]] const double* uniform_alpha() const noexcept { return std::get_if<double>(&form_); }
  [[nodiscard]] const std::vector<double>* cells() const noexcept { return std::get_if<std::vector<double>>(&form_); }
  [[nodiscard]] const weighted_table* weighted() const noexcept { return std::get_if<weighted_table>(&form_); }

  /// Every one of a family's `cells` cells, as EM's M-step reads them.
  [[nodiscard]] PGM_DECL std::vector<double> spelled_out(std::size_t cells) const;

 private:
  explicit family_pseudo_counts(double alpha) : form_(alpha) {}
  explicit family_pseudo_counts(weighted_table table) : form_(std::move(table)) {}

  std::variant<double, std::vector<double>, weighted_table> form_;
};

/// A prior names itself, for messages, and gives the pseudo-counts of a family from its
/// variables alone (a prior does not look at the data). One the registry makes may also give
/// `component_choice choice() const`, the text that makes it again ("bdeu[ess=10]"), which is
/// how saved statistics name it when it was made otherwise.
template <class P>
concept ParameterPrior = std::copy_constructible<P> &&
    requires(const P& prior, const variable& child, const std::vector<variable>& parents) {
  { prior.name() } -> std::convertible_to<std::string_view>;
  { prior.pseudo_counts(child, parents) } -> std::convertible_to<family_pseudo_counts>;
};

/// No prior: maximum likelihood (eq. 3).
struct no_prior {
  [[nodiscard]] static std::string_view name() noexcept { return "none"; }
  [[nodiscard]] static component_choice choice() { return {"none", {}}; }
  [[nodiscard]] static family_pseudo_counts pseudo_counts(const variable&, const std::vector<variable>&) {
    return family_pseudo_counts::uniform(0.0);
  }
};

/// The same pseudo-count α in every cell (α = 1 is the K2 prior, α = 0 is MLE).
struct dirichlet_prior {
  double alpha = 1.0;

  explicit dirichlet_prior(double pseudo_count = 1.0) : alpha(pseudo_count) {}
  PGM_DECL explicit dirichlet_prior(const option_values& options);
  [[nodiscard]] PGM_DECL static std::vector<option_declaration> options();

  [[nodiscard]] static std::string_view name() noexcept { return "dirichlet"; }
  [[nodiscard]] PGM_DECL component_choice choice() const;
  [[nodiscard]] PGM_DECL family_pseudo_counts pseudo_counts(const variable& child,
                                                            const std::vector<variable>& parents) const;
  friend bool operator==(const dirichlet_prior&, const dirichlet_prior&) = default;
};

/// Cooper and Herskovits' K2 prior: α = 1 in every cell.
struct k2_prior {
  [[nodiscard]] static std::string_view name() noexcept { return "k2"; }
  [[nodiscard]] static component_choice choice() { return {"k2", {}}; }
  [[nodiscard]] static family_pseudo_counts pseudo_counts(const variable&, const std::vector<variable>&) {
    return family_pseudo_counts::uniform(1.0);
  }
};

/// Bayesian Dirichlet equivalent uniform: α = N' / (J·|Val(Pa)|) for an equivalent sample
/// size N'.
struct bdeu_prior {
  double equivalent_sample_size = 1.0;

  explicit bdeu_prior(double ess = 1.0) : equivalent_sample_size(ess) {}
  PGM_DECL explicit bdeu_prior(const option_values& options);
  [[nodiscard]] PGM_DECL static std::vector<option_declaration> options();

  [[nodiscard]] static std::string_view name() noexcept { return "bdeu"; }
  [[nodiscard]] PGM_DECL component_choice choice() const;
  [[nodiscard]] PGM_DECL family_pseudo_counts pseudo_counts(const variable& child,
                                                            const std::vector<variable>& parents) const;
  friend bool operator==(const bdeu_prior&, const bdeu_prior&) = default;
};

/// Explicit pseudo-counts α[x, u] of one family, laid out like its cpt.
struct pseudo_counts_prior {
  std::vector<double> alpha;

  [[nodiscard]] static std::string_view name() noexcept { return "pseudo-counts"; }
  [[nodiscard]] family_pseudo_counts pseudo_counts(const variable&, const std::vector<variable>&) const {
    return alpha;
  }
};

/// The paper's weighted prior (eq. 7/8): θ = (w·f + M[x,u]) / (w + M[u]) for a prior table f
/// of the target node's shape and a weight w ≥ 0. With w = 0 it is MLE; where M[u] = 0 it is
/// f itself.
struct weighted_prior {
  cpt<double> prior;
  double weight = 0.0;

  [[nodiscard]] static std::string_view name() noexcept { return "weighted"; }
  [[nodiscard]] family_pseudo_counts pseudo_counts(const variable&, const std::vector<variable>&) const {
    return family_pseudo_counts::weighted(prior, weight);
  }
};

/// Any prior, type-erased; it models ParameterPrior itself. Made by the registry, it keeps the
/// choice that made it ("dirichlet[alpha=2]"), which is how saved statistics name it.
class parameter_prior {
 public:
  /// No prior: maximum likelihood.
  parameter_prior() : parameter_prior(no_prior{}) {}

  // Whether P is this type is asked first: checking ParameterPrior<parameter_prior> asks
  // whether it is copy constructible, which would otherwise ask this constraint again (clang
  // recurses without end).
  template <class P>
  requires(!std::same_as<P, parameter_prior> && ParameterPrior<P>)
      parameter_prior(P prior)  // NOLINT(google-explicit-constructor): `options.prior = k2_prior{}`
      : held_(std::make_shared<const model<P>>(std::move(prior))) {}

  template <ParameterPrior P>
  parameter_prior(P prior, component_choice choice)
      : held_(std::make_shared<const model<P>>(std::move(prior))), choice_(std::move(choice)) {}

  [[nodiscard]] std::string_view name() const { return held_->name(); }
  [[nodiscard]] family_pseudo_counts pseudo_counts(const variable& child, const std::vector<variable>& parents) const {
    return held_->pseudo_counts(child, parents);
  }

  /// The choice that makes this prior again: the registry's that made it, else the prior's
  /// own, if it gives one.
  [[nodiscard]] std::optional<component_choice> choice() const { return choice_ ? choice_ : held_->choice(); }

  /// The prior held, if it is a P.
  template <class P>
  [[nodiscard]] const P* target() const noexcept {
    const auto* held = dynamic_cast<const model<P>*>(held_.get());
    return held == nullptr ? nullptr : &held->prior;
  }

 private:
  struct concept_base {
    virtual ~concept_base() = default;
    [[nodiscard]] virtual std::string_view name() const = 0;
    [[nodiscard]] virtual family_pseudo_counts pseudo_counts(const variable& child,
                                                             const std::vector<variable>& parents) const = 0;
    [[nodiscard]] virtual std::optional<component_choice> choice() const = 0;
  };
  template <class P>
  struct model final : concept_base {
    explicit model(P held) : prior(std::move(held)) {}
    [[nodiscard]] std::string_view name() const override { return prior.name(); }
    [[nodiscard]] family_pseudo_counts pseudo_counts(const variable& child,
                                                     const std::vector<variable>& parents) const override {
      return prior.pseudo_counts(child, parents);
    }
    [[nodiscard]] std::optional<component_choice> choice() const override {
      if constexpr (requires { prior.choice(); }) {
        return prior.choice();
      } else {
        return std::nullopt;
      }
    }
    P prior;
  };

  std::shared_ptr<const concept_base> held_;
  std::optional<component_choice> choice_;
};

static_assert(ParameterPrior<parameter_prior> && ParameterPrior<no_prior> && ParameterPrior<dirichlet_prior> &&
              ParameterPrior<k2_prior> && ParameterPrior<bdeu_prior> && ParameterPrior<pseudo_counts_prior> &&
              ParameterPrior<weighted_prior>);

namespace detail {

PGM_DECL void check_pseudo_count(double value, const char* what);

}  // namespace detail

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/parameter_prior.ipp"
#endif
