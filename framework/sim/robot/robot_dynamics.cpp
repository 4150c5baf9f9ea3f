// The Bullet multibody robot: construction from the layout, the joint
// controller's torques and the per-tick checks.
#include "sim/robot/robot_dynamics.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointLimitConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <BulletDynamics/Featherstone/btMultiBodyMLCPConstraintSolver.h>
#include <BulletDynamics/MLCPSolvers/btDantzigSolver.h>
#include <btBulletDynamicsCommon.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/robot/joint_torques.hpp"

namespace corrmp {

namespace {

// As in the rigid-body world: a millimetre of collision margin keeps contacts
// where the geometry is (Bullet's default is 4 cm).
constexpr double kCollisionMargin = 0.001;

btVector3 to_vector(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }

btQuaternion to_quaternion(const Eigen::Matrix3d& rotation) {
  const Eigen::Quaterniond q(rotation);
  return btQuaternion(q.x(), q.y(), q.z(), q.w());
}

btTransform to_bullet(const Eigen::Isometry3d& pose) {
  return btTransform(to_quaternion(pose.linear()), to_vector(pose.translation()));
}

Eigen::Isometry3d from_bullet(const btTransform& transform) {
  const btQuaternion q = transform.getRotation();
  const btVector3 t = transform.getOrigin();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()).normalized().toRotationMatrix();
  pose.translation() = Eigen::Vector3d(t.x(), t.y(), t.z());
  return pose;
}

std::unique_ptr<btCollisionShape> make_shape(const RobotShape& shape) {
  const Eigen::Vector3d& s = shape.size;
  std::unique_ptr<btCollisionShape> made;
  switch (shape.kind) {
    case RobotShape::Kind::box:
      made = std::make_unique<btBoxShape>(btVector3(s.x() / 2, s.y() / 2, s.z() / 2));
      break;
    case RobotShape::Kind::cylinder:
      made = std::make_unique<btCylinderShapeZ>(btVector3(s.x(), s.x(), s.y() / 2));
      break;
    case RobotShape::Kind::sphere:
      made = std::make_unique<btSphereShape>(s.x());
      break;
  }
  made->setMargin(kCollisionMargin);
  return made;
}

// The collider of one layout body. Two bodies of the robot collide unless one
// is the other's parent (joined by a joint) or the pair is allowed; the robot
// may span several multibodies, so Bullet's own filter (one multibody's
// parent/child pairs) is not used. Only the robot's colliders are in its world.
class RobotLinkCollider : public btMultiBodyLinkCollider {
 public:
  RobotLinkCollider(btMultiBody* multibody, int link, int body, int parent)
      : btMultiBodyLinkCollider(multibody, link), body(body), parent(parent) {}
  int body;                  // layout body index
  int parent;                // its parent body, -1 for the root
  std::vector<int> allowed;  // layout body indices

  bool checkCollideWithOverride(const btCollisionObject* object) const override {
    const btMultiBodyLinkCollider* link = btMultiBodyLinkCollider::upcast(object);
    if (!link) return true;
    const auto* other = static_cast<const RobotLinkCollider*>(link);
    if (other->body == parent || other->parent == body) return false;
    return std::find(allowed.begin(), allowed.end(), other->body) == allowed.end();
  }
};

// Whether two colliders have a contact point closer than `margin`.
struct TouchCallback : btCollisionWorld::ContactResultCallback {
  explicit TouchCallback(double margin) : margin(margin) { m_closestDistanceThreshold = margin; }
  btScalar addSingleResult(btManifoldPoint& point, const btCollisionObjectWrapper*, int, int,
                           const btCollisionObjectWrapper*, int, int) override {
    if (point.getDistance() < margin) touching = true;
    return 0;
  }
  double margin;
  bool touching = false;
};

double clamp(double value, double lo, double hi) { return std::min(std::max(value, lo), hi); }

}  // namespace

struct RobotDynamics::Bullet {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btDantzigSolver mlcp;
  btMultiBodyMLCPConstraintSolver solver{&mlcp};
  btMultiBodyDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  // One fixed-base multibody per branch of the root (the root's movable
  // children and everything below each): branches of a fixed root do not
  // move one another, and the solver's rows of a smaller multibody cost less.
  std::vector<std::unique_ptr<btMultiBody>> multibodies;
  std::vector<bool> braked;         // per multibody: frozen, not simulated (see the header)
  std::vector<int> body_multibody;  // per layout body: index into multibodies
  std::vector<int> body_link;       // per layout body: its link there, -1 for the root
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<RobotLinkCollider>> colliders;  // per body; null without shapes
  std::vector<std::vector<int>> branch_joints;  // per multibody, per link: its joint index
  std::vector<std::unique_ptr<btMultiBodyJointLimitConstraint>> limits;
  btAlignedObjectArray<btQuaternion> scratch_rotations;
  btAlignedObjectArray<btVector3> scratch_origins;

  ~Bullet() {
    for (auto& limit : limits) world.removeMultiBodyConstraint(limit.get());
    for (auto& collider : colliders)
      if (collider) world.removeCollisionObject(collider.get());
    for (auto& multibody : multibodies) world.removeMultiBody(multibody.get());
  }
};

RobotDynamics::RobotDynamics(
    const RobotModel& model, const RobotDynamicsParams& params, const Eigen::Isometry3d& base_pose,
    const std::vector<std::pair<std::string, std::string>>& allowed_contacts)
    : model_(model),
      params_(params),
      layout_(make_multibody_layout(model)),
      bullet_(std::make_unique<Bullet>()) {
  for (int j : layout_.movable_joints) joint_names_.push_back(model_.joints[j].name);
  for (const LinkPlacement& placement : layout_.links)
    link_in_com_.push_back(layout_.bodies[placement.body].com.inverse() * placement.in_body);
  bullet_->world.setGravity(btVector3(0, 0, -params_.gravity));
  bullet_->world.getSolverInfo().m_numIterations = params_.solver_iterations;
  build_multibody(base_pose);
  build_colliders();
  build_limits();
  allow_contacts_at_zero(allowed_contacts);
  reset(Eigen::VectorXd::Zero(dof()));
}

RobotDynamics::~RobotDynamics() = default;

void RobotDynamics::build_multibody(const Eigen::Isometry3d& base_pose) {
  const int count = static_cast<int>(layout_.bodies.size());
  std::vector<int>& branch = bullet_->body_multibody;
  std::vector<int>& link_of = bullet_->body_link;
  branch.assign(count, 0);
  link_of.assign(count, -1);
  std::vector<int> links;  // per branch
  for (int b = 1; b < count; ++b) {
    const int parent = layout_.bodies[b].parent;
    if (parent == 0) {
      branch[b] = static_cast<int>(links.size());
      links.push_back(0);
    } else {
      branch[b] = branch[parent];
    }
    link_of[b] = links[branch[b]]++;
  }
  if (links.empty()) links.push_back(0);
  const LayoutBody& root = layout_.bodies[0];
  for (int links_here : links) {
    // Sleep only when braked here: never on Bullet's own motion test, never
    // woken by Bullet.
    auto multibody =
        std::make_unique<btMultiBody>(links_here, root.mass, to_vector(root.principal_inertia),
                                      /*fixedBase=*/true, /*canSleep=*/true);
    multibody->setSleepThreshold(-1);
    multibody->setCanWakeup(false);
    multibody->setBaseWorldTransform(to_bullet(base_pose * root.com));
    bullet_->multibodies.push_back(std::move(multibody));
  }
  bullet_->braked.assign(bullet_->multibodies.size(), false);
  for (int b = 1; b < count; ++b) {
    const LayoutBody& body = layout_.bodies[b];
    btMultiBody* multibody = bullet_->multibodies[branch[b]].get();
    const int link = link_of[b];
    const int parent_link = link_of[body.parent];
    const Eigen::Isometry3d& parent_com = layout_.bodies[body.parent].com;
    // Bullet's link frames are the centre-of-mass frames: rotations and
    // offsets between them, with the pivot on the joint axis.
    const Eigen::Matrix3d parent_to_this =
        parent_com.linear().transpose() * body.joint_origin.linear() * body.com.linear();
    const btQuaternion rotation = to_quaternion(parent_to_this.transpose());
    const btVector3 axis = to_vector(body.com.linear().transpose() * body.axis);
    const btVector3 pivot = to_vector(parent_com.linear().transpose() *
                                      (body.joint_origin.translation() - parent_com.translation()));
    const btVector3 to_com = to_vector(body.com.linear().transpose() * body.com.translation());
    const btVector3 inertia = to_vector(body.principal_inertia);
    if (model_.joints[body.joint].type == JointType::revolute) {
      multibody->setupRevolute(link, body.mass, inertia, parent_link, rotation, axis, pivot, to_com,
                               /*disableParentCollision=*/true);
    } else {
      multibody->setupPrismatic(link, body.mass, inertia, parent_link, rotation, axis, pivot,
                                to_com, /*disableParentCollision=*/true);
    }
  }
  for (auto& multibody : bullet_->multibodies) {
    multibody->finalizeMultiDof();
    multibody->setHasSelfCollision(true);
    multibody->setLinearDamping(0);
    multibody->setAngularDamping(0);
    bullet_->world.addMultiBody(multibody.get());
  }
}

void RobotDynamics::build_colliders() {
  for (size_t b = 0; b < layout_.bodies.size(); ++b) {
    const LayoutBody& body = layout_.bodies[b];
    if (body.collisions.empty()) {
      bullet_->colliders.emplace_back();
      continue;
    }
    auto compound = std::make_unique<btCompoundShape>();
    for (const RobotShape& shape : body.collisions) {
      bullet_->shapes.push_back(make_shape(shape));
      compound->addChildShape(to_bullet(body.com.inverse() * shape.origin),
                              bullet_->shapes.back().get());
    }
    compound->setMargin(kCollisionMargin);
    btMultiBody& multibody = *bullet_->multibodies[bullet_->body_multibody[b]];
    const int link = bullet_->body_link[b];
    auto collider =
        std::make_unique<RobotLinkCollider>(&multibody, link, static_cast<int>(b), body.parent);
    collider->setCollisionShape(compound.get());
    // The fixed root is static: it joins no branch's simulation island, so one
    // branch can be braked while another moves.
    if (link < 0) collider->setCollisionFlags(btCollisionObject::CF_STATIC_OBJECT);
    bullet_->shapes.push_back(std::move(compound));
    collider->setWorldTransform(link < 0 ? multibody.getBaseWorldTransform()
                                         : multibody.getLink(link).m_cachedWorldTransform);
    bullet_->world.addCollisionObject(collider.get(), btBroadphaseProxy::DefaultFilter,
                                      btBroadphaseProxy::AllFilter);
    if (link < 0)
      multibody.setBaseCollider(collider.get());
    else
      multibody.getLink(link).m_collider = collider.get();
    bullet_->colliders.push_back(std::move(collider));
  }
}

void RobotDynamics::build_limits() {
  bullet_->branch_joints.resize(bullet_->multibodies.size());
  for (size_t m = 0; m < bullet_->multibodies.size(); ++m)
    bullet_->branch_joints[m].resize(bullet_->multibodies[m]->getNumLinks());
  for (int i = 0; i < dof(); ++i) {
    const RobotJoint& joint = model_.joints[layout_.movable_joints[i]];
    const int m = bullet_->body_multibody[i + 1];
    btMultiBody* multibody = bullet_->multibodies[m].get();
    const int link = bullet_->body_link[i + 1];
    bullet_->branch_joints[m][link] = i;
    auto limit = std::make_unique<btMultiBodyJointLimitConstraint>(multibody, link, joint.lower,
                                                                   joint.upper);
    bullet_->world.addMultiBodyConstraint(limit.get());
    bullet_->limits.push_back(std::move(limit));
  }
}

// Pairs that overlap at q = 0 (and the listed ones) never collide: links
// built to overlap at their joint housings are not a self collision.
void RobotDynamics::allow_contacts_at_zero(
    const std::vector<std::pair<std::string, std::string>>& allowed) {
  auto body_of = [&](const std::string& name) {
    for (size_t i = 0; i < model_.links.size(); ++i)
      if (model_.links[i].name == name) return layout_.links[i].body;
    throw std::invalid_argument(
        fmt::format("robot '{}': allowed contact names unknown link '{}'", model_.name, name));
  };
  auto allow = [&](int a, int b) {
    if (a == b || !bullet_->colliders[a] || !bullet_->colliders[b]) return;
    bullet_->colliders[a]->allowed.push_back(b);
    bullet_->colliders[b]->allowed.push_back(a);
  };
  for (const auto& [a, b] : allowed) allow(body_of(a), body_of(b));

  reset(Eigen::VectorXd::Zero(dof()));
  const int count = static_cast<int>(layout_.bodies.size());
  for (int a = 0; a < count; ++a) {
    for (int b = a + 1; b < count; ++b) {
      if (!bullet_->colliders[a] || !bullet_->colliders[b] || layout_.bodies[b].parent == a)
        continue;
      TouchCallback touch(params_.contact_margin);
      bullet_->world.contactPairTest(bullet_->colliders[a].get(), bullet_->colliders[b].get(),
                                     touch);
      if (touch.touching) allow(a, b);
    }
  }
}

int RobotDynamics::joint_index(const std::string& name) const {
  const auto found = std::find(joint_names_.begin(), joint_names_.end(), name);
  return found == joint_names_.end() ? -1 : static_cast<int>(found - joint_names_.begin());
}

const RobotJoint& RobotDynamics::joint(int i) const {
  return model_.joints[layout_.movable_joints[i]];
}

Eigen::VectorXd RobotDynamics::per_joint(double RobotJoint::*field) const {
  Eigen::VectorXd values(dof());
  for (int i = 0; i < dof(); ++i) values[i] = joint(i).*field;
  return values;
}

Eigen::VectorXd RobotDynamics::lower_limits() const { return per_joint(&RobotJoint::lower); }
Eigen::VectorXd RobotDynamics::upper_limits() const { return per_joint(&RobotJoint::upper); }
Eigen::VectorXd RobotDynamics::velocity_limits() const { return per_joint(&RobotJoint::velocity); }

namespace {

// Bullet skips a multibody whose link colliders are all asleep (its island's
// constraints, its dynamics and its integration; the controller gives it no
// torques). A braked branch's links are also
// flagged static: a moving branch still collides with them (a self collision)
// but never joins them in its simulation island, which would wake them.
void set_braked(btMultiBody& multibody, bool braked) {
  if (braked) {
    multibody.clearVelocities();
    multibody.goToSleep();
  } else {
    multibody.wakeUp();
  }
  for (int link = 0; link < multibody.getNumLinks(); ++link) {
    btMultiBodyLinkCollider* collider = multibody.getLink(link).m_collider;
    if (!collider) continue;
    const int flags = collider->getCollisionFlags();
    collider->setCollisionFlags(braked ? flags | btCollisionObject::CF_STATIC_OBJECT
                                       : flags & ~btCollisionObject::CF_STATIC_OBJECT);
    collider->forceActivationState(braked ? ISLAND_SLEEPING : ACTIVE_TAG);
  }
}

}  // namespace

void RobotDynamics::reset(const Eigen::VectorXd& q) {
  if (q.size() != dof())
    throw std::invalid_argument(fmt::format(
        "robot '{}': reset with {} joint positions, expected {}", model_.name, q.size(), dof()));
  for (int i = 0; i < dof(); ++i) {
    btMultiBody& multibody = *bullet_->multibodies[bullet_->body_multibody[i + 1]];
    multibody.setJointPos(bullet_->body_link[i + 1], q[i]);
    multibody.setJointVel(bullet_->body_link[i + 1], 0.0);
  }
  for (size_t m = 0; m < bullet_->multibodies.size(); ++m) {
    bullet_->multibodies[m]->clearForcesAndTorques();
    bullet_->multibodies[m]->clearVelocities();
    set_braked(*bullet_->multibodies[m], false);
    bullet_->braked[m] = false;
  }
  update_kinematics();
  for (auto& multibody : bullet_->multibodies) {
    multibody->updateCollisionObjectWorldTransforms(bullet_->scratch_rotations,
                                                    bullet_->scratch_origins);
  }
  target_ = q;
  last_target_ = q;
  motor_target_ = q;
  target_velocity_.resize(0);
  target_beyond_limits_ = false;
  failure_.clear();
  failure_detail_.clear();
}

void RobotDynamics::set_targets(const Eigen::VectorXd& positions) {
  set_targets(positions, Eigen::VectorXd());
}

void RobotDynamics::set_targets(const Eigen::VectorXd& positions,
                                const Eigen::VectorXd& velocities) {
  if (positions.size() != dof() || (velocities.size() != 0 && velocities.size() != dof()))
    throw std::invalid_argument(
        fmt::format("robot '{}': targets for {} joints ({} velocities), expected {}", model_.name,
                    positions.size(), velocities.size(), dof()));
  target_beyond_limits_ = false;
  target_detail_.clear();
  target_.resize(dof());
  for (int i = 0; i < dof(); ++i) {
    const RobotJoint& joint = model_.joints[layout_.movable_joints[i]];
    target_[i] = clamp(positions[i], joint.lower, joint.upper);
    if (!target_beyond_limits_ &&
        std::abs(positions[i] - target_[i]) > params_.joint_limit_margin) {
      target_beyond_limits_ = true;
      target_detail_ = fmt::format("joint '{}' commanded to {:.4g} beyond [{:.4g}, {:.4g}]",
                                   joint.name, positions[i], joint.lower, joint.upper);
    }
  }
  target_velocity_ = velocities;
}

void RobotDynamics::step() {
  release_moved_brakes();
  const double dt = params_.time_step;
  Eigen::VectorXd velocity_target(dof()), position_target(dof());
  for (int i = 0; i < dof(); ++i) {
    const double limit = joint(i).velocity;
    const double move = clamp(target_[i] - motor_target_[i], -limit * dt, limit * dt);
    motor_target_[i] += move;
    velocity_target[i] =
        target_velocity_.size() != 0 ? clamp(target_velocity_[i], -limit, limit) : move / dt;
    // The position term is the error left after moving at the target velocity
    // for this tick, so a joint on its trajectory gets no extra push.
    position_target[i] = motor_target_[i] - velocity_target[i] * dt;
  }
  for (size_t m = 0; m < bullet_->multibodies.size(); ++m) {
    if (!bullet_->braked[m])
      apply_joint_torques(static_cast<int>(m), position_target, velocity_target);
  }
  bullet_->world.stepSimulation(dt, 0, dt);
  time_ += dt;
  update_kinematics();
  brake_still_branches();
  run_checks();
}

void RobotDynamics::apply_joint_torques(int branch, const Eigen::VectorXd& position_target,
                                        const Eigen::VectorXd& velocity_target) {
  btMultiBody& multibody = *bullet_->multibodies[branch];
  const std::vector<int>& joints = bullet_->branch_joints[branch];
  const int n = multibody.getNumLinks();
  const double dt = params_.time_step;
  std::vector<ChainBody> bodies(n);
  Eigen::VectorXd qd(n), target(n), effort(n), speed(n);
  for (int link = 0; link < n; ++link) {
    const btMultibodyLink& bullet_link = multibody.getLink(link);
    const Eigen::Isometry3d frame = from_bullet(bullet_link.m_cachedWorldTransform);
    const Eigen::Matrix3d rotation = frame.linear();
    ChainBody& body = bodies[link];
    body.parent = bullet_link.m_parent;
    body.revolute = bullet_link.m_jointType == btMultibodyLink::eRevolute;
    body.mass = bullet_link.m_mass;
    const btVector3& inertia = bullet_link.m_inertiaLocal;
    body.inertia = rotation * Eigen::Vector3d(inertia.x(), inertia.y(), inertia.z()).asDiagonal() *
                   rotation.transpose();
    body.com = frame.translation();
    const btVector3& axis =
        body.revolute ? bullet_link.m_axes[0].m_topVec : bullet_link.m_axes[0].m_bottomVec;
    body.axis = rotation * Eigen::Vector3d(axis.x(), axis.y(), axis.z());
    const btVector3& to_com = bullet_link.m_dVector;
    body.pivot = body.com - rotation * Eigen::Vector3d(to_com.x(), to_com.y(), to_com.z());
    const int i = joints[link];
    qd[link] = multibody.getJointVel(link);
    effort[link] = joint(i).effort;
    speed[link] = joint(i).velocity;
    // The velocity the joint is driven to: the position term's share of the
    // error per tick plus the velocity term's blend of the target velocity
    // and the joint's velocity after the tick with no joint torque (that
    // blend needs the inertia unless velocity_gain is 1).
    target[link] = params_.position_gain * (position_target[i] - multibody.getJointPos(link)) / dt +
                   params_.velocity_gain * velocity_target[i];
  }
  const Eigen::Vector3d gravity(0.0, 0.0, -params_.gravity);
  // M(q) and h(q, qd), computed only where needed.
  Eigen::MatrixXd inertia;
  Eigen::VectorXd bias;
  auto find_dynamics = [&] {
    if (inertia.size() != 0) return;
    inertia = joint_inertia(bodies);
    bias = inverse_dynamics(bodies, qd, Eigen::VectorXd::Zero(n), gravity);
  };
  const bool blended = params_.velocity_gain != 1.0;
  if (blended) {
    find_dynamics();
    target += (1.0 - params_.velocity_gain) * (qd - dt * inertia.ldlt().solve(bias));
  }
  target = target.cwiseMax(-speed).cwiseMin(speed);
  Eigen::VectorXd tau;
  if (!blended) tau = inverse_dynamics(bodies, qd, (target - qd) / dt, gravity);
  if (blended || (tau.cwiseAbs().array() > effort.array()).any()) {
    find_dynamics();
    tau = bounded_joint_forces(inertia, bias, qd, target, effort, dt);
  }
  for (int link = 0; link < n; ++link) multibody.addJointTorque(link, tau[link]);
}

int RobotDynamics::braked_branches() const {
  return static_cast<int>(std::count(bullet_->braked.begin(), bullet_->braked.end(), true));
}

// Whether joint i's command moved since the last step: a new position target
// or a target velocity.
bool RobotDynamics::command_moved(int i) const {
  return target_[i] != last_target_[i] ||
         (target_velocity_.size() != 0 && target_velocity_[i] != 0.0);
}

// A braked branch whose command moved is released.
void RobotDynamics::release_moved_brakes() {
  for (int i = 0; i < dof(); ++i) {
    if (command_moved(i)) bullet_->braked[bullet_->body_multibody[i + 1]] = false;
  }
  for (size_t m = 0; m < bullet_->multibodies.size(); ++m)
    set_braked(*bullet_->multibodies[m], bullet_->braked[m]);
}

void RobotDynamics::brake_still_branches() {
  const double tolerance = params_.brake_tolerance;
  std::vector<bool> still(bullet_->multibodies.size(), tolerance > 0);
  for (int i = 0; i < dof(); ++i) {
    const int m = bullet_->body_multibody[i + 1];
    const btMultiBody& multibody = *bullet_->multibodies[m];
    const int link = bullet_->body_link[i + 1];
    if (command_moved(i) || motor_target_[i] != target_[i] ||
        std::abs(multibody.getJointPos(link) - target_[i]) > tolerance ||
        std::abs(multibody.getJointVel(link)) * params_.time_step > tolerance)
      still[m] = false;
  }
  last_target_ = target_;
  for (size_t m = 0; m < still.size(); ++m) {
    bullet_->braked[m] = still[m];
    if (still[m]) set_braked(*bullet_->multibodies[m], true);
  }
}

void RobotDynamics::update_kinematics() {
  for (auto& multibody : bullet_->multibodies)
    multibody->forwardKinematics(bullet_->scratch_rotations, bullet_->scratch_origins);
}

Eigen::VectorXd RobotDynamics::positions() const {
  Eigen::VectorXd q(dof());
  for (int i = 0; i < dof(); ++i)
    q[i] = bullet_->multibodies[bullet_->body_multibody[i + 1]]->getJointPos(
        bullet_->body_link[i + 1]);
  return q;
}

Eigen::VectorXd RobotDynamics::velocities() const {
  Eigen::VectorXd v(dof());
  for (int i = 0; i < dof(); ++i)
    v[i] = bullet_->multibodies[bullet_->body_multibody[i + 1]]->getJointVel(
        bullet_->body_link[i + 1]);
  return v;
}

int RobotDynamics::link_index(const std::string& link) const {
  for (size_t i = 0; i < model_.links.size(); ++i)
    if (model_.links[i].name == link) return static_cast<int>(i);
  return -1;
}

Eigen::Isometry3d RobotDynamics::link_pose(const std::string& link) const {
  const int index = link_index(link);
  if (index < 0)
    throw std::invalid_argument(fmt::format("robot '{}': no link '{}'", model_.name, link));
  return link_pose(index);
}

Eigen::Isometry3d RobotDynamics::link_pose(int link) const {
  const LinkPlacement& placement = layout_.links.at(link);
  const btMultiBody& multibody = *bullet_->multibodies[bullet_->body_multibody[placement.body]];
  const int body_link = bullet_->body_link[placement.body];
  const btTransform com = body_link < 0 ? multibody.getBaseWorldTransform()
                                        : multibody.getLink(body_link).m_cachedWorldTransform;
  return from_bullet(com) * link_in_com_[link];
}

bool RobotDynamics::fail(const std::string& category, const std::string& detail) {
  failure_ = category;
  failure_detail_ = detail;
  return true;
}

void RobotDynamics::run_checks() {
  failure_.clear();
  failure_detail_.clear();
  const Eigen::VectorXd q = positions();
  const Eigen::VectorXd v = velocities();
  if (!q.allFinite() || !v.allFinite()) {
    fail("physics fault", "a joint position or velocity is not finite");
    return;
  }

  for (int m = 0; m < bullet_->dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = bullet_->dispatcher.getManifoldByIndexInternal(m);
    const auto* a = btMultiBodyLinkCollider::upcast(manifold->getBody0());
    const auto* b = btMultiBodyLinkCollider::upcast(manifold->getBody1());
    if (!a || !b) continue;
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      if (manifold->getContactPoint(p).getDistance() >= params_.contact_margin) continue;
      fail("self collision",
           fmt::format("links '{}' and '{}' touch",
                       layout_.bodies[static_cast<const RobotLinkCollider*>(a)->body].link,
                       layout_.bodies[static_cast<const RobotLinkCollider*>(b)->body].link));
      return;
    }
  }

  for (int i = 0; i < dof(); ++i) {
    const RobotJoint& joint = model_.joints[layout_.movable_joints[i]];
    if (q[i] < joint.lower - params_.joint_limit_margin ||
        q[i] > joint.upper + params_.joint_limit_margin) {
      fail("joint limit", fmt::format("joint '{}' at {:.4g} beyond [{:.4g}, {:.4g}]", joint.name,
                                      q[i], joint.lower, joint.upper));
      return;
    }
  }
  if (target_beyond_limits_) {
    fail("joint limit", target_detail_);
    return;
  }

  for (int i = 0; i < dof(); ++i) {
    if (std::abs(q[i] - target_[i]) > params_.tracking_error_bound) {
      fail("tracking error",
           fmt::format("joint '{}' at {:.4g}, target {:.4g}", joint_names_[i], q[i], target_[i]));
      return;
    }
  }
}

}  // namespace corrmp
