#pragma once
// The definitions of pgm/learn/independence_test_registry.hpp: inline in a header-only build,
// compiled once into libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/independence_test_registry.hpp"

namespace pgm {

PGM_DECL independence_test_registry& independence_tests() {
  static independence_test_registry registry = [] {
    independence_test_registry built_in("independence test");
    built_in.add("chi2", component_entry<independence_test, chi_square_test>("Pearson's chi-square"));
    built_in.add("g2", component_entry<independence_test, g_squared_test>("the likelihood ratio G²"));
    return built_in;
  }();
  return registry;
}

PGM_DECL independence_test::independence_test() : independence_test(make_independence_test("chi2")) {}

}  // namespace pgm
