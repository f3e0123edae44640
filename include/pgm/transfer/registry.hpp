#pragma once
/// \file
/// Strategies by name, for the `pgm` program and for code that picks one at run time. The
/// built-in strategies are always there; a user's strategy joins with one line in its own
/// translation unit:
///
///     static const pgm::register_transfer<my_strategy> registered;
///
/// (linked into the program as an object file, not from a static library, whose unreferenced
/// objects the linker would drop).

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/detail/named_registry.hpp"
#include "pgm/transfer/prior_transfer.hpp"
#include "pgm/transfer/replacement.hpp"

namespace pgm {

/// Any strategy, type-erased; it models PriorTransfer itself.
class any_prior_transfer {
 public:
  // Itself first: checking PriorTransfer<any_prior_transfer> asks whether it converts from itself,
  // which under this constructor recursed without end in clang.
  template <class S>
  requires(!std::same_as<S, any_prior_transfer> && PriorTransfer<S>)
      any_prior_transfer(S strategy)  // NOLINT(google-explicit-constructor): a strategy is one
      : name_(strategy.name()), call_(std::move(strategy)) {}

  [[nodiscard]] std::string_view name() const noexcept { return name_; }
  [[nodiscard]] transferred_prior operator()(const transfer_problem& problem) const { return call_(problem); }

 private:
  std::string name_;
  std::function<transferred_prior(const transfer_problem&)> call_;
};

static_assert(PriorTransfer<any_prior_transfer>);

class transfer_registry {
 public:
  /// The program-wide registry, holding the built-in strategies from the start.
  [[nodiscard]] static transfer_registry& instance() {
    static transfer_registry registry = [] {
      transfer_registry r;
      r.add(direct_replacement{});
      r.add(cross_replacement{});
      r.add(minimal_replacement{});
      return r;
    }();
    return registry;
  }

  /// Adds a strategy under its name; a second strategy of the same name is an error.
  void add(any_prior_transfer strategy) {
    std::string name(strategy.name());
    strategies_.add(std::move(name), std::move(strategy));
  }

  /// The strategy of that name; unknown_name otherwise.
  [[nodiscard]] any_prior_transfer at(std::string_view name) const {
    if (auto strategy = strategies_.find(name)) return *std::move(strategy);
    throw unknown_name("transfer strategy", std::string(name), names());
  }

  [[nodiscard]] std::vector<std::string> names() const { return strategies_.names(); }

 private:
  detail::named_registry<any_prior_transfer> strategies_{"transfer strategy"};
};

/// Registers a strategy when the program starts: `static const register_transfer<S> r;`.
template <PriorTransfer S>
struct register_transfer {
  explicit register_transfer(S strategy = {}) { transfer_registry::instance().add(std::move(strategy)); }
};

}  // namespace pgm
