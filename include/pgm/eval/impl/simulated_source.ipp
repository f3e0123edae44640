#pragma once
// The definitions of pgm/eval/simulated_source.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/eval/simulated_source.hpp"

namespace pgm {

PGM_DECL task_facts facts_of(const sim::task_definition& task, const std::string& node) {
  if (!task.contains(node)) throw data_error("task '" + task.name + "' has no variable '" + node + "'");
  task_facts facts;
  for (const auto& edge : task.structure) {
    if (edge.to == node) facts.parents.push_back(edge.from);
  }
  for (const auto& v : task.variables) {
    facts.tags.emplace(v.name, v.tags);
    if (v.controllable) facts.controllable.insert(v.name);
  }
  if (task.at(node).kind == sim::variable_kind::outcome) facts.success_state = sim::outcome_success_state;
  return facts;
}

PGM_DECL task_source simulated_source(simulated_source_options options) {
  struct state {
    simulated_source_options options;
    std::mutex mutex;
    std::map<std::string, sim::task_definition, std::less<>> tasks;
    std::map<std::string, std::string, std::less<>> origins;

    const sim::task_definition& task(const std::string& name) {
      const std::lock_guard lock(mutex);
      auto it = tasks.find(name);
      if (it == tasks.end()) {
        // The file is read once for both, so the checksum is of the text the task came from.
        const auto file = sim::find_task(name, options.task_folders);
        const auto text = pgm::read_file(file);
        it = tasks.emplace(name, sim::parse_task(text, file.string())).first;
        origins.emplace(name, options.backend + " on " + file.filename().string() + " (crc32 " +
                                  pgm::detail::crc32_hex(text) + ")");
      }
      return it->second;  // a std::map node: stays put while others are added
    }
    std::string origin(const std::string& name) {
      (void)task(name);
      const std::lock_guard lock(mutex);
      return origins.at(name);
    }
  };
  auto shared = std::make_shared<state>();
  shared->options = std::move(options);
  task_source result;
  result.data = [shared](const std::string& task, std::size_t rows, std::uint64_t seed) {
    sim::simulate_options run;
    run.backend = shared->options.backend;
    run.rows = rows;
    run.seed = seed;
    run.threads = shared->options.threads;
    if (shared->options.progress) {
      run.progress = [&](std::size_t done) { shared->options.progress(task, done, rows); };
    }
    return sim::simulate(shared->task(task), run);
  };
  result.facts = [shared](const std::string& task, const std::string& node) {
    return facts_of(shared->task(task), node);
  };
  result.origin = [shared](const std::string& task) { return shared->origin(task); };
  return result;
}

}  // namespace pgm
