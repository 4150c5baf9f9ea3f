// The Bullet rigid-body world.
#include "sim/bullet_world.hpp"

#include <btBulletDynamicsCommon.h>
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace corrmp {

namespace {

// Bullet's default collision margin (4 cm) is larger than the small bodies of
// a table-top scene; a millimetre keeps contacts where the geometry is.
constexpr double kCollisionMargin = 0.001;

std::unique_ptr<btCollisionShape> make_shape(const SceneBodySpec& spec) {
  const auto& s = spec.size;
  std::unique_ptr<btCollisionShape> shape;
  if (spec.shape == "box") {
    shape = std::make_unique<btBoxShape>(btVector3(s[0] / 2, s[1] / 2, s[2] / 2));
  } else if (spec.shape == "cylinder") {
    shape = std::make_unique<btCylinderShapeZ>(btVector3(s[0], s[0], s[1] / 2));
  } else if (spec.shape == "capsule") {
    shape = std::make_unique<btCapsuleShapeZ>(s[0], s[1]);
  } else if (spec.shape == "sphere") {
    shape = std::make_unique<btSphereShape>(s[0]);
  } else {
    throw std::invalid_argument(
        fmt::format("body '{}': unknown shape '{}'", spec.name, spec.shape));
  }
  shape->setMargin(kCollisionMargin);
  return shape;
}

btTransform to_bullet(const Eigen::Isometry3d& pose) {
  const Eigen::Quaterniond q(pose.rotation());
  const Eigen::Vector3d t = pose.translation();
  return btTransform(btQuaternion(q.x(), q.y(), q.z(), q.w()), btVector3(t.x(), t.y(), t.z()));
}

Eigen::Isometry3d from_bullet(const btTransform& transform) {
  const btQuaternion q = transform.getRotation();
  const btVector3 t = transform.getOrigin();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(t.x(), t.y(), t.z());
  return pose;
}

Eigen::Isometry3d spec_pose(const SceneBodySpec& spec) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd(spec.rpy[2], Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(spec.rpy[1], Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(spec.rpy[0], Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  pose.translation() = spec.position_vector();
  return pose;
}

}  // namespace

BulletWorld::BulletWorld(const PhysicsParams& params)
    : params_(params),
      configuration_(std::make_unique<btDefaultCollisionConfiguration>()),
      dispatcher_(std::make_unique<btCollisionDispatcher>(configuration_.get())),
      broadphase_(std::make_unique<btDbvtBroadphase>()),
      solver_(std::make_unique<btSequentialImpulseConstraintSolver>()),
      world_(std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(),
                                                       solver_.get(), configuration_.get())) {
  world_->setGravity(btVector3(0, 0, -params.gravity));
  world_->getSolverInfo().m_numIterations = params.solver_iterations;
}

BulletWorld::~BulletWorld() {
  for (auto& body : bodies_) world_->removeRigidBody(body.get());
}

int BulletWorld::add_body(const SceneBodySpec& spec, bool kinematic) {
  if (find(spec.name) >= 0) {
    throw std::invalid_argument(fmt::format("duplicate body name '{}'", spec.name));
  }
  auto shape = make_shape(spec);
  const double mass = kinematic ? 0.0 : spec.mass;
  btVector3 inertia(0, 0, 0);
  if (mass > 0) shape->calculateLocalInertia(mass, inertia);
  btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shape.get(), inertia);
  info.m_startWorldTransform = to_bullet(spec_pose(spec));
  info.m_friction = spec.friction;
  info.m_restitution = spec.restitution;
  auto body = std::make_unique<btRigidBody>(info);
  if (kinematic) {
    body->setCollisionFlags(body->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
  }
  body->setActivationState(DISABLE_DEACTIVATION);
  world_->addRigidBody(body.get());
  shapes_.push_back(std::move(shape));
  bodies_.push_back(std::move(body));
  infos_.push_back(BodyInfo{spec.name, spec.shape, spec.size,
                            Eigen::Vector3f(spec.colour[0], spec.colour[1], spec.colour[2]),
                            kinematic});
  return static_cast<int>(bodies_.size()) - 1;
}

int BulletWorld::add_scene(const SceneDescription& scene) {
  const int first = body_count();
  for (const auto& spec : scene.bodies) add_body(spec);
  return first;
}

int BulletWorld::find(const std::string& name) const {
  for (size_t i = 0; i < infos_.size(); ++i) {
    if (infos_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

void BulletWorld::set_pose(int body, const Eigen::Isometry3d& pose) {
  bodies_.at(body)->setWorldTransform(to_bullet(pose));
}

Eigen::Isometry3d BulletWorld::pose(int body) const {
  return from_bullet(bodies_.at(body)->getWorldTransform());
}

Eigen::Vector3d BulletWorld::linear_velocity(int body) const {
  const btVector3 v = bodies_.at(body)->getLinearVelocity();
  return {v.x(), v.y(), v.z()};
}

void BulletWorld::place(int body, const Eigen::Isometry3d& pose) {
  btRigidBody& b = *bodies_.at(body);
  b.setWorldTransform(to_bullet(pose));
  b.setInterpolationWorldTransform(b.getWorldTransform());
  b.setLinearVelocity(btVector3(0, 0, 0));
  b.setAngularVelocity(btVector3(0, 0, 0));
  b.clearForces();
}

void BulletWorld::step() {
  // maxSubSteps 0: exactly one internal step of the given length.
  world_->stepSimulation(params_.time_step, 0, params_.time_step);
  time_ += params_.time_step;
}

bool BulletWorld::touching(int a, int b, double margin) const {
  const btCollisionObject* body_a = bodies_.at(a).get();
  const btCollisionObject* body_b = bodies_.at(b).get();
  for (int i = 0; i < dispatcher_->getNumManifolds(); ++i) {
    const btPersistentManifold* m = dispatcher_->getManifoldByIndexInternal(i);
    const bool pair = (m->getBody0() == body_a && m->getBody1() == body_b) ||
                      (m->getBody0() == body_b && m->getBody1() == body_a);
    if (!pair) continue;
    for (int k = 0; k < m->getNumContacts(); ++k) {
      if (m->getContactPoint(k).getDistance() < margin) return true;
    }
  }
  return false;
}

std::string BulletWorld::blow_up(double bound, double max_speed) const {
  for (size_t i = 0; i < bodies_.size(); ++i) {
    if (infos_[i].kinematic || bodies_[i]->getInvMass() == 0) continue;
    const Eigen::Vector3d p = position(static_cast<int>(i));
    const Eigen::Vector3d v = linear_velocity(static_cast<int>(i));
    if (!p.allFinite() || !v.allFinite()) {
      return fmt::format("{}: body '{}' has a non-finite state", kBlowUpFailure, infos_[i].name);
    }
    if (p.norm() > bound || v.norm() > max_speed) {
      return fmt::format("{}: body '{}' at |p| {:.3g} m moving at {:.3g} m/s", kBlowUpFailure,
                         infos_[i].name, p.norm(), v.norm());
    }
  }
  return "";
}

}  // namespace corrmp
