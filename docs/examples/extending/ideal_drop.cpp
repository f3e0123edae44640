// A user's own simulator back-end, written outside the library: "ideal-drop" simulates the
// dropping tasks with no landing noise and no bounces — the sphere stays in exactly when its
// centre, released over (xOff, yOff), clears the rim of the opening by its radius. A first model
// to check a pipeline against before real physics. docs/extending.md walks through it.

#include <cmath>
#include <pgm/sim/registry.hpp>
#include <span>
#include <string_view>
#include <variant>

namespace {

class ideal_drop_simulator {
 public:
  // The name the user selects (`simulate_options::backend`, `pgm simulate --backend`).
  static constexpr std::string_view name = "ideal-drop";

  // Built once per worker thread; binds the task's variables by name.
  explicit ideal_drop_simulator(const pgm::sim::task_definition& task)
      : physics_(dropping(task)),
        x_(task.index("xOff")),
        y_(task.index("yOff")),
        scale_(task.index("scalingFactor")),
        inside_(task.index("inside")) {}

  // One experiment: the driver has sampled the inputs into `values` (task order); we write the
  // outcome. Noise would come from `noise` only, which keeps runs reproducible for a seed.
  void run(std::span<double> values, pgm::sim::random_stream& /*noise*/) const {
    const double opening_radius = values[scale_] * physics_.diameter_at_scale_1 / 2;
    const double clearance = opening_radius - physics_.sphere_diameter / 2;
    values[inside_] = std::hypot(values[x_], values[y_]) < clearance ? 1.0 : 0.0;
  }

 private:
  static pgm::sim::dropping_physics dropping(const pgm::sim::task_definition& task) {
    if (const auto* p = std::get_if<pgm::sim::dropping_physics>(&task.physics)) return *p;
    throw pgm::data_error("the ideal-drop back-end simulates dropping tasks; '" + task.name + "' is not one");
  }

  pgm::sim::dropping_physics physics_;
  std::size_t x_, y_, scale_, inside_;
};

static_assert(pgm::sim::Simulator<ideal_drop_simulator>);

// Joins the registry when the program starts: simulate() finds it by name.
const pgm::sim::register_simulator<ideal_drop_simulator> registered;

}  // namespace
