#pragma once
/// \file
/// Scores by name: `make_score("bdeu[iss=10]")` gives a `family_score`, any FamilyScore
/// (pgm/learn/score.hpp) behind one type, which the structure search, `score_network`, the
/// program's `--score` and Python's `score=` all take. The built-in names are bic, aic[k=1],
/// bdeu[iss=1] (bnlearn's "bde" too), k2 and loglik.
///
/// A user's score joins in one line in its own translation unit:
///
///     static const pgm::register_score<my_score> registered("mine", "what it rewards");
///
/// where `my_score` models FamilyScore and either is default-constructible or declares
/// `static std::vector<pgm::option_declaration> options()` and is constructible from the
/// `const pgm::option_values&` they are read into; `--score mine[key=value]` then reaches it.

#include <concepts>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/component_options.hpp"
#include "pgm/core/component_registry.hpp"
#include "pgm/learn/score.hpp"
#include "pgm/learn/sufficient_statistics.hpp"

namespace pgm {

/// Any family score, with the name and options it was chosen by. Copies share the score,
/// which is called from several threads at once and so must not change when called.
class family_score {
 public:
  /// bic, the library's default.
  PGM_DECL family_score();

  template <class S>
  requires(!std::same_as<S, family_score> && FamilyScore<S>) family_score(S score, component_choice choice)
      : self_(std::make_shared<const holder<S>>(std::move(score))), choice_(std::move(choice)) {}

  /// The family's term (larger is better).
  [[nodiscard]] double operator()(const count_table& counts) const { return self_->score(counts); }

  [[nodiscard]] const std::string& name() const noexcept { return choice_.name; }
  [[nodiscard]] const option_values& options() const noexcept { return choice_.options; }
  /// "bdeu[iss=10]": what chooses this score again.
  [[nodiscard]] std::string text() const { return choice_.text(); }

 private:
  struct interface {
    virtual ~interface() = default;
    [[nodiscard]] virtual double score(const count_table& counts) const = 0;
  };
  template <class S>
  struct holder final : interface {
    explicit holder(S s) : inside(std::move(s)) {}
    double score(const count_table& counts) const override { return static_cast<double>(inside(counts)); }
    S inside;
  };

  std::shared_ptr<const interface> self_;
  component_choice choice_;
};

static_assert(FamilyScore<family_score>);

using score_registry = component_registry<family_score>;

/// The program-wide registry of scores, holding the built-in ones from the start.
[[nodiscard]] PGM_DECL score_registry& scores();

/// The score `text` chooses ("bic", "bdeu[iss=10]"). Throws unknown_name for an unknown
/// score or option, model_error for a bad value.
[[nodiscard]] inline family_score make_score(std::string_view text) { return scores().make(text); }

namespace detail {

/// The registry's entry for S: its options and how it is built from them.
template <FamilyScore S>
[[nodiscard]] score_registry::entry score_entry(std::string summary) {
  if constexpr (requires { S::options(); }) {
    static_assert(std::constructible_from<S, const option_values&>,
                  "a score that declares options is constructible from the option_values they are read into");
    return {std::move(summary), S::options(),
            [](const component_choice& choice) { return family_score(S(choice.options), choice); }};
  } else {
    static_assert(std::default_initializable<S>, "a score without options is default-constructible");
    return {std::move(summary), {}, [](const component_choice& choice) { return family_score(S{}, choice); }};
  }
}

}  // namespace detail

/// Registers a score type when the program starts: `static const register_score<S> r("name", "…");`.
template <FamilyScore S>
struct register_score {
  register_score(std::string name, std::string summary) {
    scores().add(std::move(name), detail::score_entry<S>(std::move(summary)));
  }
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/score_registry.ipp"
#endif
