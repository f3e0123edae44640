#pragma once
/// \file
/// Task definitions: what a robot task's variables are, how an experiment samples them, which
/// of them the robot controls, which one is success, the known causal structure, and the
/// physical constants its simulators use. Tasks are data — one JSON file per task under
/// `tasks/` (see tasks/README.md) — so that a user can read and change them.
///
/// The physics models bind variables by name: "stacking" needs xOff<i>, yOff<i>, dropOff<i>
/// and the outcome onTop<i> for each cube i = 1, 2, …; "dropping" needs xOff, yOff,
/// scalingFactor and the outcome inside.

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "pgm/core/error.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/detail/file.hpp"
#include "pgm/detail/text.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/sim/distribution.hpp"

namespace pgm::sim {

enum class variable_kind {
  continuous,   ///< a measured quantity, written as a number
  categorical,  ///< named states (colours), written as words
  outcome       ///< an experiment's result, states "0" and "1" (1 = success)
};

struct task_variable {
  std::string name;
  variable_kind kind = variable_kind::continuous;
  semantic_tags tags;
  /// Whether the robot chooses the value (offsets, release heights) or the world does
  /// (container size, colours, outcomes).
  bool controllable = false;
  /// States of a categorical variable or an outcome; empty for a continuous one.
  std::vector<std::string> states;
  /// How an experiment samples it; unused for outcomes.
  distribution sampling;
  std::string description;

  /// The discrete variable of a categorical or outcome column.
  [[nodiscard]] variable as_variable() const { return variable(name, states, tags); }
};

/// Stacking cubes on a fixed cube: one released after the other, each with a landing offset
/// perturbed by release noise of standard deviation base + per_cm_drop * dropOff (cm).
struct stacking_physics {
  std::size_t cubes = 1;
  double cube_size = 5.0;       ///< cm
  double support_margin = 0.0;  ///< cm of each supporting face's edge that carries no load (rounded edges)
  double noise_base = 0.15;     ///< cm
  double noise_per_cm = 0.08;   ///< cm of noise per cm of release height
  double friction = 0.6;
  double restitution = 0.1;
  double cube_mass = 0.1;  ///< kg
  /// Bullet's fixed step (s): the largest whose outcomes agree with finer ones (docs/simulators.md).
  double time_step = 1.0 / 240;
  // The analytic model's own constants ("analytic" in the file; pgm calibrate fits them to
  // Bullet): a landing cube's impact, which the static rule does not see, as a margin (cm)
  // by which the load's centre of mass must stay inside the supporting face's edge and as
  // extra scatter (cm, sd) of where a cube comes to rest. "first": the first cube on the
  // fixed cubeDown; "later": once a cube lands on another one, which can move under it.
  double tipping_margin_first = 0.0;
  double tipping_margin_later = 0.0;
  double settle_noise_first = 0.0;
  double settle_noise_later = 0.0;
};

/// Dropping a sphere into a container whose diameter and height scale together.
struct dropping_physics {
  std::string container;
  double sphere_diameter = 6.6;       ///< cm
  double drop_height = 40.0;          ///< cm from the table to the sphere's bottom
  double diameter_at_scale_1 = 30.0;  ///< cm, the container's opening at scalingFactor 1
  double height_at_scale_1 = 4.0;     ///< cm
  double floor_fraction = 0.6;        ///< flat floor's diameter / opening (1: vertical walls)
  double landing_noise = 0.5;         ///< cm, standard deviation of the landing point per axis
  double friction = 0.5;
  double restitution = 0.5;
  double sphere_mass = 0.1;  ///< kg
  /// Bullet's fixed step (s): the largest whose outcomes agree with finer ones (docs/simulators.md).
  double time_step = 1.0 / 240;
  // The analytic model's own constants ("analytic" in the file; pgm calibrate fits them to
  // Bullet). The model resolves the sphere's first impact with the container and the flight
  // after it in closed form (docs/simulators.md): the share of the speed into the surface
  // that the bounce returns, the share of the speed along the surface that it keeps, extra
  // scatter (cm, sd) of the landing point, and how far (cm) above the far rim the sphere's
  // centre must pass to leave the container.
  double impact_restitution = 0.5;
  double impact_tangential = 5.0 / 7.0;
  double landing_scatter = 0.0;
  double rim_clearance = 0.0;
};

using physics_parameters = std::variant<stacking_physics, dropping_physics>;

struct task_definition {
  std::string name;
  std::string variant;  ///< "sim" or "reality" (a stand-in for the real robot, not real data)
  std::string description;
  std::string note;
  std::filesystem::path source;
  std::vector<task_variable> variables;
  std::string success;
  std::vector<named_edge> structure;
  physics_parameters physics;

  [[nodiscard]] bool contains(std::string_view variable_name) const {
    for (const auto& v : variables) {
      if (v.name == variable_name) return true;
    }
    return false;
  }
  /// Position of a variable in the file's order; throws data_error naming the task.
  [[nodiscard]] std::size_t index(std::string_view variable_name) const {
    for (std::size_t i = 0; i < variables.size(); ++i) {
      if (variables[i].name == variable_name) return i;
    }
    throw data_error("task '" + name + "' has no variable '" + std::string(variable_name) + "'");
  }
  [[nodiscard]] const task_variable& at(std::string_view variable_name) const {
    return variables[index(variable_name)];
  }
  [[nodiscard]] std::vector<std::string> names() const {
    std::vector<std::string> result;
    for (const auto& v : variables) result.push_back(v.name);
    return result;
  }
  [[nodiscard]] std::vector<std::string> controllable() const {
    std::vector<std::string> result;
    for (const auto& v : variables) {
      if (v.controllable) result.push_back(v.name);
    }
    return result;
  }
};

namespace detail {

class task_reader : public pgm::detail::json_reader {
 public:
  using json_reader::json_reader;

  task_definition read(const nlohmann::json& doc, const std::filesystem::path& path) const {
    task_definition task;
    task.source = path;
    if (!doc.is_object()) fail("", "expected an object");
    const auto format = string(member(doc, "", "format"), "/format");
    if (format != "pgm-task") fail("/format", "expected \"pgm-task\", found \"" + format + "\"");
    const auto version = number(member(doc, "", "version"), "/version");
    if (version != 1) fail("/version", "version " + pgm::detail::format_double(version) + " is not supported (1 is)");
    task.name = string(member(doc, "", "name"), "/name");
    task.variant = optional_string(doc, "variant", "/variant", "sim");
    if (task.variant != "sim" && task.variant != "reality") fail("/variant", "expected \"sim\" or \"reality\"");
    task.description = optional_string(doc, "description", "/description", "");
    task.note = optional_string(doc, "note", "/note", "");

    const auto& variables = array(member(doc, "", "variables"), "/variables");
    for (std::size_t i = 0; i < variables.size(); ++i) {
      auto v = read_task_variable(variables[i], "/variables/" + std::to_string(i));
      if (task.contains(v.name)) fail("/variables/" + std::to_string(i) + "/name", "'" + v.name + "' appears twice");
      task.variables.push_back(std::move(v));
    }
    if (task.variables.empty()) fail("/variables", "a task needs variables");

    task.success = string(member(doc, "", "success"), "/success");
    if (!task.contains(task.success) || task.at(task.success).kind != variable_kind::outcome) {
      fail("/success", "'" + task.success + "' is not an outcome variable of the task");
    }
    const auto edges = strings(member(doc, "", "structure"), "/structure");
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const auto where = "/structure/" + std::to_string(i);
      std::vector<named_edge> parsed;
      try {
        parsed = parse_edge_list(edges[i]);
      } catch (const model_error& e) {
        fail(where, e.what());
      }
      for (const auto& e : parsed) {
        for (const auto* end : {&e.from, &e.to}) {
          if (!task.contains(*end)) fail(where, "'" + *end + "' is not a variable of the task");
        }
        task.structure.push_back(e);
      }
    }
    task.physics = read_physics(member(doc, "", "physics"), task);
    return task;
  }

 private:
  std::string optional_string(const nlohmann::json& object, const char* key, const std::string& path,
                              std::string fallback) const {
    if (const auto* v = optional_member(object, key)) return string(*v, path);
    return fallback;
  }
  double optional_number(const nlohmann::json& object, const char* key, const std::string& path,
                         double fallback) const {
    if (const auto* v = optional_member(object, key)) return number(*v, path + "/" + key);
    return fallback;
  }
  double positive(const nlohmann::json& object, const char* key, const std::string& path) const {
    const auto value = number(member(object, path, key), path + "/" + key);
    if (!(value > 0) || !std::isfinite(value)) fail(path + "/" + key, "expected a positive number");
    return value;
  }
  double non_negative(const nlohmann::json& object, const char* key, const std::string& path,
                      double fallback) const {
    const auto value = optional_number(object, key, path, fallback);
    if (!(value >= 0) || !std::isfinite(value)) fail(path + "/" + key, "expected a number >= 0");
    return value;
  }

  double time_step(const nlohmann::json& object, const std::string& path, double fallback) const {
    const auto value = optional_number(object, "time_step", path, fallback);
    if (!(value > 0 && value <= 0.05)) fail(path + "/time_step", "expected a step in (0, 0.05] seconds");
    return value;
  }

  task_variable read_task_variable(const nlohmann::json& value, const std::string& path) const {
    task_variable v;
    if (!value.is_object()) fail(path, "expected an object");
    v.name = string(member(value, path, "name"), path + "/name");
    const auto kind = string(member(value, path, "kind"), path + "/kind");
    if (kind == "continuous") {
      v.kind = variable_kind::continuous;
    } else if (kind == "categorical") {
      v.kind = variable_kind::categorical;
    } else if (kind == "outcome") {
      v.kind = variable_kind::outcome;
    } else {
      fail(path + "/kind", "expected \"continuous\", \"categorical\" or \"outcome\", found \"" + kind + "\"");
    }
    v.tags.quantity = optional_string(value, "quantity", path + "/quantity", "");
    v.tags.unit = optional_string(value, "unit", path + "/unit", "");
    v.tags.role = optional_string(value, "role", path + "/role", "");
    if (const auto* c = optional_member(value, "controllable")) {
      if (!c->is_boolean()) fail(path + "/controllable", "expected true or false");
      v.controllable = c->get<bool>();
    }
    v.description = optional_string(value, "description", path + "/description", "");
    if (v.kind != variable_kind::continuous) {
      v.states = strings(member(value, path, "states"), path + "/states");
      if (v.kind == variable_kind::outcome && v.states != std::vector<std::string>{"0", "1"}) {
        fail(path + "/states", "an outcome has the states [\"0\", \"1\"] (1 = success)");
      }
      try {
        (void)v.as_variable();
      } catch (const model_error& e) {
        fail(path, e.what());
      }
    } else if (optional_member(value, "states")) {
      fail(path + "/states", "a continuous variable has no states");
    }
    if (v.kind == variable_kind::outcome) {
      if (optional_member(value, "distribution")) fail(path + "/distribution", "an outcome is simulated, not sampled");
      return v;
    }
    v.sampling = read_distribution(member(value, path, "distribution"), path + "/distribution", v);
    return v;
  }

  distribution read_distribution(const nlohmann::json& value, const std::string& path,
                                 const task_variable& v) const {
    distribution d;
    if (!value.is_object()) fail(path, "expected an object");
    const auto type = string(member(value, path, "type"), path + "/type");
    const auto inf = std::numeric_limits<double>::infinity();
    if (v.kind == variable_kind::categorical) {
      if (type != "categorical") fail(path + "/type", "a categorical variable is sampled from \"categorical\"");
      d.kind = distribution_kind::categorical;
      d.states = v.states.size();
      return d;
    }
    if (type == "normal") {
      d.kind = distribution_kind::normal;
      d.location = number(member(value, path, "mean"), path + "/mean");
      d.scale = positive(value, "sd", path);
      d.min = optional_number(value, "min", path, -inf);
      d.max = optional_number(value, "max", path, inf);
    } else if (type == "uniform") {
      d.kind = distribution_kind::uniform;
      d.min = number(member(value, path, "min"), path + "/min");
      d.max = number(member(value, path, "max"), path + "/max");
    } else if (type == "lognormal") {
      d.kind = distribution_kind::lognormal;
      d.location = number(member(value, path, "mu"), path + "/mu");
      d.scale = positive(value, "sigma", path);
      d.shift = optional_number(value, "shift", path, 0.0);
      d.min = d.shift;
      d.max = optional_number(value, "max", path, inf);
    } else if (type == "grid") {
      d.kind = distribution_kind::grid;
      d.values = numbers(member(value, path, "values"), path + "/values");
      if (d.values.empty()) fail(path + "/values", "a grid needs at least one value");
    } else if (type == "constant") {
      d.kind = distribution_kind::constant;
      d.values = {number(member(value, path, "value"), path + "/value")};
    } else {
      fail(path + "/type", "expected \"normal\", \"uniform\", \"lognormal\", \"grid\" or \"constant\", found \"" +
                               type + "\"");
    }
    if (d.continuous()) {
      if (std::isnan(d.min) || std::isnan(d.max) || !(d.min < d.max)) fail(path, "min must be below max");
      if (d.kind == distribution_kind::uniform && !(std::isfinite(d.min) && std::isfinite(d.max))) {
        fail(path, "a uniform distribution needs finite min and max");
      }
      // Rejection sampling must accept often enough to be quick.
      if (d.raw_cdf(d.max) - d.raw_cdf(d.min) < 0.01) fail(path, "min and max keep less than 1% of the mass");
    }
    return d;
  }

  void require(const task_definition& task, const std::string& name, variable_kind kind,
               const std::string& model) const {
    if (!task.contains(name) || task.at(name).kind != kind) {
      fail("/physics/model", "the model \"" + model + "\" needs the " +
                                 (kind == variable_kind::outcome ? "outcome" : "continuous variable") + " '" +
                                 name + "'");
    }
  }

  physics_parameters read_physics(const nlohmann::json& value, const task_definition& task) const {
    const std::string path = "/physics";
    if (!value.is_object()) fail(path, "expected an object");
    const auto model = string(member(value, path, "model"), path + "/model");
    if (model == "stacking") {
      stacking_physics p;
      p.cubes = 0;
      while (task.contains("onTop" + std::to_string(p.cubes + 1))) ++p.cubes;
      if (p.cubes == 0) fail(path + "/model", "the model \"stacking\" needs the outcome 'onTop1'");
      for (std::size_t i = 1; i <= p.cubes; ++i) {
        const auto n = std::to_string(i);
        for (const auto* stem : {"xOff", "yOff", "dropOff"}) require(task, stem + n, variable_kind::continuous, model);
        require(task, "onTop" + n, variable_kind::outcome, model);
      }
      p.cube_size = positive(value, "cube_size", path);
      p.support_margin = non_negative(value, "support_margin", path, 0.0);
      if (!(p.support_margin < p.cube_size / 2)) fail(path + "/support_margin", "must be below half the cube size");
      const auto& noise = member(value, path, "release_noise");
      p.noise_base = positive(noise, "base", path + "/release_noise");
      p.noise_per_cm = non_negative(noise, "per_cm_drop", path + "/release_noise", 0.0);
      p.friction = non_negative(value, "friction", path, p.friction);
      p.restitution = non_negative(value, "restitution", path, p.restitution);
      p.cube_mass = positive(value, "cube_mass", path);
      p.time_step = time_step(value, path, p.time_step);
      if (const auto* analytic = optional_member(value, "analytic")) {
        const auto at = path + "/analytic";
        if (!analytic->is_object()) fail(at, "expected an object");
        auto pair = [&](const char* key, double& first, double& later) {
          if (const auto* v = optional_member(*analytic, key)) {
            if (!v->is_object()) fail(at + "/" + key, "expected an object with \"first\" and \"later\"");
            first = non_negative(*v, "first", at + "/" + key, first);
            later = non_negative(*v, "later", at + "/" + key, later);
          }
        };
        pair("tipping_margin", p.tipping_margin_first, p.tipping_margin_later);
        pair("settle_noise", p.settle_noise_first, p.settle_noise_later);
        const double edge = p.cube_size / 2 - p.support_margin;
        if (!(p.tipping_margin_first < edge)) fail(at + "/tipping_margin/first", "must be below the supporting half-width");
        if (!(p.tipping_margin_later < edge)) fail(at + "/tipping_margin/later", "must be below the supporting half-width");
      }
      return p;
    }
    if (model == "dropping") {
      for (const auto* name : {"xOff", "yOff", "scalingFactor"}) require(task, name, variable_kind::continuous, model);
      require(task, "inside", variable_kind::outcome, model);
      dropping_physics p;
      p.container = string(member(value, path, "container"), path + "/container");
      p.sphere_diameter = positive(value, "sphere_diameter", path);
      p.drop_height = positive(value, "drop_height", path);
      p.diameter_at_scale_1 = positive(value, "diameter_at_scale_1", path);
      p.height_at_scale_1 = positive(value, "height_at_scale_1", path);
      p.floor_fraction = positive(value, "floor_fraction", path);
      if (p.floor_fraction > 1) fail(path + "/floor_fraction", "expected a number in (0, 1]");
      p.landing_noise = positive(value, "landing_noise", path);
      for (const auto* retired : {"bounce_out", "rim_catch"}) {
        if (optional_member(value, retired)) {
          fail(path + "/" + retired, "is no longer used: the analytic model now resolves the sphere's impact with the "
                                     "container (docs/simulators.md); remove it and fit /physics/analytic with "
                                     "pgm calibrate");
        }
      }
      p.friction = non_negative(value, "friction", path, p.friction);
      p.restitution = non_negative(value, "restitution", path, p.restitution);
      p.sphere_mass = positive(value, "sphere_mass", path);
      p.time_step = time_step(value, path, p.time_step);
      p.impact_restitution = p.restitution;
      if (const auto* analytic = optional_member(value, "analytic")) {
        const auto at = path + "/analytic";
        if (!analytic->is_object()) fail(at, "expected an object");
        p.impact_restitution = non_negative(*analytic, "restitution", at, p.impact_restitution);
        p.impact_tangential = non_negative(*analytic, "tangential", at, p.impact_tangential);
        p.landing_scatter = non_negative(*analytic, "scatter", at, p.landing_scatter);
        p.rim_clearance = optional_number(*analytic, "rim_clearance", at, p.rim_clearance);
        if (p.impact_restitution > 1) fail(at + "/restitution", "expected a number in [0, 1]");
        if (p.impact_tangential > 1) fail(at + "/tangential", "expected a number in [0, 1]");
        if (!std::isfinite(p.rim_clearance)) fail(at + "/rim_clearance", "expected a number");
      }
      const auto& s = task.at("scalingFactor").sampling;
      if (!s.continuous() || !(s.min > 0)) fail("/variables", "scalingFactor must be sampled from positive values");
      return p;
    }
    fail(path + "/model", "expected \"stacking\" or \"dropping\", found \"" + model + "\"");
  }
};

}  // namespace detail

/// Reads a task from JSON text; `source` names it in error messages ("tasks/2-stack.json").
[[nodiscard]] inline task_definition parse_task(std::string_view text, const std::string& source) {
  detail::task_reader reader(source);
  return reader.read(reader.parse(text), source);
}

/// Reads a task file. Errors name the file and the JSON path of the offending key.
[[nodiscard]] inline task_definition load_task(const std::filesystem::path& path) {
  return parse_task(pgm::detail::read_file(path), path.string());
}

/// Where tasks are looked for, in order: $PGM_TASKS_DIR, then the source tree's tasks/ when
/// the program was built with PGM_DEFAULT_TASKS_DIR, then the installed ones
/// (PGM_INSTALLED_TASKS_DIR).
[[nodiscard]] inline std::vector<std::filesystem::path> default_task_directories() {
  std::vector<std::filesystem::path> result;
  if (const char* env = std::getenv("PGM_TASKS_DIR"); env && *env) result.emplace_back(env);
#ifdef PGM_DEFAULT_TASKS_DIR
  result.emplace_back(PGM_DEFAULT_TASKS_DIR);
#endif
#ifdef PGM_INSTALLED_TASKS_DIR
  result.emplace_back(PGM_INSTALLED_TASKS_DIR);
#endif
  return result;
}

/// Names of the tasks (`<name>.json`) in the directories, sorted, without repeats.
[[nodiscard]] inline std::vector<std::string> list_tasks(const std::vector<std::filesystem::path>& directories) {
  std::vector<std::string> names;
  for (const auto& dir : directories) {
    std::error_code ec;
    for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
      if (it->path().extension() == ".json") names.push_back(it->path().stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

/// The file of task `name` in the first directory that has it; throws data_error listing
/// the known tasks otherwise.
[[nodiscard]] inline std::filesystem::path find_task(std::string_view name,
                                                     const std::vector<std::filesystem::path>& directories) {
  if (directories.empty()) {
    throw data_error("no task directory is known; give one with --tasks-dir or PGM_TASKS_DIR");
  }
  for (const auto& dir : directories) {
    const auto candidate = dir / (std::string(name) + ".json");
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
  }
  std::vector<std::string> where;
  for (const auto& dir : directories) where.push_back(dir.string());
  throw data_error("unknown task '" + std::string(name) + "' (known tasks: " +
                   pgm::detail::list_for_message(list_tasks(directories), 40) + "; looked in " +
                   pgm::detail::join(where) + ")");
}

/// Loads task `name` from the first directory that has it.
[[nodiscard]] inline task_definition load_task(std::string_view name,
                                               const std::vector<std::filesystem::path>& directories) {
  return load_task(find_task(name, directories));
}

}  // namespace pgm::sim
