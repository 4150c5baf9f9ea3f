// A robot simulated as fixed-base Featherstone multibodies in its own Bullet
// world, one per branch of its root link (the arms of a fixed torso do not move
// one another), tracking commanded joint trajectories (the paper's robot
// controller tracking IK joint trajectories fed at a nominal rate) with a
// velocity-limited motor law per joint. Each tick the controller's joint
// torques come from the robot's inverse dynamics (joint_torques.hpp): every
// joint reaches the velocity its motor law asks for after the step, unless its
// effort limit binds; then it is pushed at that limit and the others still
// reach theirs. Bullet integrates the multibody under those torques; its
// constraint solver (MLCP with Dantzig's method, the iterative solver only
// where that fails) handles only joint limits and contacts. A branch holding
// still is braked: once its joints have reached
// targets unchanged since the last step, with no target velocity, and stopped
// (within params.brake_tolerance), it is frozen and not simulated until its
// command moves; its links are flagged static meanwhile so that a moving
// branch never wakes it through their shared simulation island.
// Fixed time step, one internal step per tick: a fresh robot replays identically.
//
// Model to multibody: see multibody_layout.hpp (fixed joints merged, body
// frames at the principal centre-of-mass axes). Bullet's scalars are single
// precision here, so link poses agree with the model's double-precision
// forward kinematics to about 1e-6, not to rounding.
//
// Checks after every tick, most severe first (check() returns one, "" when fine):
//   "physics fault"   a joint position or velocity is not finite;
//   "self collision"  two links of the robot touch (contact distance below
//                     params.contact_margin), except parent/child pairs, pairs
//                     touching at q = 0 (joint housings built to overlap) and the
//                     pairs passed as `allowed_contacts`; those never collide;
//   "joint limit"     a joint is outside its limits by more than
//                     params.joint_limit_margin, or the last command asked for a
//                     position beyond them (the command is clamped to the
//                     limits, and hard limit constraints hold the joint);
//   "tracking error"  a joint is further than params.tracking_error_bound from
//                     its commanded target (joint units: rad or m).
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/config/field_rule.hpp"
#include "sim/robot/multibody_layout.hpp"
#include "sim/robot/robot_model.hpp"

namespace corrmp {

struct RobotDynamicsParams {
  double time_step = 1.0 / 240.0;
  double gravity = 9.81;
  int solver_iterations = 50;  // of the iterative solver, where the exact solve fails
  // The motor law: each joint is driven to the velocity
  //   position_gain * (position error) / time_step
  //   + velocity_gain * target_velocity + (1 - velocity_gain) * velocity,
  // (velocity: the joint's after this tick with no joint torque), clamped to the
  // joint's velocity limit, with a torque within its effort limit.
  double position_gain = 0.2;
  double velocity_gain = 1.0;
  double tracking_error_bound = 0.05;  // rad (m for prismatic joints)
  double joint_limit_margin = 0.01;    // rad (m)
  double contact_margin = 0.001;       // m
  double brake_tolerance = 1e-5;       // rad (m) from the target, and per tick of motion; 0: never

  template <class Fields>
  void describe(Fields& f) {
    f("time_step", time_step, "simulation tick (s); one internal step per tick",
      in_range(1e-4, 0.05));
    f("gravity", gravity, "gravity magnitude (m/s^2)", at_least(0.0));
    f("solver_iterations", solver_iterations, "constraint solver iterations", in_range(1, 1000));
    f("position_gain", position_gain, "joint motor position gain (fraction of the error per tick)",
      in_range(0.0, 1.0));
    f("velocity_gain", velocity_gain, "joint motor velocity gain", in_range(0.0, 1.0));
    f("tracking_error_bound", tracking_error_bound,
      "largest joint tracking error before a failure (rad or m)", positive());
    f("joint_limit_margin", joint_limit_margin,
      "how far a joint may pass its limits before a failure (rad or m)", at_least(0.0));
    f("contact_margin", contact_margin, "distance below which links touch (m)", at_least(0.0));
    f("brake_tolerance", brake_tolerance,
      "an arm this close to unchanged targets and moving less than this per tick is braked "
      "until its targets move (rad or m; 0: never braked)",
      at_least(0.0));
  }
};

class RobotDynamics {
 public:
  // The robot's root link at `base_pose` in the world, at q = 0 and at rest.
  // `allowed_contacts` names link pairs that may overlap (never collide).
  // Throws std::invalid_argument for a malformed model (multibody_layout.hpp)
  // or an unknown link in `allowed_contacts`.
  RobotDynamics(const RobotModel& model, const RobotDynamicsParams& params,
                const Eigen::Isometry3d& base_pose = Eigen::Isometry3d::Identity(),
                const std::vector<std::pair<std::string, std::string>>& allowed_contacts = {});
  ~RobotDynamics();
  RobotDynamics(const RobotDynamics&) = delete;
  RobotDynamics& operator=(const RobotDynamics&) = delete;

  // The movable joints in model order: the order of every joint vector here.
  int dof() const { return static_cast<int>(joint_names_.size()); }
  const std::vector<std::string>& joint_names() const { return joint_names_; }
  int joint_index(const std::string& name) const;  // -1 when absent
  Eigen::VectorXd lower_limits() const;
  Eigen::VectorXd upper_limits() const;
  Eigen::VectorXd velocity_limits() const;  // rad/s or m/s

  // Puts the arm at `q` at rest, holding it there (targets = q), and clears the check.
  void reset(const Eigen::VectorXd& q);

  // Targets for the following ticks, clamped to the joint limits. Each tick the
  // motor's position target moves towards them by at most velocity limit x
  // time_step. Without velocities, the target velocity is the motion of that
  // position target over the tick; given velocities are clamped to the limits.
  void set_targets(const Eigen::VectorXd& positions);
  void set_targets(const Eigen::VectorXd& positions, const Eigen::VectorXd& velocities);

  void step();
  double time() const { return time_; }
  // How many of the robot's branches (its multibodies) are braked now.
  int braked_branches() const;
  double time_step() const { return params_.time_step; }

  Eigen::VectorXd positions() const;
  Eigen::VectorXd velocities() const;
  const Eigen::VectorXd& targets() const { return target_; }
  // The model link's frame (not its centre of mass) in the world; throws
  // std::invalid_argument for an unknown link.
  Eigen::Isometry3d link_pose(const std::string& link) const;
  // The index of a model link (into RobotModel::links), -1 when absent, and
  // the pose of the link with that index.
  int link_index(const std::string& link) const;
  Eigen::Isometry3d link_pose(int link) const;

  // The failure category of the last tick, "" when fine (see the top of this file).
  const std::string& check() const { return failure_; }
  // What the failure was, e.g. "joint 'j2' at 1.71 beyond [-1.5, 1.5]".
  const std::string& failure_detail() const { return failure_detail_; }

 private:
  struct Bullet;
  void build_multibody(const Eigen::Isometry3d& base_pose);
  void build_colliders();
  void build_limits();
  // The i-th movable joint, and one field of each movable joint.
  const RobotJoint& joint(int i) const;
  Eigen::VectorXd per_joint(double RobotJoint::*field) const;
  // Joint torques for one multibody's joints, applied for the next step: each
  // joint reaches the velocity its motor law asks for after the step, within
  // its effort limit.
  void apply_joint_torques(int branch, const Eigen::VectorXd& position_target,
                           const Eigen::VectorXd& velocity_target);
  void allow_contacts_at_zero(const std::vector<std::pair<std::string, std::string>>& allowed);
  void update_kinematics();
  bool command_moved(int joint) const;
  void release_moved_brakes();
  void brake_still_branches();
  void run_checks();
  bool fail(const std::string& category, const std::string& detail);

  RobotModel model_;
  RobotDynamicsParams params_;
  MultibodyLayout layout_;
  std::vector<std::string> joint_names_;
  // Per model link: its frame in its body's centre-of-mass frame.
  std::vector<Eigen::Isometry3d> link_in_com_;
  std::unique_ptr<Bullet> bullet_;
  Eigen::VectorXd target_;           // requested, clamped to the limits
  Eigen::VectorXd target_velocity_;  // requested; empty when not given
  Eigen::VectorXd motor_target_;     // moving towards target_ at the velocity limits
  Eigen::VectorXd last_target_;      // target_ at the last step
  bool target_beyond_limits_ = false;
  std::string target_detail_;
  std::string failure_;
  std::string failure_detail_;
  double time_ = 0.0;
};

}  // namespace corrmp
