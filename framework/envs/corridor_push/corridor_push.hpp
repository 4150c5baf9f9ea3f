// Environment `corridor_push` (paper, Section IV-A): a gripper pushes an object
// towards a narrow corridor whose position is perturbed along x. pre-MP brings
// the object in front of the corridor (the critical point); cor-MP pushes it
// further (+x), pulls it back (-x) or leaves it; post-MP pushes it through.
// Success: the object's centre passes the corridor's midpoint without the
// object touching the corridor.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "envs/corridor_push/corridor_push_params.hpp"
#include "envs/environment.hpp"
#include "sim/bullet_world.hpp"
#include "sim/head_camera.hpp"
#include "sim/kinematic_gripper.hpp"
#include "sim/robot/dual_arm.hpp"
#include "sim/robot/ik_solve_times.hpp"
#include "sim/scene_description.hpp"

namespace corrmp {

class CorridorPush : public Environment {
 public:
  explicit CorridorPush(const CorridorPushParams& params);
  ~CorridorPush() override;

  std::unique_ptr<Environment> clone() const override;
  TaskReport report() const override;
  Scenario sample_scenario(Rng& rng) const override;
  void reset(const Scenario& scenario) override;
  std::vector<SegmentInfo> segments() const override;
  Eigen::RowVectorXd effector_position() const override;
  std::string execute(const std::string& segment, const Eigen::MatrixXd& trajectory) override;
  // The tool position when the command reached each row: the floating
  // gripper's is the command's; the arm's is where its tool frame was.
  Eigen::MatrixXd executed_path() const override { return executed_; }
  Observation observe(bool with_image) override;
  cv::Size camera_size() const override { return {params_.camera.width, params_.camera.height}; }
  std::vector<std::string> state_names() const override;
  Outcome outcome() const override;
  std::string classify_decision(const Eigen::MatrixXd& trajectory) const override;
  // On the arms: the robot's run metrics and its IK time per solve
  // (sim/robot/robot_run_metrics.hpp).
  RunAdditions run_additions(const std::vector<EvaluatedTrial>& trials,
                             const std::string& label) const override;

  const CorridorPushParams& params() const { return params_; }
  // Geometry the expert plans with.
  double corridor_x() const;      // centre of the corridor gap
  double corridor_mid_y() const;  // midpoint of the corridor along y
  Eigen::Vector3d object_position() const;
  double object_half_size() const;         // half the object's width
  double tool_half_width_x() const;        // closed fingers, along x
  double tool_half_width_y() const;        // along y
  Eigen::Vector3d start_position() const;  // the tool's position at reset
  // The dual-arm robot carrying the gripper; null when the gripper floats.
  const DualArm* robot() const { return robot_.get(); }

 private:
  CorridorPushParams params_;
  SceneDescription scene_;
  double nominal_corridor_x_;
  Scenario scenario_;
  std::unique_ptr<BulletWorld> world_;
  std::unique_ptr<DualArm> robot_;  // on arms only
  // The wall time of the robots' IK solves, shared with the clones.
  std::shared_ptr<IkSolveTimes> ik_times_ = std::make_shared<IkSolveTimes>();
  std::unique_ptr<Gripper> gripper_;
  int object_ = -1, wall_left_ = -1, wall_right_ = -1;
  bool touched_corridor_ = false;
  std::string failure_;
  Eigen::MatrixXd executed_;  // of the last execute()
  std::unique_ptr<HeadCamera> camera_;
};

}  // namespace corrmp
