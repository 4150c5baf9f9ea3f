#include "test_arms.hpp"

#include <string>
#include <utility>

namespace corrmp::test {

namespace {

Eigen::Isometry3d pose(const Eigen::Vector3d& xyz, const Eigen::Vector3d& rpy = {0, 0, 0}) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  p.translation() = xyz;
  return p;
}

RobotShape box(const Eigen::Vector3d& size, const Eigen::Isometry3d& origin) {
  RobotShape s;
  s.kind = RobotShape::Kind::box;
  s.size = size;
  s.origin = origin;
  return s;
}

RobotShape cylinder(double radius, double length, const Eigen::Isometry3d& origin) {
  RobotShape s;
  s.kind = RobotShape::Kind::cylinder;
  s.size = Eigen::Vector3d(radius, length, 0);
  s.origin = origin;
  return s;
}

// A solid cylinder along z from the link origin: mass, inertia, shape.
RobotLink cylinder_link(const std::string& name, double mass, double radius, double length) {
  RobotLink link;
  link.name = name;
  link.mass = mass;
  link.inertial_origin = pose({0, 0, length / 2});
  const double side = mass * (3 * radius * radius + length * length) / 12;
  link.inertia = Eigen::Vector3d(side, side, mass * radius * radius / 2).asDiagonal();
  link.collisions.push_back(cylinder(radius, length, pose({0, 0, length / 2})));
  link.visuals = link.collisions;
  return link;
}

RobotLink box_link(const std::string& name, double mass, const Eigen::Vector3d& size) {
  RobotLink link;
  link.name = name;
  link.mass = mass;
  link.inertial_origin = pose({0, 0, size.z() / 2});
  const Eigen::Vector3d s2 = size.cwiseProduct(size);
  link.inertia =
      (mass / 12 * Eigen::Vector3d(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y())).asDiagonal();
  link.collisions.push_back(box(size, pose({0, 0, size.z() / 2})));
  link.visuals = link.collisions;
  return link;
}

RobotJoint joint(const std::string& name, JointType type, const std::string& parent,
                 const std::string& child, const Eigen::Isometry3d& origin,
                 const Eigen::Vector3d& axis, double limit, double velocity, double effort) {
  RobotJoint j;
  j.name = name;
  j.type = type;
  j.parent = parent;
  j.child = child;
  j.origin = origin;
  j.axis = axis;
  if (type != JointType::fixed) {
    j.lower = -limit;
    j.upper = limit;
    j.velocity = velocity;
    j.effort = effort;
  }
  return j;
}

RobotJoint fixed(const std::string& name, const std::string& parent, const std::string& child,
                 const Eigen::Isometry3d& origin) {
  return joint(name, JointType::fixed, parent, child, origin, Eigen::Vector3d::UnitZ(), 0, 0, 0);
}

// Appends a seven-joint arm below `parent` at `mount`, names prefixed.
void add_arm(RobotModel& model, const std::string& prefix, const std::string& parent,
             const Eigen::Isometry3d& mount) {
  const double lengths[7] = {0.15, 0.2, 0.2, 0.2, 0.15, 0.1, 0.08};
  const double masses[7] = {2.5, 2.0, 1.8, 1.5, 1.0, 0.8, 0.5};
  const double efforts[7] = {150, 150, 80, 80, 30, 30, 10};
  std::string previous = parent;
  Eigen::Isometry3d origin = mount;
  for (int i = 0; i < 7; ++i) {
    const std::string link = prefix + "link" + std::to_string(i + 1);
    model.links.push_back(cylinder_link(link, masses[i], 0.04, lengths[i]));
    const bool z = i % 2 == 0;
    model.joints.push_back(joint(
        prefix + "joint" + std::to_string(i + 1), JointType::revolute, previous, link, origin,
        z ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY(), z ? 2.9 : 2.6, 2.0, efforts[i]));
    previous = link;
    origin = pose({0, 0, lengths[i]});
  }
  RobotLink ee;
  ee.name = prefix + "ee";
  model.links.push_back(ee);
  model.joints.push_back(fixed(prefix + "ee_joint", previous, ee.name, pose({0, 0, 0.08})));
}

// A model called `name` of the root link `root` alone.
RobotModel rooted_at(const std::string& name, RobotLink root) {
  RobotModel model;
  model.name = name;
  model.root = root.name;
  model.links.push_back(std::move(root));
  return model;
}

}  // namespace

RobotModel three_joint_arm() {
  RobotModel model = rooted_at("three_joint_arm", box_link("base", 5.0, {0.2, 0.2, 0.1}));
  model.links.push_back(cylinder_link("link1", 2.0, 0.05, 0.3));
  RobotLink link2 = box_link("link2", 1.5, {0.06, 0.06, 0.4});
  link2.inertial_origin = pose({0.01, -0.005, 0.2}, {0.3, -0.2, 0.5});
  link2.inertia << 0.02, 0.002, -0.001, 0.002, 0.018, 0.003, -0.001, 0.003, 0.001;
  model.links.push_back(link2);
  model.links.push_back(cylinder_link("link3", 0.5, 0.025, 0.2));
  RobotLink tool;
  tool.name = "tool";
  model.links.push_back(tool);
  model.joints.push_back(joint("joint1", JointType::revolute, "base", "link1", pose({0, 0, 0.1}),
                               Eigen::Vector3d::UnitZ(), 2.5, 2.0, 100));
  model.joints.push_back(joint("joint2", JointType::revolute, "link1", "link2",
                               pose({0, 0, 0.3}, {0.3, 0.0, 0.2}), Eigen::Vector3d::UnitY(), 2.0,
                               2.0, 100));
  RobotJoint slide =
      joint("joint3", JointType::prismatic, "link2", "link3", pose({0, 0, 0.4}, {0, 0.1, 0}),
            Eigen::Vector3d(0, 0.6, 0.8), 0.0, 0.3, 200);
  slide.lower = -0.15;
  slide.upper = 0.1;
  model.joints.push_back(slide);
  model.joints.push_back(fixed("tool_joint", "link3", "tool", pose({0, 0, 0.2}, {0.1, 0.2, 0.3})));
  return model;
}

RobotModel seven_joint_arm() {
  RobotModel model = rooted_at("seven_joint_arm", box_link("base", 5.0, {0.2, 0.2, 0.1}));
  add_arm(model, "", "base", pose({0, 0, 0.1}));
  return model;
}

RobotModel dual_arm() {
  RobotModel model = rooted_at("dual_arm", box_link("torso", 20.0, {0.2, 0.4, 0.5}));
  add_arm(model, "left_", "torso", pose({0, 0.25, 0.4}, {-1.5708, 0, 0}));
  add_arm(model, "right_", "torso", pose({0, -0.25, 0.4}, {1.5708, 0, 0}));
  return model;
}

std::vector<Eigen::Isometry3d> forward_kinematics(const RobotModel& model,
                                                  const Eigen::Isometry3d& base,
                                                  const Eigen::VectorXd& q) {
  std::vector<Eigen::Isometry3d> poses(model.links.size(), Eigen::Isometry3d::Identity());
  auto index = [&](const std::string& name) {
    for (size_t i = 0; i < model.links.size(); ++i)
      if (model.links[i].name == name) return i;
    return model.links.size();
  };
  poses[index(model.root)] = base;
  int movable = 0;
  for (const RobotJoint& j : model.joints) {
    Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
    if (j.type == JointType::revolute)
      motion.linear() = Eigen::AngleAxisd(q[movable++], j.axis.normalized()).toRotationMatrix();
    else if (j.type == JointType::prismatic)
      motion.translation() = q[movable++] * j.axis.normalized();
    poses[index(j.child)] = poses[index(j.parent)] * j.origin * motion;
  }
  return poses;
}

}  // namespace corrmp::test
