// Merging fixed links and finding each body's principal centre-of-mass frame.
#include "sim/robot/multibody_layout.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <stdexcept>

namespace corrmp {

namespace {

int find_link(const RobotModel& model, const std::string& name) {
  for (size_t i = 0; i < model.links.size(); ++i)
    if (model.links[i].name == name) return static_cast<int>(i);
  return -1;
}

[[noreturn]] void fail(const RobotModel& model, const std::string& what) {
  throw std::invalid_argument(fmt::format("robot '{}': {}", model.name, what));
}

void check_movable(const RobotModel& model, const RobotJoint& joint) {
  if (joint.axis.norm() < 1e-12) fail(model, fmt::format("joint '{}' has a zero axis", joint.name));
  if (!(joint.lower <= joint.upper))
    fail(model, fmt::format("joint '{}' has lower limit {} above upper limit {}", joint.name,
                            joint.lower, joint.upper));
  if (!(joint.velocity > 0.0) || !(joint.effort > 0.0))
    fail(model, fmt::format("joint '{}' needs positive velocity and effort limits", joint.name));
}

// Inertia about the centre of mass of a point-free rigid body moved by `d`
// (parallel axis theorem): I + m (|d|^2 E - d d^T).
Eigen::Matrix3d shifted(const Eigen::Matrix3d& inertia, double mass, const Eigen::Vector3d& d) {
  return inertia + mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
}

// Fills mass, com and principal_inertia of `body` from the links fixed to it.
void combine_inertia(const RobotModel& model, const MultibodyLayout& layout, int body_index,
                     LayoutBody& body) {
  double mass = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < model.links.size(); ++i) {
    if (layout.links[i].body != body_index || model.links[i].mass <= 0.0) continue;
    const Eigen::Isometry3d com = layout.links[i].in_body * model.links[i].inertial_origin;
    mass += model.links[i].mass;
    moment += model.links[i].mass * com.translation();
  }
  const Eigen::Vector3d centre =
      mass > 0.0 ? Eigen::Vector3d(moment / mass) : Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < model.links.size(); ++i) {
    if (layout.links[i].body != body_index || model.links[i].mass <= 0.0) continue;
    const RobotLink& link = model.links[i];
    const Eigen::Isometry3d com = layout.links[i].in_body * link.inertial_origin;
    const Eigen::Matrix3d rotated = com.linear() * link.inertia * com.linear().transpose();
    inertia += shifted(rotated, link.mass, com.translation() - centre);
  }
  inertia = 0.5 * (inertia + inertia.transpose());

  // Keep the link's axes when the inertia is already diagonal in them, so a
  // plain model gives plain frames; otherwise rotate onto the eigenvectors.
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d moments = inertia.diagonal();
  const double off_diagonal = (inertia - Eigen::Matrix3d(moments.asDiagonal())).norm();
  if (off_diagonal > 1e-12 * (1.0 + inertia.trace())) {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia);
    axes = solver.eigenvectors();
    if (axes.determinant() < 0.0) axes.col(2) = -axes.col(2);
    moments = solver.eigenvalues();
  }
  body.mass = std::max(mass, kMinBodyMass);
  body.com = Eigen::Isometry3d::Identity();
  body.com.linear() = axes;
  body.com.translation() = centre;
  body.principal_inertia = moments.cwiseMax(kMinPrincipalInertia);
}

}  // namespace

MultibodyLayout make_multibody_layout(const RobotModel& model) {
  MultibodyLayout layout;
  layout.links.resize(model.links.size());
  const int root = find_link(model, model.root);
  if (root < 0) fail(model, fmt::format("root link '{}' is not a link", model.root));
  LayoutBody root_body;
  root_body.link = model.root;
  layout.bodies.push_back(root_body);
  layout.links[root] = LinkPlacement{0, Eigen::Isometry3d::Identity()};

  for (size_t j = 0; j < model.joints.size(); ++j) {
    const RobotJoint& joint = model.joints[j];
    const int parent = find_link(model, joint.parent);
    const int child = find_link(model, joint.child);
    if (parent < 0 || layout.links[parent].body < 0)
      fail(model,
           fmt::format("joint '{}': parent link '{}' is unknown or not reached from the root",
                       joint.name, joint.parent));
    if (child < 0 || layout.links[child].body >= 0)
      fail(model, fmt::format("joint '{}': child link '{}' is unknown or already attached",
                              joint.name, joint.child));
    const LinkPlacement& up = layout.links[parent];
    if (joint.type == JointType::fixed) {
      layout.links[child] = LinkPlacement{up.body, up.in_body * joint.origin};
      continue;
    }
    check_movable(model, joint);
    LayoutBody body;
    body.link = joint.child;
    body.parent = up.body;
    body.joint = static_cast<int>(j);
    body.joint_origin = up.in_body * joint.origin;
    body.axis = joint.axis.normalized();
    layout.links[child] =
        LinkPlacement{static_cast<int>(layout.bodies.size()), Eigen::Isometry3d::Identity()};
    layout.bodies.push_back(body);
    layout.movable_joints.push_back(static_cast<int>(j));
  }

  for (size_t b = 0; b < layout.bodies.size(); ++b)
    combine_inertia(model, layout, static_cast<int>(b), layout.bodies[b]);
  for (size_t i = 0; i < model.links.size(); ++i) {
    if (layout.links[i].body < 0)
      fail(model, fmt::format("link '{}' is not reached from the root", model.links[i].name));
    for (RobotShape shape : model.links[i].collisions) {
      shape.origin = layout.links[i].in_body * shape.origin;
      layout.bodies[layout.links[i].body].collisions.push_back(shape);
    }
  }
  return layout;
}

}  // namespace corrmp
