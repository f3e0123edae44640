// A test that answers with a bare p-value rather than a ci_result is not an IndependenceTest:
// register_independence_test refuses it.
#include <pgm/learn/independence_test_registry.hpp>

struct p_value_only {
#ifdef PGM_CONTROL
  pgm::ci_result operator()(std::span<const std::uint64_t> counts, std::size_t x_states, std::size_t y_states) const;
#else
  std::string operator()(std::span<const std::uint64_t> counts, std::size_t x_states, std::size_t y_states) const;
#endif
};

static const pgm::register_independence_test<p_value_only> registered("p", "a p-value and nothing else");
