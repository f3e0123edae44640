#pragma once
// The definitions of pgm/sim/task_file.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/sim/task_file.hpp"

namespace pgm::sim::detail {

PGM_DECL task_definition task_reader::read(const nlohmann::json& doc, const std::filesystem::path& path) const {
  task_definition task;
  task.source = path;
  if (!doc.is_object()) fail("", "expected an object");
  const auto format = string(member(doc, "", "format"), "/format");
  if (format != "pgm-task") fail("/format", "expected \"pgm-task\", found \"" + format + "\"");
  const auto version = number(member(doc, "", "version"), "/version");
  if (version != 1) fail("/version", "version " + pgm::text::format_double(version) + " is not supported (1 is)");
  // sample_sizes: free, for people (the paper's sizes of a reality task).
  only_keys(doc, "",
            {"format", "version", "name", "variant", "description", "note", "sample_sizes", "variables", "success",
             "structure", "physics"});
  task.name = string(member(doc, "", "name"), "/name");
  task.variant = optional_string(doc, "variant", "/variant", "sim");
  if (const auto known = known_task_variants(); std::find(known.begin(), known.end(), task.variant) == known.end()) {
    fail("/variant", "expected one of " + pgm::text::join(known));
  }
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
  // The known causal structure is a DAG: an edge that closes a cycle is refused, naming it.
  std::vector<std::string> names;
  for (const auto& v : task.variables) names.push_back(v.name);
  dag graph(names);
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
      try {
        graph.add_edge(e.from, e.to);
      } catch (const not_a_dag& cycle) {
        fail(where, "the structure is not a DAG: " + e.from + " -> " + e.to + " closes the cycle " +
                        pgm::text::join(cycle.cycle(), " -> "));
      } catch (const model_error& problem) {
        fail(where, problem.what());
      }
      task.structure.push_back(e);
    }
  }
  task.physics = read_physics(member(doc, "", "physics"), task);
  return task;
}

PGM_DECL std::string task_reader::optional_string(const nlohmann::json& object, const char* key,
                                                  const std::string& path, std::string fallback) const {
  if (const auto* v = optional_member(object, key)) return string(*v, path);
  return fallback;
}

PGM_DECL double task_reader::optional_number(const nlohmann::json& object, const char* key, const std::string& path,
                                             double fallback) const {
  if (const auto* v = optional_member(object, key)) return number(*v, path + "/" + key);
  return fallback;
}

PGM_DECL double task_reader::positive(const nlohmann::json& object, const char* key, const std::string& path) const {
  const auto value = number(member(object, path, key), path + "/" + key);
  if (!(value > 0) || !std::isfinite(value)) fail(path + "/" + key, "expected a positive number");
  return value;
}

PGM_DECL double task_reader::non_negative(const nlohmann::json& object, const char* key, const std::string& path,
                                          double fallback) const {
  const auto value = optional_number(object, key, path, fallback);
  if (!(value >= 0) || !std::isfinite(value)) fail(path + "/" + key, "expected a number >= 0");
  return value;
}

PGM_DECL double task_reader::time_step(const nlohmann::json& object, const std::string& path, double fallback) const {
  const auto value = optional_number(object, "time_step", path, fallback);
  if (!(value > 0 && value <= 0.05)) fail(path + "/time_step", "expected a step in (0, 0.05] seconds");
  return value;
}

PGM_DECL task_variable task_reader::read_task_variable(const nlohmann::json& value, const std::string& path) const {
  task_variable v;
  if (!value.is_object()) fail(path, "expected an object");
  only_keys(value, path,
            {"name", "kind", "quantity", "unit", "role", "controllable", "description", "states", "distribution"});
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

PGM_DECL distribution task_reader::read_distribution(const nlohmann::json& value, const std::string& path,
                                                     const task_variable& v) const {
  distribution d;
  if (!value.is_object()) fail(path, "expected an object");
  const auto type = string(member(value, path, "type"), path + "/type");
  const auto inf = std::numeric_limits<double>::infinity();
  if (v.kind == variable_kind::categorical) {
    if (type != "categorical") fail(path + "/type", "a categorical variable is sampled from \"categorical\"");
    only_keys(value, path, {"type"});
    d.kind = distribution_kind::categorical;
    d.states = v.states.size();
    return d;
  }
  if (type == "normal") {
    d.kind = distribution_kind::normal;
    only_keys(value, path, {"type", "mean", "sd", "min", "max"});
    d.location = number(member(value, path, "mean"), path + "/mean");
    d.scale = positive(value, "sd", path);
    d.min = optional_number(value, "min", path, -inf);
    d.max = optional_number(value, "max", path, inf);
  } else if (type == "uniform") {
    d.kind = distribution_kind::uniform;
    only_keys(value, path, {"type", "min", "max"});
    d.min = number(member(value, path, "min"), path + "/min");
    d.max = number(member(value, path, "max"), path + "/max");
  } else if (type == "lognormal") {
    d.kind = distribution_kind::lognormal;
    only_keys(value, path, {"type", "mu", "sigma", "shift", "max"});
    d.location = number(member(value, path, "mu"), path + "/mu");
    d.scale = positive(value, "sigma", path);
    d.shift = optional_number(value, "shift", path, 0.0);
    d.min = d.shift;
    d.max = optional_number(value, "max", path, inf);
  } else if (type == "grid") {
    d.kind = distribution_kind::grid;
    only_keys(value, path, {"type", "values"});
    d.values = numbers(member(value, path, "values"), path + "/values");
    if (d.values.empty()) fail(path + "/values", "a grid needs at least one value");
  } else if (type == "constant") {
    d.kind = distribution_kind::constant;
    only_keys(value, path, {"type", "value"});
    d.values = {number(member(value, path, "value"), path + "/value")};
  } else {
    fail(path + "/type",
         "expected \"normal\", \"uniform\", \"lognormal\", \"grid\" or \"constant\", found \"" + type + "\"");
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

PGM_DECL void task_reader::require(const task_definition& task, const std::string& name, variable_kind kind,
                                   const std::string& model) const {
  if (!task.contains(name) || task.at(name).kind != kind) {
    fail("/physics/model", "the model \"" + model + "\" needs the " +
                               (kind == variable_kind::outcome ? "outcome" : "continuous variable") + " '" + name +
                               "'");
  }
}

PGM_DECL physics_parameters task_reader::read_physics(const nlohmann::json& value, const task_definition& task) const {
  const std::string path = "/physics";
  if (!value.is_object()) fail(path, "expected an object");
  const auto model = string(member(value, path, "model"), path + "/model");
  if (model == "stacking") {
    only_keys(value, path,
              {"model", "cube_size", "support_margin", "release_noise", "friction", "restitution", "cube_mass",
               "time_step", "analytic"});
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
    only_keys(noise, path + "/release_noise", {"base", "per_cm_drop"});
    p.noise_base = positive(noise, "base", path + "/release_noise");
    p.noise_per_cm = non_negative(noise, "per_cm_drop", path + "/release_noise", 0.0);
    p.friction = non_negative(value, "friction", path, p.friction);
    p.restitution = non_negative(value, "restitution", path, p.restitution);
    p.cube_mass = positive(value, "cube_mass", path);
    p.time_step = time_step(value, path, p.time_step);
    if (const auto* analytic = optional_member(value, "analytic")) {
      const auto at = path + "/analytic";
      if (!analytic->is_object()) fail(at, "expected an object");
      // note: how pgm calibrate fitted the constants.
      only_keys(*analytic, at, {"tipping_margin", "settle_noise", "note"});
      auto pair = [&](const char* key, double& first, double& later) {
        if (const auto* v = optional_member(*analytic, key)) {
          if (!v->is_object()) fail(at + "/" + key, "expected an object with \"first\" and \"later\"");
          only_keys(*v, at + "/" + key, {"first", "later"});
          first = non_negative(*v, "first", at + "/" + key, first);
          later = non_negative(*v, "later", at + "/" + key, later);
        }
      };
      pair("tipping_margin", p.tipping_margin_first, p.tipping_margin_later);
      pair("settle_noise", p.settle_noise_first, p.settle_noise_later);
      const double edge = p.cube_size / 2 - p.support_margin;
      if (!(p.tipping_margin_first < edge)) {
        fail(at + "/tipping_margin/first", "must be below the supporting half-width");
      }
      if (!(p.tipping_margin_later < edge)) {
        fail(at + "/tipping_margin/later", "must be below the supporting half-width");
      }
    }
    return p;
  }
  if (model == "dropping") {
    for (const auto* name : {"xOff", "yOff", "scalingFactor"}) require(task, name, variable_kind::continuous, model);
    require(task, "inside", variable_kind::outcome, model);
    // bounce_out and rim_catch are known to be refused with the reason below.
    only_keys(value, path,
              {"model", "container", "sphere_diameter", "drop_height", "diameter_at_scale_1", "height_at_scale_1",
               "floor_fraction", "landing_noise", "bounce_out", "rim_catch", "friction", "restitution", "sphere_mass",
               "time_step", "analytic"});
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
        fail(path + "/" + retired,
             "is no longer used: the analytic model now resolves the sphere's impact with the "
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
      only_keys(*analytic, at, {"restitution", "tangential", "scatter", "rim_clearance", "note"});
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

}  // namespace pgm::sim::detail
