// A dual-arm torso executing Cartesian tool targets the way the paper's robot
// did: each tick, inverse kinematics with a fixed tool orientation maps the
// target to joint positions (warm-started at the last solution), the joint
// controller of the Bullet multibody tracks them, and the tool is where the
// simulated arm actually is. Tasks place their grippers at the executed tool
// positions and render the arm's shapes in their own worlds.
//
// Frames: targets, tool positions and shape poses are in the task's world
// frame; the robot's base link sits at `base_position` in it (unrotated).
//
// Failure categories of a tick, "" when fine: "out of reach" (no IK solution
// within tolerance), "joint limit" (solutions only outside the limits, or a
// joint past them), "self collision", "tracking error" (the executed joints
// too far from the commanded ones), "physics fault".
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/config/field_rule.hpp"
#include "sim/robot/arm_kinematics.hpp"
#include "sim/robot/ik_solve_times.hpp"
#include "sim/robot/robot_dynamics.hpp"
#include "sim/robot/robot_model.hpp"

namespace corrmp {

enum class Arm { left = 0, right = 1 };

struct DualArmParams {
  std::string urdf = "assets/robots/dual_arm_torso.urdf";  // relative: to the source tree
  std::vector<double> base_position{0.0, 0.0, 0.0};        // the base link in the world (m)
  std::string base_link = "base";
  std::string left_tool = "left_tool";
  std::string right_tool = "right_tool";
  // Joint positions at reset (rad), in each arm's joint order: elbow-down
  // poses from which the workspace is tracked without flips.
  std::vector<double> left_home{-0.16, 1.15, 0.49, 1.68, -1.68, -1.14, -1.19};
  std::vector<double> right_home{0.33, 1.08, -0.72, 1.74, 1.80, -0.99, 1.08};
  IkParams ik;
  RobotDynamicsParams control;  // its time_step is the task's tick (another is refused)
  // Links that may touch one another without a self collision (every pair of them).
  std::vector<std::string> touching_links;

  template <class Fields>
  void describe(Fields& f) {
    f("urdf", urdf, "the robot's URDF file");
    f("base_position", base_position, "the base link's position in the world (m)", size_is(3));
    f("base_link", base_link, "the link both arms' chains start from");
    f("left_tool", left_tool, "the left arm's tool frame (between the fingertips)");
    f("right_tool", right_tool, "the right arm's tool frame");
    f("left_home", left_home, "left arm joint positions at reset (rad)");
    f("right_home", right_home, "right arm joint positions at reset (rad)");
    f("ik", ik, "inverse kinematics");
    f("control", control,
      "joint control and its failure bounds (its time_step is the task's tick: leave it out)");
    f("touching_links", touching_links,
      "links that may touch one another (every pair of them is no self collision)");
  }
};

// A collision shape of the robot at its executed pose, for a task's world.
struct PlacedShape {
  std::string link;
  RobotShape shape;  // shape.origin is the shape's pose in the world
};

class DualArm {
 public:
  // Loads the URDF (ConfigError "<file>: <what>" when it cannot be used: a
  // missing file or link, a home of the wrong length or outside the limits)
  // and puts both arms at home. `time_step` is the task's tick (s).
  DualArm(const DualArmParams& params, double time_step);
  ~DualArm();

  // Both arms at home, at rest; the tool orientations become the home poses'.
  void reset();
  // The orientation (tool frame to world) the IK holds for an arm's tool.
  void set_tool_orientation(Arm arm, const Eigen::Matrix3d& orientation);
  // Puts an arm's tool at `position` (world frame, the arm's tool orientation)
  // at once, the robot at rest there: IK from the arm's last solution. Returns
  // the failure category, "" when placed (else nothing moves).
  std::string place_tool(Arm arm, const Eigen::Vector3d& position);

  // One tick: IK for both tool targets (world frame), joint targets, one
  // physics step. Returns the failure category of the tick, "" when fine;
  // failure_detail() says more.
  std::string track(const Eigen::Vector3d& left_target, const Eigen::Vector3d& right_target);

  // Whether inverse kinematics (from the last solutions) finds joint positions
  // for both tool targets, without moving: "" when it does, else
  // "<category>: <detail>" with the category track() would return.
  std::string reach(const Eigen::Vector3d& left_target, const Eigen::Vector3d& right_target) const;

  // The executed tool pose (world frame).
  Eigen::Isometry3d tool_pose(Arm arm) const;
  Eigen::Vector3d tool_position(Arm arm) const { return tool_pose(arm).translation(); }
  // Every collision shape of the robot at its executed pose (world frame).
  std::vector<PlacedShape> shapes() const;
  // Only the world poses of shapes(), in its order.
  std::vector<Eigen::Isometry3d> shape_poses() const;
  // The links an arm's joints move (its links, hand and tool frame), and of
  // those the hand: the links fixed below its last joint (gripper, fingers,
  // tool frame), whose shapes a task leaves out where its own gripper stands in.
  const std::vector<std::string>& arm_links(Arm arm) const;
  const std::vector<std::string>& hand_links(Arm arm) const;

  const std::string& failure_detail() const { return failure_detail_; }
  // Simulated time since construction (s): one tick per track().
  double time() const;

  // Inverse kinematics statistics of track() since construction.
  struct IkStats {
    long solves = 0;  // tool targets track() solved with the IK
    // Tool targets answered by the arm's last solution without solving: the
    // target had not moved (the same tool pose in the base frame, bit for bit,
    // as at the arm's last solve in track()), so the joint targets stay.
    long reused = 0;
    long failures = 0;  // of the solves
  };
  const IkStats& ik_stats() const { return ik_stats_; }
  // Also adds the wall time of each of track()'s solves to `times` (shared by a
  // task's robots; null: not).
  void time_solves_into(std::shared_ptr<IkSolveTimes> times) { solve_times_ = std::move(times); }
  // The largest joint tracking error (rad or m) since the last reset.
  double max_tracking_error() const { return max_tracking_error_; }

 private:
  struct ArmState;
  DualArmParams params_;
  RobotModel model_;
  size_t shape_count_ = 0;  // collision shapes of all links
  std::unique_ptr<RobotDynamics> dynamics_;
  std::array<std::unique_ptr<ArmState>, 2> arms_;
  int base_link_ = -1;  // index into the model's links
  IkStats ik_stats_;
  std::shared_ptr<IkSolveTimes> solve_times_;
  double max_tracking_error_ = 0.0;
  std::string failure_detail_;
};

}  // namespace corrmp
