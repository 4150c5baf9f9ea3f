// How a RobotModel maps onto a Featherstone multibody, in double precision and
// without Bullet: links joined by fixed joints are merged into one rigid body
// (their masses, inertias and shapes combined), every movable joint starts a
// new body, and each body's frame for the dynamics is its centre of mass
// aligned with the principal axes of its inertia.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "sim/robot/robot_model.hpp"

namespace corrmp {

// One rigid body of the multibody: the root (the fixed base) or the child of a
// movable joint, with every link fixed to it.
struct LayoutBody {
  std::string link;  // the model link whose frame is the body's frame
  int parent = -1;   // index into MultibodyLayout::bodies; -1 for the root
  int joint = -1;    // index into RobotModel::joints of the joint to the parent
  double mass = 0.0;
  // The centre-of-mass frame in the body's link frame, rotated onto the
  // principal axes of the inertia; `principal_inertia` are the moments about them.
  Eigen::Isometry3d com = Eigen::Isometry3d::Identity();
  Eigen::Vector3d principal_inertia = Eigen::Vector3d::Zero();
  // The joint frame at q = 0 (origin on the axis) in the parent body's link frame.
  Eigen::Isometry3d joint_origin = Eigen::Isometry3d::Identity();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // in the body's link frame
  std::vector<RobotShape> collisions;               // origins in the body's link frame
};

struct LinkPlacement {
  int body = -1;                                              // index into bodies
  Eigen::Isometry3d in_body = Eigen::Isometry3d::Identity();  // link frame in the body's link frame
};

struct MultibodyLayout {
  std::vector<LayoutBody> bodies;    // bodies[0] is the root; parents come first
  std::vector<LinkPlacement> links;  // per RobotModel::links entry
  std::vector<int> movable_joints;   // RobotModel::joints indices, one per bodies[1..]
};

// Bodies lighter than kMinBodyMass, or with a principal moment below
// kMinPrincipalInertia, get these values: a massless frame on a movable joint
// stays a valid (very light) body instead of a singular one.
constexpr double kMinBodyMass = 1e-3;          // kg
constexpr double kMinPrincipalInertia = 1e-6;  // kg m^2

// Throws std::invalid_argument "robot '<name>': ..." when a joint names an
// unknown or already attached child, a parent not yet reached from the root, a
// link no joint reaches, or
// a movable joint has a zero axis, lower > upper, or a non-positive velocity or
// effort limit.
MultibodyLayout make_multibody_layout(const RobotModel& model);

}  // namespace corrmp
