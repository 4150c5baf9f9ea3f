// A gripper carried by one arm of a DualArm (the paper's robot executing a
// Cartesian trajectory through inverse kinematics with a fixed gripper
// orientation). The commanded tool point moves through the waypoints as a
// KinematicGripper's does; every tick the arm tracks it (the other arm holds
// its tool where it was at construction), the gripper's kinematic bodies are
// placed at the executed tool position, the arms' links are placed as
// kinematic bodies of the task's world, and the world steps.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "sim/bullet_world.hpp"
#include "sim/kinematic_gripper.hpp"
#include "sim/robot/dual_arm.hpp"

namespace corrmp {

class ArmGripper : public Gripper {
 public:
  // Adds the gripper's bodies and one kinematic body per collision shape of
  // both arms' links to `world` (not of the driving arm's hand: the gripper's
  // bodies stand in for it), all at the robot's current pose.
  ArmGripper(BulletWorld& world, const GripperParams& params, DualArm& robot, Arm arm);

  // The executed tool position.
  Eigen::Vector3d position() const override { return robot_.tool_position(arm_); }
  void set_closed(bool closed) override { gripper_.set_closed(closed); }
  // A DualArm failure stops the motion with its category as the failure.
  TrackingResult follow(const Eigen::MatrixXd& waypoints,
                        const std::function<std::string()>& check) override;

  // The world bodies of the arms' shapes, in DualArm::shapes() order. Only this
  // gripper places them (it skips a body whose pose has not changed).
  const std::vector<int>& arm_bodies() const { return arm_bodies_; }

 private:
  void place_bodies();

  BulletWorld& world_;
  GripperParams params_;
  DualArm& robot_;
  Arm arm_;
  Eigen::Vector3d hold_;       // the other arm's tool target
  Eigen::Vector3d commanded_;  // the driving arm's tool target
  KinematicGripper gripper_;
  std::vector<bool> shown_;  // per DualArm::shapes() entry: has a world body
  std::vector<int> arm_bodies_;
  std::vector<std::optional<Eigen::Isometry3d>> placed_;  // per entry: its body's last pose
};

}  // namespace corrmp
