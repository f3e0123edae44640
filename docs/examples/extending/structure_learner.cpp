// Chooses the user's learner of chow_liu.cpp by name, as the program and Python do, beside hill
// climbing: b is a noisy copy of a, c a noisier copy of b, and d a coin of its own.

#include <cstdint>
#include <iostream>
#include <pgm/learn/learn_structure.hpp>
#include <vector>

int main() {
  std::vector<unsigned> a, b, c, d;
  std::uint64_t state = 11;
  const auto draw = [&state](unsigned percent) {  // a fixed LCG, so the example prints the same
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<unsigned>((state >> 33) % 100) < percent;
  };
  for (int row = 0; row < 3000; ++row) {
    a.push_back(draw(50));
    b.push_back(draw(a.back() ? 90 : 10));
    c.push_back(draw(b.back() ? 80 : 20));
    d.push_back(draw(50));
  }
  pgm::dataset data;
  for (auto [name, codes] : {std::pair{"a", &a}, {"b", &b}, {"c", &c}, {"d", &d}}) {
    data.add(pgm::discrete_column(pgm::variable(name, {"0", "1"}), *codes));
  }

  std::cout << "learners:";
  for (const auto& name : pgm::structure_learners().names()) std::cout << ' ' << name;
  std::cout << '\n';
  for (const char* choice : {"hc", "chow-liu", "chow-liu[min_information=0.01]"}) {
    const auto learned = pgm::learn_structure(data, pgm::make_structure_learner(choice));
    std::cout << choice << ":";
    for (const auto& edge : learned.edges) std::cout << ' ' << edge.from << "->" << edge.to;
    std::cout << '\n';
  }
}
