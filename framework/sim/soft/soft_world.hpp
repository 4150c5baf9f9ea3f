// A Bullet soft-rigid world for the rope-knotting task (paper, Section IV-C,
// "Knotting with the real robot", reproduced in simulation): a scaled world
// (Bullet units per metre), a fixed tick with exactly one internal step,
// gravity on the world and on the soft-body world info, a fine sparse SDF for
// rope-versus-rigid contact, static bars (cylinders along y), hooks run after
// each step (the rope's self-contact pass) and a blow-up check.
// The public interface is in metres and seconds.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/config/field_rule.hpp"

class btRigidBody;
class btCollisionShape;
class btSoftBody;
class btSoftBodyWorldInfo;
class btSoftRigidDynamicsWorld;
class btBroadphaseInterface;
class btCollisionDispatcher;
class btSoftBodyRigidBodyCollisionConfiguration;
class btSequentialImpulseConstraintSolver;
class btVector3;

namespace corrmp {

struct SoftWorldParams {
  double time_step = 1.0 / 600.0;
  double world_scale = 10.0;
  double gravity = 9.81;
  double sdf_voxel = 0.005;
  int rigid_solver_iterations = 10;
  double stretch_limit = 3.0;
  double bound = 3.0;

  template <class Fields>
  void describe(Fields& f) {
    f("time_step", time_step, "simulation tick (s); one internal step per tick",
      in_range(1e-4, 0.01));
    f("world_scale", world_scale, "Bullet length units per metre", positive());
    f("gravity", gravity, "gravity magnitude (m/s^2)", at_least(0.0));
    f("sdf_voxel", sdf_voxel, "sparse SDF voxel size for soft-rigid contact (m)",
      in_range(1e-4, 0.05));
    f("rigid_solver_iterations", rigid_solver_iterations, "rigid constraint solver iterations",
      in_range(1, 1000));
    f("stretch_limit", stretch_limit,
      "blow-up when a link is longer than this factor times its rest length",
      FieldRule{}.above(1.0));
    f("bound", bound, "blow-up when a node is farther than this from the origin (m)", positive());
  }
};

// A static horizontal cylinder along the y axis.
struct Bar {
  std::string name;
  Eigen::Vector3d centre;
  double radius = 0.0;
  double length = 0.0;
};

class SoftWorld {
 public:
  explicit SoftWorld(const SoftWorldParams& params);
  ~SoftWorld();
  SoftWorld(const SoftWorld&) = delete;
  SoftWorld& operator=(const SoftWorld&) = delete;

  // Adds a static bar along y; returns its index.
  int add_bar(const std::string& name, const Eigen::Vector3d& centre, double radius, double length,
              double friction);
  const std::vector<Bar>& bars() const { return bars_; }

  // Soft bodies are owned by their creators, who remove them before deleting them;
  // a post-step hook belongs to a soft body and leaves with it.
  void add_soft_body(btSoftBody* body);
  void remove_soft_body(btSoftBody* body);
  void add_post_step(btSoftBody* owner, std::function<void()> hook);

  void step();
  double time() const { return time_; }
  double time_step() const { return params_.time_step; }
  const SoftWorldParams& params() const { return params_; }

  // "" or a description of the first fault: a non-finite node, a node out of
  // bounds, a link stretched beyond stretch_limit, a node deep inside a bar.
  std::string blow_up() const;

  btVector3 to_bullet(const Eigen::Vector3d& metres) const;
  Eigen::Vector3d to_metres(const btVector3& units) const;
  double to_units(double metres) const { return metres * params_.world_scale; }
  btSoftBodyWorldInfo& world_info();
  btSoftRigidDynamicsWorld& bullet() { return *world_; }

 private:
  SoftWorldParams params_;
  std::unique_ptr<btSoftBodyRigidBodyCollisionConfiguration> configuration_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::unique_ptr<btSoftRigidDynamicsWorld> world_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::vector<btSoftBody*> soft_bodies_;
  std::vector<std::pair<btSoftBody*, std::function<void()>>> post_step_;
  std::vector<Bar> bars_;
  double time_ = 0.0;
};

}  // namespace corrmp
