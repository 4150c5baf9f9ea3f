// The Bullet soft-rigid world of the rope task (paper, Section IV-C).
#include "sim/soft/soft_world.hpp"

#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <btBulletDynamicsCommon.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace corrmp {

SoftWorld::SoftWorld(const SoftWorldParams& params)
    : params_(params),
      configuration_(std::make_unique<btSoftBodyRigidBodyCollisionConfiguration>()),
      dispatcher_(std::make_unique<btCollisionDispatcher>(configuration_.get())),
      broadphase_(std::make_unique<btDbvtBroadphase>()),
      solver_(std::make_unique<btSequentialImpulseConstraintSolver>()),
      world_(std::make_unique<btSoftRigidDynamicsWorld>(dispatcher_.get(), broadphase_.get(),
                                                        solver_.get(), configuration_.get())) {
  if (!(params.time_step > 0) || !(params.world_scale > 0) || !(params.sdf_voxel > 0)) {
    throw std::invalid_argument("SoftWorld: time_step, world_scale and sdf_voxel must be > 0");
  }
  const btVector3 gravity(0, 0, -params.gravity * params.world_scale);
  world_->setGravity(gravity);
  world_->getSolverInfo().m_numIterations = params.rigid_solver_iterations;
  btSoftBodyWorldInfo& info = world_->getWorldInfo();
  info.m_gravity = gravity;
  info.m_broadphase = broadphase_.get();
  info.m_dispatcher = dispatcher_.get();
  info.air_density = 0;
  info.water_density = 0;
  info.m_sparsesdf.Initialize();
  info.m_sparsesdf.setDefaultVoxelsz(to_units(params.sdf_voxel));
  info.m_sparsesdf.Reset();
}

SoftWorld::~SoftWorld() {
  for (btSoftBody* body : soft_bodies_) world_->removeSoftBody(body);
  for (auto& body : bodies_) world_->removeRigidBody(body.get());
}

int SoftWorld::add_bar(const std::string& name, const Eigen::Vector3d& centre, double radius,
                       double length, double friction) {
  if (!(radius > 0) || !(length > 0)) {
    throw std::invalid_argument(
        fmt::format("SoftWorld::add_bar '{}': radius and length > 0", name));
  }
  auto shape = std::make_unique<btCylinderShape>(
      btVector3(to_units(radius), to_units(length / 2), to_units(radius)));
  shape->setMargin(0);
  btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, shape.get());
  info.m_startWorldTransform.setIdentity();
  info.m_startWorldTransform.setOrigin(to_bullet(centre));
  info.m_friction = friction;
  auto body = std::make_unique<btRigidBody>(info);
  world_->addRigidBody(body.get());
  shapes_.push_back(std::move(shape));
  bodies_.push_back(std::move(body));
  bars_.push_back(Bar{name, centre, radius, length});
  return static_cast<int>(bars_.size()) - 1;
}

void SoftWorld::add_soft_body(btSoftBody* body) {
  world_->addSoftBody(body);
  soft_bodies_.push_back(body);
}

void SoftWorld::remove_soft_body(btSoftBody* body) {
  const auto it = std::find(soft_bodies_.begin(), soft_bodies_.end(), body);
  if (it == soft_bodies_.end()) return;
  world_->removeSoftBody(body);
  soft_bodies_.erase(it);
  post_step_.erase(std::remove_if(post_step_.begin(), post_step_.end(),
                                  [body](const auto& hook) { return hook.first == body; }),
                   post_step_.end());
}

void SoftWorld::add_post_step(btSoftBody* owner, std::function<void()> hook) {
  post_step_.emplace_back(owner, std::move(hook));
}

void SoftWorld::step() {
  // maxSubSteps 0: exactly one internal step of the given length.
  world_->stepSimulation(params_.time_step, 0, params_.time_step);
  for (auto& hook : post_step_) hook.second();
  time_ += params_.time_step;
}

std::string SoftWorld::blow_up() const {
  const double bound = to_units(params_.bound);
  for (size_t b = 0; b < soft_bodies_.size(); ++b) {
    const btSoftBody& body = *soft_bodies_[b];
    for (int i = 0; i < body.m_nodes.size(); ++i) {
      const btVector3& x = body.m_nodes[i].m_x;
      const btVector3& v = body.m_nodes[i].m_v;
      if (!std::isfinite(x.x()) || !std::isfinite(x.y()) || !std::isfinite(x.z()) ||
          !std::isfinite(v.x()) || !std::isfinite(v.y()) || !std::isfinite(v.z())) {
        return fmt::format("physics fault: soft body {} node {} is not finite", b, i);
      }
      if (x.length() > bound) {
        return fmt::format("physics fault: soft body {} node {} is {:.3g} m from the origin", b, i,
                           x.length() / params_.world_scale);
      }
      for (const Bar& bar : bars_) {
        const Eigen::Vector3d p = to_metres(x) - bar.centre;
        const bool inside_length = std::abs(p.y()) < bar.length / 2;
        if (inside_length && std::hypot(p.x(), p.z()) < 0.5 * bar.radius) {
          return fmt::format("physics fault: soft body {} node {} tunnelled into bar '{}'", b, i,
                             bar.name);
        }
      }
    }
    for (int l = 0; l < body.m_links.size(); ++l) {
      const btSoftBody::Link& link = body.m_links[l];
      const double length = (link.m_n[0]->m_x - link.m_n[1]->m_x).length();
      if (length > params_.stretch_limit * link.m_rl) {
        return fmt::format(
            "physics fault: soft body {} link {} (nodes {}-{}) stretched {:.3g} times to {:.3g} m",
            b, l, link.m_n[0] - &body.m_nodes[0], link.m_n[1] - &body.m_nodes[0],
            length / link.m_rl, length / params_.world_scale);
      }
    }
  }
  return "";
}

btVector3 SoftWorld::to_bullet(const Eigen::Vector3d& metres) const {
  const Eigen::Vector3d u = metres * params_.world_scale;
  return btVector3(u.x(), u.y(), u.z());
}

Eigen::Vector3d SoftWorld::to_metres(const btVector3& units) const {
  return Eigen::Vector3d(units.x(), units.y(), units.z()) / params_.world_scale;
}

btSoftBodyWorldInfo& SoftWorld::world_info() { return world_->getWorldInfo(); }

}  // namespace corrmp
