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

#include "pgm/core/compilation.hpp"
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

/// The state of an outcome that is success.
inline constexpr const char* outcome_success_state = "1";

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

/// The variants of a task: "sim", and "reality", the stacking tasks' stand-in for the real
/// robot (not real data). Task files, `pgm simulate --variant` and Python check against them.
[[nodiscard]] inline std::vector<std::string> known_task_variants() { return {"sim", "reality"}; }

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

  [[nodiscard]] PGM_DECL bool contains(std::string_view variable_name) const;
  /// Position of a variable in the file's order; throws data_error naming the task.
  [[nodiscard]] PGM_DECL std::size_t index(std::string_view variable_name) const;
  [[nodiscard]] const task_variable& at(std::string_view variable_name) const {
    return variables[index(variable_name)];
  }
  [[nodiscard]] PGM_DECL std::vector<std::string> names() const;
  [[nodiscard]] PGM_DECL std::vector<std::string> controllable() const;
};

}  // namespace pgm::sim

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/sim/impl/task.ipp"
#endif
