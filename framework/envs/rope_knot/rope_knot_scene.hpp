// The physical set-up of the simulated rope-knotting task (paper, Section
// IV-C), without any learning: a soft-body rope with a weight on its standing
// end, a bar, two anchoring grippers that follow rows [Lx, Ly, Lz, Lgrip, Rx,
// Ry, Rz, Rgrip] (metres; grip 1 closed, 0 open, thresholded at 0.5) at
// bounded speed, scenario sampling and the knot outcome. The left gripper is
// the enclosing one; its hand drift is added to the rows it executes after it
// has let go of the standing part (its reach for the free end). The right
// (looping) hand tracks its rows with waypoint noise: an offset interpolated
// linearly between random knots in time, the "invisible" variation of the
// paper's demonstrations.
//
// On the robot's arms (params.robot.type "dual_arm"): each tick the commanded
// gripper positions (rows at bounded speed, plus the drift and noise) go to
// DualArm::track with the grippers' fixed orientations as the tools'; the
// grippers are placed where the tools are. A DualArm failure ("out of reach",
// "joint limit", "self collision", "tracking error", "physics fault") ends the
// execution and is the outcome's failure. The rope does not collide with the
// arm's links: only the grippers' anchors hold it. The rope's left (enclosing)
// gripper is DualArm's Arm::left, its right gripper Arm::right; the config
// says which URDF chain each is (left_tool, right_tool).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "core/seeds.hpp"
#include "data/observation.hpp"
#include "envs/rope_knot/knot_check.hpp"
#include "envs/rope_knot/rope_knot_params.hpp"
#include "sim/render/render_scene.hpp"
#include "sim/robot/dual_arm.hpp"
#include "sim/robot/ik_solve_times.hpp"

namespace corrmp {

struct RopeKnotOutcome {
  bool knot = false;
  // "" on success, else "missed enclose", "near miss", "knot lost while
  // tightening", "physics fault" or, on the arms, a DualArm failure category.
  std::string failure;
  KnotReport report;
};

class RopeKnotScene {
 public:
  // Checks the parameters (3-vectors, motion lists of whole points, every
  // scenario of the grasp and span ranges fits the rope, a base offset range
  // only on the arms; std::invalid_argument naming the key otherwise; a robot
  // that cannot be built, ParameterError naming `robot`) and resets to the
  // nominal scenario.
  explicit RopeKnotScene(const RopeKnotParams& params);
  ~RopeKnotScene();

  // Keys: grasp_offset (m along the rope towards its end), span_offset (m more
  // rope between the weight and the right gripper), drift_x, drift_y, drift_z
  // (m, the left hand's drift, see left_drift()), noise_seed (a whole number in
  // [0, 2^53]: the seed of the right hand's waypoint noise, see right_noise();
  // missing: no noise), base_dx, base_dy, base_dz (m, the robot base's offset
  // from robot.base_position; dual_arm only). Other missing keys are 0. Builds
  // the world, brings the arms' tools to the grippers' start positions, lets
  // the rope settle.
  void reset(const Scenario& scenario);
  // Draws grasp_offset, span_offset, drift_x, drift_y, drift_z, noise_seed
  // (uniform in [0, 2^31)) and then, when base_offset_range is not all zero,
  // base_dx, base_dy, base_dz, in that order.
  Scenario sample(Rng& rng) const;

  // Follows the rows; "" or the physics fault or arm failure that stopped it.
  std::string execute(const Eigen::MatrixXd& rows);
  // Per row of the last execute() the grippers reached (and then gripped as
  // it said): [left_position, left_closed, right_position, right_closed],
  // closed 1, open 0; rows stop where a fault stopped the execution.
  const Eigen::MatrixXd& executed() const { return executed_; }
  // The arm failure that stopped the execution ("<category>: <detail>"), "" if none.
  const std::string& arm_failure() const { return arm_failure_; }
  const DualArm* arms() const { return arms_.get(); }
  // The arms built from now on add the wall time of their IK solves to `times`.
  void time_ik_solves_into(std::shared_ptr<IkSolveTimes> times);

  // Finger mid-points: on the arms, where the tools are.
  Eigen::Vector3d left_position() const;
  // Where the rows put the left gripper: its commanded position without the
  // hand's drift.
  Eigen::Vector3d left_command() const;
  // The left hand's drift: the scenario's drift once the left gripper has let
  // go of the standing part (it reaches for the free end), zero before.
  Eigen::Vector3d left_drift() const;
  Eigen::Vector3d right_position() const;
  // Where the rows put the right gripper: its commanded position without the noise.
  Eigen::Vector3d right_command() const;
  // The right hand's waypoint noise on the row it tracks (or last tracked):
  // with a noise_seed, each axis interpolated linearly in the simulated time
  // since reset at the row's start between knots drawn uniformly in
  // +-waypoint_noise every waypoint_noise_period; zero without one.
  Eigen::Vector3d right_noise() const { return right_noise_; }
  bool left_closed() const;
  bool right_closed() const;
  std::vector<Eigen::Vector3d> rope_nodes() const;
  // The rope end: the centroid of the coloured end's nodes.
  Eigen::Vector3d rope_end() const;
  // The rope end relative to the left (enclosing) gripper's finger mid-point.
  Eigen::Vector3d end_offset() const;
  Eigen::Vector3d bar_centre() const;
  double time() const;

  RenderScene render_scene() const;
  RopeKnotOutcome outcome() const;
  const RopeKnotParams& params() const { return params_; }

 private:
  void tick(const Eigen::Vector3d& left, const Eigen::Vector3d& right);
  void reset_arms(const Scenario& scenario, const Eigen::Vector3d& left,
                  const Eigen::Vector3d& right);
  // The grippers' commanded positions (with drift and noise): floating, where they are.
  Eigen::Vector3d left_point() const;
  Eigen::Vector3d right_point() const;
  std::string set_grips(bool left_closed, bool right_closed);
  Eigen::Vector3d noise_at(double time) const;

  RopeKnotParams params_;
  std::unique_ptr<SoftWorld> world_;
  std::unique_ptr<Rope> rope_;
  std::unique_ptr<AnchorGripper> left_;
  std::unique_ptr<AnchorGripper> right_;
  std::unique_ptr<DualArm> arms_;                          // dual_arm only
  std::shared_ptr<IkSolveTimes> ik_times_;                 // null: not timed
  Eigen::Vector3d left_target_ = Eigen::Vector3d::Zero();  // last commanded (arms)
  Eigen::Vector3d right_target_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d drift_ = Eigen::Vector3d::Zero();
  // The right hand's noise at times 0, waypoint_noise_period, ...; empty: none.
  std::vector<Eigen::Vector3d> noise_knots_;
  Eigen::Vector3d right_noise_ = Eigen::Vector3d::Zero();
  // Nodes anchored at the left gripper's last close after it let go of the
  // standing part (-1: no such close yet); the pre-MP grab does not count.
  int enclosed_ = -1;
  bool near_miss_ = false;    // at that close
  bool drifting_ = false;     // the left gripper has opened once
  std::string fault_;         // what stopped the execution
  std::string arm_failure_;   // when it was the arms
  Eigen::MatrixXd executed_;  // see executed()
};

}  // namespace corrmp
