// The Bullet back-end. Units are centimetres, seconds and kilograms (gravity 981 cm/s²),
// which keeps Bullet's fixed collision margins (0.04) small beside 5 cm cubes.
//
// Each worker keeps one world and empties it between experiments. Emptying it completely is
// what makes the data independent of which experiments ran before on the same thread (and so
// of the thread count): bodies are made anew for each experiment (no velocities, forces or
// sleeping state carry over), they are added in the same order every time and removed last
// first, which leaves the brute-force broadphase's handle list, the pair cache and the
// dispatcher's contact manifolds (the solver's warm-starting cache) empty and as they were.

#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCollisionCreateFunc.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "pgm/core/assert.hpp"
#include "pgm/sim/bullet.hpp"
#include "pgm/sim/container.hpp"
#include "pgm/sim/registry.hpp"
#include "pgm/sim/run.hpp"

namespace pgm::sim {
// Named (not anonymous) because bullet_simulator::model holds these types.
namespace bullet_detail {

constexpr double gravity = standard_gravity;  // cm/s²
constexpr double rest_time = 0.05;            // s every moving body must stay quiet to count as resting
constexpr double quiet_speed = 0.5;           // cm/s
constexpr double quiet_spin = 0.05;           // rad/s

btVector3 vec(double x, double y, double z) {
  return {static_cast<btScalar>(x), static_cast<btScalar>(y), static_cast<btScalar>(z)};
}

btTransform at(double x, double y, double z) {
  btTransform pose;
  pose.setIdentity();
  pose.setOrigin(vec(x, y, z));
  return pose;
}

/// One worker's physics world: made once, emptied by clear() before every experiment.
class world {
 public:
  /// `time_step`: the fixed step, in seconds.
  explicit world(double time_step)
      : time_step_(time_step),
        configuration_(small_pools()),
        dispatcher_(&configuration_),
        // Fewer than ten bodies: the brute-force broadphase is the quickest, and it keeps no
        // tree whose shape could depend on earlier experiments.
        broadphase_(16),
        dynamics_(&dispatcher_, &broadphase_, &solver_, &configuration_) {
    dynamics_.setGravity(vec(0, 0, -gravity));
  }
  world(const world&) = delete;
  world& operator=(const world&) = delete;
  ~world() { clear(); }

  /// Removes every body, last added first, and resets the solver: the state of a new world.
  void clear() {
    for (auto it = bodies_.rbegin(); it != bodies_.rend(); ++it) dynamics_.removeRigidBody(it->get());
    bodies_.clear();
    moving_.clear();
    static_cast<btBroadphaseInterface&>(broadphase_).resetPool(&dispatcher_);
    solver_.reset();
    PGM_ASSERT(dispatcher_.getNumManifolds() == 0, "contact manifolds left from the previous experiment");
    PGM_ASSERT(broadphase_.getOverlappingPairCache()->getNumOverlappingPairs() == 0, "pairs left in the cache");
  }

  /// Adds a body; `rolling_friction` (cm) resists rolling, for a sphere: a cube's tipping is
  /// left to its shape.
  btRigidBody* add(btCollisionShape* shape, double mass, const btTransform& pose, double friction, double restitution,
                   double rolling_friction = 0.0) {
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape->calculateLocalInertia(static_cast<btScalar>(mass), inertia);
    btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(mass), nullptr, shape, inertia);
    info.m_startWorldTransform = pose;
    info.m_friction = static_cast<btScalar>(friction);
    info.m_restitution = static_cast<btScalar>(restitution);
    info.m_rollingFriction = static_cast<btScalar>(rolling_friction);
    info.m_angularDamping = mass > 0 ? btScalar(0.2) : btScalar(0.0);
    bodies_.push_back(std::make_unique<btRigidBody>(info));
    auto* body = bodies_.back().get();
    if (mass > 0) {
      // Rest is detected below (settle), for the whole world at once; Bullet's own sleeping
      // waits 2 s and is set by a process-wide global.
      body->setActivationState(DISABLE_DEACTIVATION);
      moving_.push_back(body);
    }
    dynamics_.addRigidBody(body);
    return body;
  }

  /// Steps until every moving body has been quiet for rest_time or `decided()` says the
  /// outcome is known, at most `seconds`.
  btCollisionDispatcher& dispatcher() { return dispatcher_; }

  template <class Decided>
  void settle(double seconds, Decided decided) {
    const int cap = static_cast<int>(seconds / time_step_);
    const int rest_steps = static_cast<int>(std::ceil(rest_time / time_step_));
    int quiet = 0;
    for (int step = 0; step < cap && quiet < rest_steps; ++step) {
      dynamics_.stepSimulation(static_cast<btScalar>(time_step_), 0, static_cast<btScalar>(time_step_));
      if (decided()) break;
      bool still = true;
      for (const auto* body : moving_) {
        still = still && body->getLinearVelocity().length2() < quiet_speed * quiet_speed &&
                body->getAngularVelocity().length2() < quiet_spin * quiet_spin;
      }
      quiet = still ? quiet + 1 : 0;
    }
  }

 private:
  static btDefaultCollisionConstructionInfo small_pools() {
    btDefaultCollisionConstructionInfo info;
    info.m_defaultMaxPersistentManifoldPoolSize = 64;
    info.m_defaultMaxCollisionAlgorithmPoolSize = 64;
    return info;
  }

  double time_step_;
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btSimpleBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld dynamics_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::vector<btRigidBody*> moving_;
};

/// How far a body's local z axis is tilted from the world's (cosine).
double upright(const btRigidBody* body) { return std::abs(body->getWorldTransform().getBasis()[2][2]); }

/// Gives `body` the downward speed of a free fall through `height` (there is no air drag), so
/// that a body released close above what it lands on needs no steps for the fall before.
void fallen_through(btRigidBody* body, double height) {
  body->setLinearVelocity(vec(0, 0, -std::sqrt(2 * gravity * std::max(0.0, height))));
}

/// Position and rotation (quaternion x, y, z, w) of each body.
std::vector<std::array<double, 7>> poses_of(const std::vector<btRigidBody*>& bodies) {
  std::vector<std::array<double, 7>> result;
  for (const auto* b : bodies) {
    const auto& t = b->getWorldTransform();
    const auto q = t.getRotation();
    result.push_back({t.getOrigin().x(), t.getOrigin().y(), t.getOrigin().z(), q.x(), q.y(), q.z(), q.w()});
  }
  return result;
}

class stacking_world_simulator {
 public:
  explicit stacking_world_simulator(const task_definition& task)
      : p_(std::get<stacking_physics>(task.physics)), cube_(vec(p_.cube_size / 2, p_.cube_size / 2, p_.cube_size / 2)) {
    for (std::size_t i = 1; i <= p_.cubes; ++i) {
      const auto n = std::to_string(i);
      columns_.push_back(
          {task.index("xOff" + n), task.index("yOff" + n), task.index("dropOff" + n), task.index("onTop" + n)});
    }
    // Rounded edges (support_margin) are modelled as a larger collision margin.
    cube_.setMargin(static_cast<btScalar>(std::max(0.04, p_.support_margin)));
  }

  void run(std::span<double> values, random_stream& noise) {
    const double size = p_.cube_size;
    world_.clear();
    world_.add(&ground_, 0, at(0, 0, 0), p_.friction, 1.0);
    // cubeDown is fixed: the task is about the cubes placed on it.
    world_.add(&cube_, 0, at(0, 0, size / 2), p_.friction, 1.0);
    double below_x = 0, below_y = 0, below_top = size;
    bool standing = true;
    auto& placed = placed_;  // the cubes released so far, bottom first
    placed.clear();
    for (std::size_t i = 0; i < columns_.size(); ++i) {
      const auto& c = columns_[i];
      const double sd = p_.noise_base + p_.noise_per_cm * values[c.drop];
      const double x = values[c.x] + sd * noise.normal();
      const double y = values[c.y] + sd * noise.normal();
      if (!standing) {
        values[c.on_top] = 0;
        continue;
      }
      const double drop = values[c.drop];
      const double gap = std::min(drop, release_gap);
      auto* cube = world_.add(&cube_, p_.cube_mass, at(below_x + x, below_y + y, below_top + gap + size / 2),
                              p_.friction, p_.restitution);
      fallen_through(cube, drop - gap);
      placed.push_back(cube);
      // Decided once a cube's centre is a quarter of its size below where it would rest: it
      // has slid or tipped off, and the check below would fail however it ends.
      world_.settle(3.0, [&] {
        for (std::size_t k = 0; k < placed.size(); ++k) {
          if (placed[k]->getWorldTransform().getOrigin().z() < (static_cast<double>(k) + 1.25) * size) return true;
        }
        return false;
      });
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

  [[nodiscard]] std::vector<std::array<double, 7>> poses() const { return poses_of(placed_); }

 private:
  struct cube_columns {
    std::size_t x, y, drop, on_top;
  };
  static constexpr double release_gap = 0.001;  // cm between a released cube and what it lands on

  stacking_physics p_;
  btStaticPlaneShape ground_{btVector3(0, 0, 1), 0};
  btBoxShape cube_;
  std::vector<cube_columns> columns_;
  world world_{p_.time_step};
  std::vector<btRigidBody*> placed_;
};

/// The container (pgm/sim/container.hpp's profile) as a Bullet shape. Contacts with a
/// sphere are computed by sphere_container_algorithm from the profile, exactly: unlike a
/// compound of flat panels it has no creases where a sphere touches two faces at once, which
/// made the outcome of such landings depend on the time step.
class container_shape final : public btCollisionShape {
 public:
  container_shape() { m_shapeType = CUSTOM_CONCAVE_SHAPE_TYPE; }

  void reshape(const dropping_physics& p, double scale) { profile_.emplace(p, scale); }
  [[nodiscard]] const container_profile& profile() const { return *profile_; }

  void getAabb(const btTransform& t, btVector3& lo, btVector3& hi) const override {
    const double extent = profile_->extent();
    lo = t.getOrigin() + vec(-extent, -extent, 0);
    hi = t.getOrigin() + vec(extent, extent, profile_->top());
  }
  void setLocalScaling(const btVector3&) override {}
  [[nodiscard]] const btVector3& getLocalScaling() const override { return unit_; }
  void calculateLocalInertia(btScalar, btVector3& inertia) const override { inertia.setZero(); }
  [[nodiscard]] const char* getName() const override { return "container"; }
  void setMargin(btScalar) override {}
  [[nodiscard]] btScalar getMargin() const override { return 0; }

 private:
  std::optional<container_profile> profile_;
  btVector3 unit_{1, 1, 1};
};

/// Sphere against container_shape (the container is static and not rotated).
class sphere_container_algorithm final : public btActivatingCollisionAlgorithm {
 public:
  sphere_container_algorithm(const btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* a,
                             const btCollisionObjectWrapper* b, bool swapped)
      : btActivatingCollisionAlgorithm(info, a, b), swapped_(swapped) {
    const auto* sphere = swapped ? b : a;
    const auto* container = swapped ? a : b;
    manifold_ = m_dispatcher->getNewManifold(sphere->getCollisionObject(), container->getCollisionObject());
  }
  ~sphere_container_algorithm() override { m_dispatcher->releaseManifold(manifold_); }
  sphere_container_algorithm(const sphere_container_algorithm&) = delete;
  sphere_container_algorithm& operator=(const sphere_container_algorithm&) = delete;

  void processCollision(const btCollisionObjectWrapper* a, const btCollisionObjectWrapper* b, const btDispatcherInfo&,
                        btManifoldResult* result) override {
    const auto* sphere_wrap = swapped_ ? b : a;
    const auto* container_wrap = swapped_ ? a : b;
    const auto& shape = static_cast<const container_shape*>(container_wrap->getCollisionShape())->profile();
    const double r = static_cast<const btSphereShape*>(sphere_wrap->getCollisionShape())->getRadius();
    const btVector3 base = container_wrap->getWorldTransform().getOrigin();
    const btVector3 c = sphere_wrap->getWorldTransform().getOrigin() - base;
    const double rho = std::hypot(c.x(), c.y());
    // The meridian plane's horizontal direction; any on the axis itself.
    const double cos_phi = rho > 1e-9 ? c.x() / rho : 1.0;
    const double sin_phi = rho > 1e-9 ? c.y() / rho : 0.0;
    const double half = shape.wall() / 2;
    const double breaking = manifold_->getContactBreakingThreshold();
    result->setPersistentManifold(manifold_);
    std::array<container_profile::nearest_point, 3> found{};
    const int n = shape.nearest(rho, c.z(), r + half + breaking, found);
    for (int k = 0; k < n; ++k) {
      const auto& f = found[static_cast<std::size_t>(k)];
      const btVector3 normal = vec(f.normal_rho * cos_phi, f.normal_rho * sin_phi, f.normal_z);
      const btVector3 on_surface = base + vec((f.rho + half * f.normal_rho) * cos_phi,
                                              (f.rho + half * f.normal_rho) * sin_phi, f.z + half * f.normal_z);
      result->addContactPoint(normal, on_surface, static_cast<btScalar>(f.distance - r - half));
    }
    if (manifold_->getNumContacts()) result->refreshContactPoints();
  }

  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return 1;
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override { manifolds.push_back(manifold_); }

  struct create final : btCollisionAlgorithmCreateFunc {
    explicit create(bool swapped) { m_swapped = swapped; }
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                   const btCollisionObjectWrapper* a,
                                                   const btCollisionObjectWrapper* b) override {
      void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(sphere_container_algorithm));
      return new (memory) sphere_container_algorithm(info, a, b, m_swapped);
    }
  };

 private:
  btPersistentManifold* manifold_ = nullptr;
  bool swapped_;
};

class dropping_world_simulator {
 public:
  explicit dropping_world_simulator(const task_definition& task)
      : p_(std::get<dropping_physics>(task.physics)),
        sphere_(static_cast<btScalar>(p_.sphere_diameter / 2)),
        x_(task.index("xOff")),
        y_(task.index("yOff")),
        scale_(task.index("scalingFactor")),
        inside_(task.index("inside")) {
    world_.dispatcher().registerCollisionCreateFunc(SPHERE_SHAPE_PROXYTYPE, CUSTOM_CONCAVE_SHAPE_TYPE, &sphere_first_);
    world_.dispatcher().registerCollisionCreateFunc(CUSTOM_CONCAVE_SHAPE_TYPE, SPHERE_SHAPE_PROXYTYPE,
                                                    &container_first_);
  }

  void run(std::span<double> values, random_stream& noise) {
    const double r = p_.sphere_diameter / 2;
    const double x = values[x_] + p_.landing_noise * noise.normal();
    const double y = values[y_] + p_.landing_noise * noise.normal();
    world_.clear();  // before the container's shape changes
    container_.reshape(p_, values[scale_]);
    world_.add(&ground_, 0, at(0, 0, 0), p_.friction, 1.0);
    world_.add(&container_, 0, at(0, 0, 0), p_.friction, 1.0);
    // The sphere falls straight down until it first touches the container or the table:
    // start it there, with the speed of that fall, so that the first impact is resolved
    // where it happens whatever the time step.
    const auto& profile = container_.profile();
    const double rim = profile.height();
    const auto touch = profile.first_touch(std::hypot(x, y));
    const double start = std::min(touch.hit ? touch.z : r, p_.drop_height + r);
    sphere_body_ = world_.add(&sphere_, p_.sphere_mass, at(x, y, start), p_.friction, p_.restitution, 0.02);
    fallen_through(sphere_body_, p_.drop_height + r - start);
    auto* sphere = sphere_body_;
    const double opening = profile.radius();
    const double out = profile.extent() + r + 1.0;
    // Decided once the sphere lies on the table beyond the rim, or is within the opening
    // without the energy (moving and spinning) to lift its centre over the rim.
    world_.settle(4.0, [&] {
      const auto o = sphere->getWorldTransform().getOrigin();
      const double rho = std::hypot(o.x(), o.y());
      if (o.z() < r + 0.5 && rho > out) return true;
      const double v2 = sphere->getLinearVelocity().length2();
      const double w2 = sphere->getAngularVelocity().length2();
      const double reach = (v2 + 0.4 * r * r * w2) / (2 * gravity);
      return rho < opening && o.z() + reach < rim + r;
    });
    const auto o = sphere->getWorldTransform().getOrigin();
    values[inside_] = std::hypot(o.x(), o.y()) < opening && o.z() < rim + r ? 1.0 : 0.0;
  }

  [[nodiscard]] std::vector<std::array<double, 7>> poses() const { return poses_of({sphere_body_}); }

 private:
  dropping_physics p_;
  btStaticPlaneShape ground_{btVector3(0, 0, 1), 0};
  btSphereShape sphere_;
  container_shape container_;
  sphere_container_algorithm::create sphere_first_{false}, container_first_{true};
  std::size_t x_, y_, scale_, inside_;
  world world_{p_.time_step};  // last: emptied and gone before the shapes and collision functions it uses
  btRigidBody* sphere_body_ = nullptr;
};

}  // namespace bullet_detail

/// Dispatches to the task's physics model.
struct bullet_simulator::model {
  std::unique_ptr<bullet_detail::stacking_world_simulator> stacking;
  std::unique_ptr<bullet_detail::dropping_world_simulator> dropping;
};

bullet_simulator::bullet_simulator(const task_definition& task) : model_(std::make_unique<model>()) {
  if (std::holds_alternative<stacking_physics>(task.physics)) {
    model_->stacking = std::make_unique<bullet_detail::stacking_world_simulator>(task);
  } else {
    model_->dropping = std::make_unique<bullet_detail::dropping_world_simulator>(task);
  }
}

bullet_simulator::~bullet_simulator() = default;
bullet_simulator::bullet_simulator(bullet_simulator&&) noexcept = default;
bullet_simulator& bullet_simulator::operator=(bullet_simulator&&) noexcept = default;

void bullet_simulator::run(std::span<double> values, random_stream& noise) {
  if (model_->stacking) {
    model_->stacking->run(values, noise);
  } else {
    model_->dropping->run(values, noise);
  }
}

std::vector<std::array<double, 7>> bullet_simulator::final_poses() const {
  return model_->stacking ? model_->stacking->poses() : model_->dropping->poses();
}

static_assert(Simulator<bullet_simulator>);

dataset simulate_bullet(const task_definition& task, const simulate_options& options) {
  return run_experiments<bullet_simulator>(task, options, 8);
}

namespace {
// Offers "bullet" to simulate() and `pgm simulate --backend bullet` when this object is linked.
const register_backend registered("bullet", &simulate_bullet);
}  // namespace

}  // namespace pgm::sim
