// The Bullet back-end. Units are centimetres, seconds and kilograms (gravity 981 cm/s²),
// which keeps Bullet's fixed collision margins (0.04) small beside 5 cm cubes.
//
// Each experiment builds a fresh world, so no solver or broadphase state carries over from
// one experiment to the next: the outcome depends only on the experiment's own inputs and
// noise stream, whatever thread runs it.

#include "pgm/sim/bullet.hpp"

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "pgm/sim/registry.hpp"
#include "pgm/sim/run.hpp"

namespace pgm::sim {
namespace {

constexpr double gravity = 981.0;       // cm/s²
constexpr double time_step = 1.0 / 240;  // s
constexpr int rest_steps = 12;           // consecutive quiet steps that count as rest

/// A world with its own dispatcher, broadphase and solver; bodies are owned here.
class world {
 public:
  world()
      : dispatcher_(&configuration_),
        dynamics_(&dispatcher_, &broadphase_, &solver_, &configuration_) {
    dynamics_.setGravity(btVector3(0, 0, static_cast<btScalar>(-gravity)));
  }
  world(const world&) = delete;
  world& operator=(const world&) = delete;
  ~world() {
    for (auto& body : bodies_) dynamics_.removeRigidBody(body.get());
  }

  btRigidBody* add(btCollisionShape* shape, double mass, const btTransform& pose, double friction,
                   double restitution) {
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape->calculateLocalInertia(static_cast<btScalar>(mass), inertia);
    btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(mass), nullptr, shape, inertia);
    info.m_startWorldTransform = pose;
    info.m_friction = static_cast<btScalar>(friction);
    info.m_restitution = static_cast<btScalar>(restitution);
    info.m_rollingFriction = mass > 0 ? btScalar(0.02) : btScalar(0.0);
    info.m_angularDamping = mass > 0 ? btScalar(0.2) : btScalar(0.0);
    bodies_.push_back(std::make_unique<btRigidBody>(info));
    auto* body = bodies_.back().get();
    if (mass > 0) body->setActivationState(DISABLE_DEACTIVATION);
    dynamics_.addRigidBody(body);
    return body;
  }

  /// Steps until `body` rests (or `stop` says the outcome is decided), at most `seconds`.
  template <class Stop>
  void settle(btRigidBody* body, double seconds, Stop stop) {
    const int cap = static_cast<int>(seconds / time_step);
    int quiet = 0;
    for (int step = 0; step < cap && quiet < rest_steps; ++step) {
      dynamics_.stepSimulation(static_cast<btScalar>(time_step), 0, static_cast<btScalar>(time_step));
      const bool still = body->getLinearVelocity().length() < 0.5 && body->getAngularVelocity().length() < 0.05;
      quiet = still ? quiet + 1 : 0;
      if (stop()) break;
    }
  }

 private:
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld dynamics_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
};

btTransform at(double x, double y, double z) {
  btTransform pose;
  pose.setIdentity();
  pose.setOrigin(btVector3(static_cast<btScalar>(x), static_cast<btScalar>(y), static_cast<btScalar>(z)));
  return pose;
}

/// How far a body's local z axis is tilted from the world's (cosine).
double upright(const btRigidBody* body) { return std::abs(body->getWorldTransform().getBasis()[2][2]); }

class stacking_world_simulator {
 public:
  explicit stacking_world_simulator(const task_definition& task)
      : p_(std::get<stacking_physics>(task.physics)),
        cube_(btVector3(static_cast<btScalar>(p_.cube_size / 2), static_cast<btScalar>(p_.cube_size / 2),
                        static_cast<btScalar>(p_.cube_size / 2))) {
    for (std::size_t i = 1; i <= p_.cubes; ++i) {
      const auto n = std::to_string(i);
      columns_.push_back({task.index("xOff" + n), task.index("yOff" + n), task.index("dropOff" + n),
                          task.index("onTop" + n)});
    }
    // Rounded edges (support_margin) are modelled as a larger collision margin.
    cube_.setMargin(static_cast<btScalar>(std::max(0.04, p_.support_margin)));
  }

  void run(std::span<double> values, random_stream& noise) {
    const double size = p_.cube_size;
    world w;
    w.add(&ground_, 0, at(0, 0, 0), p_.friction, 1.0);
    // cubeDown is fixed: the task is about the cubes placed on it.
    w.add(&cube_, 0, at(0, 0, size / 2), p_.friction, 1.0);
    double below_x = 0, below_y = 0, below_top = size;
    bool standing = true;
    std::vector<btRigidBody*> placed;
    for (std::size_t i = 0; i < columns_.size(); ++i) {
      const auto& c = columns_[i];
      const double sd = p_.noise_base + p_.noise_per_cm * values[c.drop];
      const double x = values[c.x] + sd * noise.normal();
      const double y = values[c.y] + sd * noise.normal();
      if (!standing) {
        values[c.on_top] = 0;
        continue;
      }
      auto* cube = w.add(&cube_, p_.cube_mass, at(below_x + x, below_y + y, below_top + values[c.drop] + size / 2),
                         p_.friction, p_.restitution);
      placed.push_back(cube);
      w.settle(cube, 3.0, [] { return false; });
      // Every cube placed so far must still sit on the one below it, upright.
      bool holds = true;
      double top = size;
      double bx = 0, by = 0;
      for (auto* b : placed) {
        const auto o = b->getWorldTransform().getOrigin();
        holds = holds && std::abs(o.z() - (top + size / 2)) < 0.25 * size && upright(b) > 0.95 &&
                std::abs(o.x() - bx) < size && std::abs(o.y() - by) < size;
        top += size;
        bx = o.x();
        by = o.y();
      }
      values[c.on_top] = holds ? 1.0 : 0.0;
      standing = holds;
      const auto o = cube->getWorldTransform().getOrigin();
      below_x = o.x();
      below_y = o.y();
      below_top = o.z() + size / 2;
    }
  }

 private:
  struct cube_columns {
    std::size_t x, y, drop, on_top;
  };
  stacking_physics p_;
  btStaticPlaneShape ground_{btVector3(0, 0, 1), 0};
  btBoxShape cube_;
  std::vector<cube_columns> columns_;
};

/// A container as a compound of boxes: a round floor and a ring of wall panels that follow
/// the profile from the floor's edge up to the rim.
class container_shape {
 public:
  container_shape(const dropping_physics& p, double scale) {
    radius_ = scale * p.diameter_at_scale_1 / 2;
    height_ = scale * p.height_at_scale_1;
    const double floor_radius = p.floor_fraction * radius_;
    const double floor_thickness = std::min(1.0, height_ / 3);
    const double wall = 0.8;
    parts_.push_back(std::make_unique<btCylinderShapeZ>(btVector3(
        static_cast<btScalar>(floor_radius + wall), static_cast<btScalar>(floor_radius + wall),
        static_cast<btScalar>(floor_thickness / 2))));
    compound_.addChildShape(at(0, 0, floor_thickness / 2), parts_.back().get());
    const int panels = 24;
    const double rise = height_ - floor_thickness;
    const double run = radius_ - floor_radius;
    const double slant = std::hypot(run, rise);
    const double tilt = std::atan2(run, rise);  // from vertical, top leaning outwards
    const double mid_radius = (floor_radius + radius_) / 2;
    const double half_width = 1.15 * std::numbers::pi * (radius_ + wall) / panels;
    for (int k = 0; k < panels; ++k) {
      const double angle = 2 * std::numbers::pi * k / panels;
      parts_.push_back(std::make_unique<btBoxShape>(btVector3(static_cast<btScalar>(wall / 2),
                                                              static_cast<btScalar>(half_width),
                                                              static_cast<btScalar>(slant / 2))));
      btQuaternion around(btVector3(0, 0, 1), static_cast<btScalar>(angle));
      btQuaternion lean(btVector3(0, 1, 0), static_cast<btScalar>(tilt));
      // The inner face lies on the profile: move the panel's centre out along its normal.
      const double r = mid_radius + (wall / 2) * std::cos(tilt);
      const double z = floor_thickness + rise / 2 - (wall / 2) * std::sin(tilt);
      btTransform pose(around * lean,
                       btVector3(static_cast<btScalar>(r * std::cos(angle)), static_cast<btScalar>(r * std::sin(angle)),
                                 static_cast<btScalar>(z)));
      compound_.addChildShape(pose, parts_.back().get());
    }
  }
  container_shape(const container_shape&) = delete;
  container_shape& operator=(const container_shape&) = delete;

  btCompoundShape* shape() { return &compound_; }
  [[nodiscard]] double radius() const { return radius_; }
  [[nodiscard]] double height() const { return height_; }

 private:
  std::vector<std::unique_ptr<btCollisionShape>> parts_;
  btCompoundShape compound_;
  double radius_ = 0, height_ = 0;
};

class dropping_world_simulator {
 public:
  explicit dropping_world_simulator(const task_definition& task)
      : p_(std::get<dropping_physics>(task.physics)),
        sphere_(static_cast<btScalar>(p_.sphere_diameter / 2)),
        x_(task.index("xOff")),
        y_(task.index("yOff")),
        scale_(task.index("scalingFactor")),
        inside_(task.index("inside")) {}

  void run(std::span<double> values, random_stream& noise) {
    const double r = p_.sphere_diameter / 2;
    const double x = values[x_] + p_.landing_noise * noise.normal();
    const double y = values[y_] + p_.landing_noise * noise.normal();
    container_shape container(p_, values[scale_]);
    world w;
    w.add(&ground_, 0, at(0, 0, 0), p_.friction, 1.0);
    w.add(container.shape(), 0, at(0, 0, 0), p_.friction, 1.0);
    // Start just above the rim with the speed of a fall from drop_height (no air drag), which
    // saves simulating most of the fall.
    const double start = std::min(container.height() + r + 1.0, p_.drop_height + r);
    auto* sphere = w.add(&sphere_, p_.sphere_mass, at(x, y, start), p_.friction, p_.restitution);
    sphere->setLinearVelocity(
        btVector3(0, 0, static_cast<btScalar>(-std::sqrt(2 * gravity * (p_.drop_height + r - start)))));
    const double out = container.radius() + r + 1.0;
    auto position = [&] { return sphere->getWorldTransform().getOrigin(); };
    // Decided once the sphere lies on the table beyond the rim, or is within the opening
    // without the energy to lift its centre to the rim again.
    const double rim = container.height();
    w.settle(sphere, 4.0, [&] {
      const auto o = position();
      const double rho = std::hypot(o.x(), o.y());
      if (o.z() < r + 0.5 && rho > out) return true;
      const double v = sphere->getLinearVelocity().length();
      return rho < container.radius() && o.z() + v * v / (2 * gravity) < rim;
    });
    const auto o = position();
    values[inside_] = std::hypot(o.x(), o.y()) < container.radius() && o.z() < container.height() + r ? 1.0 : 0.0;
  }

 private:
  dropping_physics p_;
  btStaticPlaneShape ground_{btVector3(0, 0, 1), 0};
  btSphereShape sphere_;
  std::size_t x_, y_, scale_, inside_;
};

/// Dispatches to the task's physics model; one per worker thread.
class bullet_simulator {
 public:
  static constexpr std::string_view name = "bullet";

  explicit bullet_simulator(const task_definition& task) {
    if (std::holds_alternative<stacking_physics>(task.physics)) {
      stacking_ = std::make_unique<stacking_world_simulator>(task);
    } else {
      dropping_ = std::make_unique<dropping_world_simulator>(task);
    }
  }
  void run(std::span<double> values, random_stream& noise) {
    if (stacking_) {
      stacking_->run(values, noise);
    } else {
      dropping_->run(values, noise);
    }
  }

 private:
  std::unique_ptr<stacking_world_simulator> stacking_;
  std::unique_ptr<dropping_world_simulator> dropping_;
};

static_assert(Simulator<bullet_simulator>);

}  // namespace

dataset simulate_bullet(const task_definition& task, const simulate_options& options) {
  return run_experiments<bullet_simulator>(task, options, 8);
}

namespace {
// Offers "bullet" to simulate() and `pgm simulate --backend bullet` when this object is linked.
const register_backend registered("bullet", &simulate_bullet);
}  // namespace

}  // namespace pgm::sim
