// The anchoring parallel gripper of the rope task (paper, Section IV-C).
#include "sim/soft/anchor_gripper.hpp"

#include <BulletSoftBody/btSoftBody.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace corrmp {

namespace {

// Distance from point p to the axis-aligned box centred at c with half extents h.
double box_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& c, const Eigen::Vector3d& h) {
  const Eigen::Vector3d d = ((p - c).cwiseAbs() - h).cwiseMax(0.0);
  return d.norm();
}

}  // namespace

AnchorGripper::AnchorGripper(Rope& rope, const AnchorGripperParams& params,
                             const Eigen::Matrix3d& orientation, const Eigen::Vector3d& position)
    : rope_(rope), params_(params), orientation_(orientation), position_(position) {
  if (!orientation.allFinite() || !(orientation.transpose() * orientation).isIdentity(1e-6)) {
    throw std::invalid_argument("AnchorGripper: orientation is not a rotation matrix");
  }
  if (params.colour.size() != 3) {
    throw std::invalid_argument("AnchorGripper: colour needs 3 values (RGB)");
  }
  shape_ = std::make_unique<btSphereShape>(0.01);
  btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, shape_.get());
  body_ = std::make_unique<btRigidBody>(info);
  body_->setCollisionFlags(body_->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
  place(position);
}

AnchorGripper::~AnchorGripper() { remove_anchors(); }

Eigen::Vector3d AnchorGripper::local(const Eigen::Vector3d& world) const {
  return orientation_.transpose() * (world - position_);
}

void AnchorGripper::set_body(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity) {
  SoftWorld& world = rope_.world();
  btTransform transform;
  transform.setIdentity();
  transform.setOrigin(world.to_bullet(position));
  body_->setWorldTransform(transform);
  body_->setInterpolationWorldTransform(transform);
  body_->setLinearVelocity(world.to_bullet(velocity));
  body_->setAngularVelocity(btVector3(0, 0, 0));
  position_ = position;
}

void AnchorGripper::place(const Eigen::Vector3d& position) {
  set_body(position, Eigen::Vector3d::Zero());
}

void AnchorGripper::tick_to(const Eigen::Vector3d& position) {
  const double dt = rope_.world().time_step();
  set_body(position, (position - position_) / dt);
  if (closed_ || anchored() == 0) return;
  influence_ = std::max(0.0, influence_ - dt / params_.release_time);
  if (influence_ <= 0.0) {
    remove_anchors();
    return;
  }
  for (int k = 0; k < rope_.body().m_anchors.size(); ++k) {
    btSoftBody::Anchor& anchor = rope_.body().m_anchors[k];
    if (anchor.m_body == body_.get()) anchor.m_influence = influence_;
  }
}

std::vector<int> AnchorGripper::nodes_in_gap() const {
  std::vector<int> inside;
  for (int i = 0; i < rope_.node_count(); ++i) {
    const Eigen::Vector3d p = local(rope_.node(i));
    if (std::abs(p.x()) < params_.opening / 2 && std::abs(p.y()) < params_.finger_width / 2 &&
        std::abs(p.z()) < params_.finger_length / 2) {
      inside.push_back(i);
    }
  }
  return inside;
}

int AnchorGripper::close() {
  if (closed_) return anchored();
  remove_anchors();
  closed_ = true;
  influence_ = 1.0;
  const std::vector<int> inside = nodes_in_gap();
  for (int i : inside) rope_.body().appendAnchor(i, body_.get(), false, 1.0);
  return static_cast<int>(inside.size());
}

void AnchorGripper::open() { closed_ = false; }

int AnchorGripper::anchored() const {
  int count = 0;
  for (int k = 0; k < rope_.body().m_anchors.size(); ++k) {
    if (rope_.body().m_anchors[k].m_body == body_.get()) ++count;
  }
  return count;
}

bool AnchorGripper::releasing() const { return !closed_ && anchored() > 0; }

void AnchorGripper::remove_anchors() {
  auto& anchors = rope_.body().m_anchors;
  for (int k = anchors.size() - 1; k >= 0; --k) {
    if (anchors[k].m_body != body_.get()) continue;
    anchors[k].m_node->m_battach = 0;
    anchors.swap(k, anchors.size() - 1);
    anchors.pop_back();
  }
}

bool AnchorGripper::near_miss() const {
  if (!nodes_in_gap().empty()) return false;
  const double reach = 2.0 * rope_.params().radius;
  const Eigen::Vector3d half(params_.finger_thickness / 2, params_.finger_width / 2,
                             params_.finger_length / 2);
  const double side = (params_.opening + params_.finger_thickness) / 2;
  for (int i = 0; i < rope_.node_count(); ++i) {
    const Eigen::Vector3d p = local(rope_.node(i));
    if (box_distance(p, Eigen::Vector3d(side, 0, 0), half) < reach ||
        box_distance(p, Eigen::Vector3d(-side, 0, 0), half) < reach) {
      return true;
    }
  }
  return false;
}

void AnchorGripper::add_to(RenderScene& scene) const {
  const Eigen::Vector3f colour(params_.colour[0], params_.colour[1], params_.colour[2]);
  const double gap =
      closed_ ? (anchored() > 0 ? 2.0 * rope_.params().radius : 0.0) : params_.opening;
  auto item = [&](const Eigen::Vector3d& centre, const Eigen::Vector3d& half) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = orientation_;
    pose.translation() = position_ + orientation_ * centre;
    scene.items.push_back({Box{half}, pose, colour});
  };
  const Eigen::Vector3d finger(params_.finger_thickness / 2, params_.finger_width / 2,
                               params_.finger_length / 2);
  const double side = (gap + params_.finger_thickness) / 2;
  item(Eigen::Vector3d(side, 0, 0), finger);
  item(Eigen::Vector3d(-side, 0, 0), finger);
  const double palm_half_x = side + params_.finger_thickness / 2;
  item(Eigen::Vector3d(0, 0, -(params_.finger_length + params_.palm_thickness) / 2),
       Eigen::Vector3d(palm_half_x, params_.finger_width / 2, params_.palm_thickness / 2));
}

}  // namespace corrmp
