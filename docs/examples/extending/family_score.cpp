// Chooses the user's score of heavy_bic.cpp by name, as the program and Python do, and learns a
// structure with it beside BIC: c is a noisy copy of a, and b is a coin that c barely depends on.
// The heavier penalty drops the weak edge that BIC keeps.

#include <cstdint>
#include <iostream>
#include <pgm/learn/hill_climbing.hpp>
#include <pgm/learn/score_registry.hpp>
#include <string>
#include <vector>

int main() {
  std::vector<unsigned> a, b, c;
  std::uint64_t state = 7;
  const auto draw = [&state](unsigned percent) {  // a fixed LCG, so the example prints the same
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<unsigned>((state >> 33) % 100) < percent;
  };
  for (int row = 0; row < 2000; ++row) {
    a.push_back(draw(50));
    b.push_back(draw(50));
    c.push_back(draw(a.back() ? (b.back() ? 90 : 83) : (b.back() ? 17 : 10)));
  }
  pgm::dataset data;
  data.add(pgm::discrete_column(pgm::variable("a", {"0", "1"}), a));
  data.add(pgm::discrete_column(pgm::variable("b", {"0", "1"}), b));
  data.add(pgm::discrete_column(pgm::variable("c", {"0", "1"}), c));

  std::cout << "scores: ";
  for (const auto& listed : pgm::scores().listing()) std::cout << listed << ' ';
  std::cout << '\n';
  const std::vector<std::string> names{"a", "b", "c"};
  for (const char* choice : {"bic", "heavy-bic[weight=3]"}) {
    pgm::search_options options;
    options.score = pgm::make_score(choice);
    const auto learned = pgm::hill_climb(data, names, options);
    std::cout << options.score.text() << ":";
    for (const auto& edge : learned.edges) std::cout << ' ' << edge.from << "->" << edge.to;
    std::cout << '\n';
  }
}
