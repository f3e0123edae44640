// Finds the "blend" strategy (blend.cpp, a translation unit of its own) by name, as the pgm
// program does for `--strategy blend`, and transfers 1-Stack's onTop1 table to 2-Stack's onTop2.

#include <iostream>
#include <pgm/core/correspondence.hpp>
#include <pgm/transfer/registry.hpp>

int main() {
  try {
    const auto& registry = pgm::transfer_registry::instance();
    std::cout << "strategies:";
    for (const auto& name : registry.names()) std::cout << ' ' << name;
    std::cout << '\n';

    // The prior task's table P(onTop1 | xOff1) and the target node onTop2 with parents xOff1, xOff2.
    const auto x1 = pgm::variable::intervals("xOff1", {-3, -0.4, 0.4, 3});
    const auto x2 = pgm::variable::intervals("xOff2", {-3, -0.4, 0.4, 3});
    const pgm::variable on_top1("onTop1", {"0", "1"});
    const pgm::variable on_top2("onTop2", {"0", "1"});
    const pgm::cpt<double> prior(on_top1, {x1}, {0.9, 0.1, 0.2, 0.8, 0.9, 0.1});
    const pgm::transfer_problem problem(prior, on_top2, {x1, x2},
                                        pgm::parse_correspondence("onTop2=onTop1,xOff2~xOff1"));

    const auto blended = registry.at("blend")(problem);
    // Direct takes xOff1's bin, Cross takes xOff2's: at (left, centre) they say 0.1 and 0.8.
    std::cout << "blend: P(onTop2=1 | xOff1=0, xOff2=1) = " << blended.table().probability("1", {"0", "1"}) << '\n';
  } catch (const pgm::error& e) {
    std::cerr << "transfer_strategy: " << e.what() << '\n';
    return 1;
  }
}
