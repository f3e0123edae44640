#pragma once
// The definitions of pgm/learn/structure_learner_registry.hpp: inline in a header-only build,
// compiled once into libpgm under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/structure_learner_registry.hpp"
#include "pgm/learn/structure_learners.hpp"

namespace pgm {

PGM_DECL structure_learner_registry& structure_learners() {
  static structure_learner_registry registry = [] {
    structure_learner_registry built_in("structure learner");
    built_in.add("pc", component_entry<structure_learner, pc_learner>("PC-stable, its CPDAG and one DAG of the class"));
    built_in.add("hc", component_entry<structure_learner, hill_climbing_learner>("hill climbing"));
    built_in.add("tabu", component_entry<structure_learner, tabu_search_learner>("tabu search"));
    built_in.add("mmhc", component_entry<structure_learner, hybrid_learner>(
                             "PC-stable's skeleton restricts hill climbing (bnlearn's rsmax2)"));
    built_in.add("empty", component_entry<structure_learner, empty_learner>("the empty graph and the required edges"));
    return built_in;
  }();
  return registry;
}

PGM_DECL structure_learner make_structure_learner(std::string_view text,
                                                  const std::vector<component_setting>& settings) {
  const auto& registry = structure_learners();
  const auto refused = [](const component_setting& setting, const error& why) {
    return model_error(setting.label + ": " + why.what());
  };
  std::optional<std::string> start;
  for (const auto& setting : settings) {
    if (setting.key != "start" || !setting.value) continue;
    try {
      static_cast<void>(registry.choose(*setting.value));
    } catch (const error& why) {
      throw refused(setting, why);
    }
    start = *setting.value;
  }
  std::vector<bool> taken(settings.size(), false);
  if (start) {
    for (std::size_t i = 0; i < settings.size(); ++i) {
      const auto& setting = settings[i];
      if (!setting.value || setting.key == "start" || !registry.choose(*start).options.declares(setting.key)) continue;
      try {
        start = registry.with_setting(*start, setting.key, *setting.value);
      } catch (const error& why) {
        throw refused(setting, why);
      }
      taken[i] = true;
    }
  }
  std::string chosen(text);
  for (std::size_t i = 0; i < settings.size(); ++i) {
    const auto& setting = settings[i];
    if (!setting.value) continue;
    const auto value = setting.key == "start" ? *start : *setting.value;
    if (taken[i] && !registry.choose(chosen).options.declares(setting.key)) continue;
    try {
      chosen = registry.with_setting(chosen, setting.key, value);
    } catch (const error& why) {
      throw refused(setting, why);
    }
  }
  return registry.make(chosen);
}

}  // namespace pgm
