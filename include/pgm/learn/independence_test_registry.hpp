#pragma once
/// \file
/// Independence tests by name: `make_independence_test("chi2[correction=yates]")` gives an
/// `independence_test`, any IndependenceTest (pgm/learn/independence_test.hpp) behind one type,
/// which PC-stable, the DAG check, the program's `--test` and Python's `test=` all take. The
/// built-in names are chi2 and g2, each with the options correction (none or yates) and
/// min_rows_per_cell.
///
/// A user's test joins in one line in its own translation unit:
///
///     static const pgm::register_independence_test<my_test> registered("mine", "what it measures");
///
/// where `my_test` models IndependenceTest and either is default-constructible or declares
/// `static std::vector<pgm::option_declaration> options()` and is constructible from the
/// `const pgm::option_values&` they are read into.

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/component_options.hpp"
#include "pgm/core/component_registry.hpp"
#include "pgm/learn/independence_test.hpp"

namespace pgm {

/// Any independence test, with the name and options it was chosen by.
class independence_test : public chosen_function<ci_result(std::span<const std::uint64_t>, std::size_t, std::size_t)> {
 public:
  /// chi2, the library's default.
  PGM_DECL independence_test();
  independence_test(function_type test, component_choice choice)
      : chosen_function(std::move(test), std::move(choice)) {}
};

static_assert(IndependenceTest<independence_test>);

using independence_test_registry = component_registry<independence_test>;

/// The program-wide registry of independence tests, holding the built-in ones from the start.
[[nodiscard]] PGM_DECL independence_test_registry& independence_tests();

/// The test `text` chooses ("g2", "chi2[correction=yates]"). Throws unknown_name for an
/// unknown test or option, model_error for a bad value.
[[nodiscard]] inline independence_test make_independence_test(std::string_view text) {
  return independence_tests().make(text);
}

/// Registers a test type when the program starts:
/// `static const register_independence_test<T> r("name", "…");`.
template <IndependenceTest T>
using register_independence_test = component_registration<&independence_tests, T>;

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/learn/impl/independence_test_registry.ipp"
#endif
