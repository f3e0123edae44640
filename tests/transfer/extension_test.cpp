// A user's strategy, added in its own translation unit (docs/examples/extending/blend.cpp, linked into
// this test), is found by name; the concept accepts and rejects the right types.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "pgm/transfer/registry.hpp"

namespace extension_tests {
namespace {

using namespace pgm;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

struct no_name {
  transferred_prior operator()(const transfer_problem&) const;
};
struct mutating_call {
  static std::string_view name() { return "x"; }
  transferred_prior operator()(const transfer_problem&);  // not const
};
struct wrong_result {
  static std::string_view name() { return "x"; }
  cpt<double> operator()(const transfer_problem&) const;
};
static_assert(!PriorTransfer<no_name>);
static_assert(!PriorTransfer<mutating_call>);
static_assert(!PriorTransfer<wrong_result>);
static_assert(PriorTransfer<minimal_replacement>);

TEST(extension_test, the_blend_example_is_registered_and_averages_direct_and_cross) {
  const auto names = transfer_registry::instance().names();
  EXPECT_THAT(names, ::testing::IsSupersetOf({"blend", "cross", "direct", "minimal"}));
  const auto x1 = variable::intervals("xOff1", {0, 1, 2, 3}), x2 = variable::intervals("xOff2", {0, 1, 2, 3});
  const variable on1("onTop1", {"0", "1"}), on2("onTop2", {"0", "1"});
  const cpt<double> prior(on1, {x1}, {0.9, 0.1, 0.5, 0.5, 0.2, 0.8});
  const transfer_problem problem(prior, on2, {x1, x2}, parse_correspondence("onTop2=onTop1,xOff2~xOff1"));
  const auto blend = transfer_registry::instance().at("blend")(problem);
  const std::vector<std::size_t> codes{0, 2};
  EXPECT_DOUBLE_EQ(blend.table().column(blend.table().configuration(codes))[1], 0.5 * 0.1 + 0.5 * 0.8);
  EXPECT_EQ(blend.sources(blend.table().configuration(codes)).size(), 2U);
  EXPECT_EQ(blend.via(config_index(0)), replacement::other);
}

TEST(extension_test, registry_errors) {
  EXPECT_THAT([] { static_cast<void>(transfer_registry::instance().at("bogus")); },
              ThrowsMessage<unknown_name>(
                  HasSubstr("unknown transfer strategy 'bogus' (known: blend, cross, direct, minimal)")));
  EXPECT_THAT([] { transfer_registry::instance().add(direct_replacement{}); },
              ThrowsMessage<model_error>(HasSubstr("named 'direct' is registered already")));
}

}  // namespace
}  // namespace extension_tests
