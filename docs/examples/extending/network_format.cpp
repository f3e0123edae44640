// Writes the sprinkler network in libDAI's factor graph format of fg_format.cpp through the format registry,
// reads it back, and shows a broken file's error.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <pgm/io/network_file.hpp>

int main() {
  std::cout << "formats:";
  for (const auto& format : pgm::network_formats()) std::cout << ' ' << format.name();
  std::cout << "\nfiles: " << pgm::network_file_kinds() << '\n';

  const pgm::variable rain("rain", {"no", "yes"});
  const pgm::variable sprinkler("sprinkler", {"off", "on"});
  const pgm::variable grass("grass", {"dry", "wet"});
  const auto net = pgm::bayesian_network::from_tables({
      pgm::cpt<double>(rain, {}, {0.8, 0.2}),
      pgm::cpt<double>(sprinkler, {rain}, {0.6, 0.4, 0.99, 0.01}),
      pgm::cpt<double>(grass, {rain, sprinkler}, {1.0, 0.0, 0.2, 0.8, 0.1, 0.9, 0.01, 0.99}),
  });
  const auto folder = std::filesystem::temp_directory_path() / "pgm-fg-example";
  std::filesystem::create_directories(folder);
  pgm::write_network(net, folder / "sprinkler.fg");
  const auto back = pgm::read_network(folder / "sprinkler.fg");
  std::cout << "read back: " << back.size() << " variables, " << back.free_parameters() << " free parameters\n"
            << "P(grass=wet | rain=yes, sprinkler=off) = " << net.table("grass").probability("wet", {"yes", "off"})
            << ", P(v2=1 | v0=1, v1=0) = " << back.table("v2").probability("1", {"1", "0"}) << '\n';

  std::ofstream(folder / "broken.fg") << "1\n\n2\n0 x\n";
  try {
    static_cast<void>(pgm::read_network(folder / "broken.fg"));
  } catch (const pgm::error& e) {
    std::cout << "a broken file: " << e.what() << '\n';
  }
  std::filesystem::remove_all(folder);
}
