#include "sim/robot/kdl_chain.hpp"

namespace corrmp {
namespace {

KDL::Vector kdl_vector(const Eigen::Vector3d& v) { return KDL::Vector(v.x(), v.y(), v.z()); }

KDL::Frame kdl_frame(const Eigen::Isometry3d& pose) {
  const Eigen::Matrix3d& r = pose.linear();
  return KDL::Frame(KDL::Rotation(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0),
                                  r(2, 1), r(2, 2)),
                    kdl_vector(pose.translation()));
}

// The link's inertia about its centre of mass, turned into the link frame's axes.
KDL::RigidBodyInertia kdl_inertia(const RobotLink& link) {
  const Eigen::Matrix3d& r = link.inertial_origin.linear();
  const Eigen::Matrix3d i = r * link.inertia * r.transpose();
  return KDL::RigidBodyInertia(
      link.mass, kdl_vector(link.inertial_origin.translation()),
      KDL::RotationalInertia(i(0, 0), i(1, 1), i(2, 2), i(0, 1), i(0, 2), i(1, 2)));
}

// The URDF axis is in the child frame at the joint origin; KDL wants the joint's
// point and axis in the parent frame, and the child frame at q = 0 as the tip.
KDL::Joint kdl_joint(const RobotJoint& joint) {
  const KDL::Vector origin = kdl_vector(joint.origin.translation());
  const KDL::Vector axis = kdl_vector(joint.origin.linear() * joint.axis);
  switch (joint.type) {
    case JointType::revolute:
      return KDL::Joint(joint.name, origin, axis, KDL::Joint::RotAxis);
    case JointType::prismatic:
      return KDL::Joint(joint.name, origin, axis, KDL::Joint::TransAxis);
    case JointType::fixed:
      break;
  }
  return KDL::Joint(joint.name, KDL::Joint::Fixed);
}

}  // namespace

KDL::Chain kdl_chain(const RobotModel& model, const std::string& base, const std::string& tip) {
  KDL::Chain chain;
  for (int index : model.chain(base, tip)) {
    const RobotJoint& joint = model.joints[index];
    const RobotLink& child = model.links[model.link_index(joint.child)];
    chain.addSegment(
        KDL::Segment(joint.child, kdl_joint(joint), kdl_frame(joint.origin), kdl_inertia(child)));
  }
  return chain;
}

}  // namespace corrmp
