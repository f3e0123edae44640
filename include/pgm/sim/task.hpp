#pragma once
/// \file
/// Task definitions: what a robot task's variables are, how an experiment samples them, which
/// of them the robot controls, which one is success, the known causal structure, and the
/// physical constants its simulators use. Tasks are data — one JSON file per task under
/// `tasks/` (see tasks/README.md) — so that a user can read and change them: `task_file.hpp`
/// reads one file, `task_lookup.hpp` finds a task by name.
///
/// The physics models bind variables by name: "stacking" needs xOff<i>, yOff<i>, dropOff<i>
/// and the outcome onTop<i> for each cube i = 1, 2, …; "dropping" needs xOff, yOff,
/// scalingFactor and the outcome inside.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/core/variable.hpp"
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
  double bounce_max = 0.6;            ///< analytic: chance of bouncing out of a container of depth 0 …
  double bounce_depth_scale = 3.0;    ///< … falling as exp(-height / this)
  double rim_catch = 0.7;             ///< analytic: chance that a sphere landing on the rim of a
                                      ///< container it fits well into (opening ≥ 2 diameters) falls in
  double friction = 0.5;
  double restitution = 0.5;
  double sphere_mass = 0.1;  ///< kg
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

}  // namespace pgm::sim
