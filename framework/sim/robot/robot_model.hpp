// A robot read from a URDF file (load_robot_model): links with their inertia
// and shapes, joints with their origin, axis and limits. Plain data in SI
// units, shared by the kinematics (KDL chains, inverse kinematics) and the
// dynamics (Bullet btMultiBody), so neither depends on the other or on urdfdom.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace corrmp {

struct RobotShape {
  enum class Kind { box, cylinder, sphere };
  Kind kind = Kind::box;
  // box: full extents x, y, z; cylinder: radius, length (along its local z), 0;
  // sphere: radius, 0, 0.
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // in the link frame
  Eigen::Vector3f colour{0.6f, 0.6f, 0.6f};                  // RGB in [0, 1]
};

struct RobotLink {
  std::string name;
  double mass = 0.0;  // 0: a massless frame (fixed to its parent)
  // The centre-of-mass frame in the link frame, and the inertia about the
  // centre of mass in that frame.
  Eigen::Isometry3d inertial_origin = Eigen::Isometry3d::Identity();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  std::vector<RobotShape> collisions;
  std::vector<RobotShape> visuals;
};

enum class JointType { fixed, revolute, prismatic };

struct RobotJoint {
  std::string name;
  JointType type = JointType::fixed;
  std::string parent;  // link names
  std::string child;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // child frame in parent, q = 0
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();           // unit, in the child frame
  double lower = 0.0;  // position limits (rad or m); fixed joints: 0
  double upper = 0.0;
  double velocity = 0.0;  // velocity limit (rad/s or m/s)
  double effort = 0.0;    // effort limit (N m or N)
};

struct RobotModel {
  std::string name;
  std::string source;  // the URDF file it was read from
  std::string root;    // the root link's name
  std::vector<RobotLink> links;
  // Ordered parents first: a joint's parent link is the root or the child of
  // an earlier joint.
  std::vector<RobotJoint> joints;

  int link_index(const std::string& name) const;   // -1 when absent
  int joint_index(const std::string& name) const;  // -1 when absent
  // The joints from link `base` down to link `tip`, in order; throws
  // ConfigError "<source>: no chain from '<base>' to '<tip>' (...)" when `tip`
  // is not below `base` or either link is missing.
  std::vector<int> chain(const std::string& base, const std::string& tip) const;
};

// Reads a URDF file. Throws ConfigError "<path>: <what is wrong>" for a missing
// or unreadable file, malformed XML or URDF, a joint type other than fixed,
// revolute or prismatic, a movable joint without limits (lower > upper,
// non-positive velocity or effort), a zero axis, or a mesh shape.
RobotModel load_robot_model(const std::string& path);

}  // namespace corrmp
