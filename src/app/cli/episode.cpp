#include "cli/episode.hpp"

#include <algorithm>

#include "cli/common.hpp"
#include "pgm/core/text.hpp"
#include "pgm/io/csv.hpp"

namespace pgm::cli {

variable_id template_id(const dynamic_network& model, const std::string& name, const std::string& where) {
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (model.variables()[i].name() == name) return index_at<variable_id>(i);
  }
  std::vector<std::string> names;
  for (const auto& v : model.variables()) names.push_back(v.name());
  const auto closest = text::closest_name(name, names);
  throw error(where + ": '" + name + "' is not a variable of the model" +
              (closest ? " (did you mean '" + *closest + "'?)" : ""));
}

dataset read_episodes(const std::string& path, const std::set<std::string>& templates, const dynamic_network* model,
                      const missing_values& missing, unsigned threads) {
  const episode_columns columns;
  auto reading = long_form_options(columns);
  reading.missing = missing;
  reading.threads = threads;
  if (model) {
    for (const auto& v : model->variables()) reading.variables.emplace(v.name(), v);
  }
  if (path != "-") {  // other columns are not read (standard input is read once)
    const auto header = csv_reader(path).header();
    reading.columns.assign(templates.begin(), templates.end());
    reading.columns.push_back(columns.step);
    if (std::find(header.begin(), header.end(), columns.episode) != header.end()) {
      reading.columns.push_back(columns.episode);
    }
  }
  return read_csv(path, reading);
}

std::vector<evidence_set> read_episode(const dynamic_network& model, const std::string& path) {
  csv_options options;
  options.kinds["t"] = column_kind::continuous;
  options.kinds["episode"] = column_kind::discrete;
  for (const auto& v : model.variables()) options.variables.emplace(v.name(), v);
  options.missing.policy = missing_policy::available;
  const auto data = read_csv(path, options);
  if (!data.contains("t")) throw error(path + ": the data have no column t (long form: episode,t,<variables>)");
  for (const auto& name : data.names()) {
    if (name != "t" && name != "episode") static_cast<void>(template_id(model, name, path + ", column '" + name + "'"));
  }
  if (data.contains("episode")) {
    const auto& episode = data.discrete("episode");
    for (std::size_t r = 1; r < data.rows(); ++r) {
      if (episode.code(r) != episode.code(0)) {
        throw error(path + ": row " + std::to_string(r + 1) + " is of episode '" + episode.label(r) +
                    "', the first of '" + episode.label(0) + "': one episode is answered at a time");
      }
    }
  }
  const auto t = data.continuous("t").values();
  std::vector<evidence_set> steps(data.rows());
  for (std::size_t r = 0; r < data.rows(); ++r) {
    if (t[r] != static_cast<double>(r)) {
      throw error(path + ": row " + std::to_string(r + 1) + " has t = " + text::format_double(t[r]) + " where " +
                  std::to_string(r) + " was expected (the rows run t = 0, 1, 2, … in order)");
    }
  }
  for (const auto& name : data.names()) {
    if (name == "t" || name == "episode") continue;
    const auto id = template_id(model, name, path);
    const auto& column = data.discrete(name);
    for (std::size_t r = 0; r < data.rows(); ++r) {
      if (!column.is_missing(r)) {
        steps[r].hard.push_back({id, index_at<state_index>(column.code(r))});
      }
    }
  }
  return steps;
}

}  // namespace pgm::cli
