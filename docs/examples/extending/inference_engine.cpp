// Uses the engine of enumeration_engine.cpp through the registry, beside the junction tree, on
// the sprinkler network: the same posterior, the same P(evidence).

#include <iostream>
#include <pgm/inference/engine_registry.hpp>
#include <string>

int main() {
  const pgm::variable rain("rain", {"no", "yes"});
  const pgm::variable sprinkler("sprinkler", {"off", "on"});
  const pgm::variable grass("grass", {"dry", "wet"});
  const auto net = pgm::bayesian_network::from_tables({
      pgm::cpt<double>(rain, {}, {0.8, 0.2}),
      pgm::cpt<double>(sprinkler, {rain}, {0.6, 0.4, 0.99, 0.01}),
      pgm::cpt<double>(grass, {rain, sprinkler}, {1.0, 0.0, 0.2, 0.8, 0.1, 0.9, 0.01, 0.99}),
  });
  std::cout << "engines:";
  for (const auto& name : pgm::engine_registry::instance().names()) std::cout << ' ' << name;
  std::cout << '\n';
  for (const char* name : {"enumerate", "jt"}) {
    auto engine = pgm::make_engine(name, net);
    pgm::set_evidence(engine, {{"grass", "wet"}});
    const auto p = pgm::marginal(engine, "rain");
    std::cout << name << ": P(rain=yes | grass=wet) = " << p.probability({"yes"})
              << ", P(grass=wet) = " << p.evidence_probability << '\n';
  }
}
