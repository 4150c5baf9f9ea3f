// A Bullet rigid-body world with a fixed time step and one internal step per
// tick (deterministic: a fresh world replays identically), bodies from scene
// descriptions, kinematic bodies moved by pose, contact queries and a blow-up
// check. Paper, Section IV-A (simulation in place of the Torobo robot).
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <vector>

#include "core/config/field_rule.hpp"
#include "sim/scene_description.hpp"

class btRigidBody;
class btCollisionShape;
class btDiscreteDynamicsWorld;
class btBroadphaseInterface;
class btCollisionDispatcher;
class btDefaultCollisionConfiguration;
class btSequentialImpulseConstraintSolver;

namespace corrmp {

// How BulletWorld::blow_up()'s descriptions start (a failure category).
inline constexpr const char* kBlowUpFailure = "physics blow-up";

struct PhysicsParams {
  double time_step = 1.0 / 240.0;
  int solver_iterations = 50;
  double gravity = 9.81;

  template <class Fields>
  void describe(Fields& f) {
    f("time_step", time_step, "simulation tick (s); one internal step per tick",
      in_range(1e-4, 0.05));
    f("solver_iterations", solver_iterations, "constraint solver iterations", in_range(1, 1000));
    f("gravity", gravity, "gravity magnitude (m/s^2)", at_least(0.0));
  }
};

// What a body is, for rendering and queries.
struct BodyInfo {
  std::string name;
  std::string shape;         // box, cylinder, capsule, sphere
  std::vector<double> size;  // as in SceneBodySpec
  Eigen::Vector3f colour;
  bool kinematic = false;
};

class BulletWorld {
 public:
  explicit BulletWorld(const PhysicsParams& params);
  ~BulletWorld();
  BulletWorld(const BulletWorld&) = delete;
  BulletWorld& operator=(const BulletWorld&) = delete;

  // Adds a body; returns its index. `kinematic` bodies are moved with set_pose.
  int add_body(const SceneBodySpec& spec, bool kinematic = false);
  int add_scene(const SceneDescription& scene);  // returns the index of the first body
  int find(const std::string& name) const;       // -1 when absent

  // Kinematic bodies: the pose of the next tick (Bullet derives the velocity
  // from the last pose).
  void set_pose(int body, const Eigen::Isometry3d& pose);
  Eigen::Isometry3d pose(int body) const;
  Eigen::Vector3d position(int body) const { return pose(body).translation(); }
  Eigen::Vector3d linear_velocity(int body) const;
  // Moves a dynamic body (at rest) to a new pose before a rollout.
  void place(int body, const Eigen::Isometry3d& pose);

  void step();
  double time() const { return time_; }
  double time_step() const { return params_.time_step; }

  // True when bodies a and b have a contact point closer than `margin` (m).
  bool touching(int a, int b, double margin = 1e-4) const;

  // "" when every dynamic body is finite, within `bound` metres of the origin
  // and slower than `max_speed`; else a description of the blow-up, starting
  // with kBlowUpFailure.
  std::string blow_up(double bound = 10.0, double max_speed = 20.0) const;

  int body_count() const { return static_cast<int>(bodies_.size()); }
  const BodyInfo& info(int body) const { return infos_.at(body); }

 private:
  PhysicsParams params_;
  std::unique_ptr<btDefaultCollisionConfiguration> configuration_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::vector<BodyInfo> infos_;
  double time_ = 0.0;
};

}  // namespace corrmp
