// Robot models built in code for the robot tests (no URDF needed), and the
// forward kinematics composed by hand from a model: the reference every
// kinematics and dynamics implementation of a model is checked against.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "sim/robot/robot_model.hpp"

namespace corrmp::test {

// Revolute z, revolute y (origin rotated), prismatic z, then a massless "tool"
// frame on a fixed joint; link2's inertial frame is rotated with a full inertia.
RobotModel three_joint_arm();
// A z-y-z-y-z-y-z arm of cylinders on a box base, with a massless "ee" frame.
RobotModel seven_joint_arm();
// A torso with two seven-joint arms ("left_*", "right_*" links and joints).
RobotModel dual_arm();

// World poses of every model link (model link order) for the movable joint
// positions `q` (model joint order), the root at `base`.
std::vector<Eigen::Isometry3d> forward_kinematics(const RobotModel& model,
                                                  const Eigen::Isometry3d& base,
                                                  const Eigen::VectorXd& q);

}  // namespace corrmp::test
