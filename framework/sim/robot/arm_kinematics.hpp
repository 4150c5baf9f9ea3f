// The kinematics of one arm of a RobotModel: the pose of its tool frame in the
// frame of a base link, and inverse kinematics that reaches a full tool pose
// within tolerances and the model's joint limits: Levenberg-Marquardt on the
// arm's KDL chain, warm-started at the given configuration, then from a fixed
// list of seeds within the limits.
//
// The solver is written here rather than taken from KDL (ChainIkSolverPos_LMA):
// KDL's objects with Eigen members are compiled for the baseline CPU, and this
// project's -march=native builds give Eigen another alignment, so sharing them
// corrupts the heap. Only KDL's Eigen-free types (Chain, Segment, Frame) are used.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <kdl/chain.hpp>
#include <string>
#include <vector>

#include "core/config/field_rule.hpp"
#include "sim/robot/robot_model.hpp"

namespace corrmp {

struct IkParams {
  double position_tolerance = 1e-3;     // m
  double orientation_tolerance = 1e-2;  // rad
  int max_iterations = 200;             // per attempt
  int restarts = 8;                     // attempts from other seeds after the warm start
  uint64_t restart_seed = 1;            // the seeds' generator (the same every call)

  template <class Fields>
  void describe(Fields& f) {
    f("position_tolerance", position_tolerance, "largest tool position error (m)",
      in_range(1e-6, 0.1));
    f("orientation_tolerance", orientation_tolerance, "largest tool orientation error (rad)",
      in_range(1e-6, 1.0));
    f("max_iterations", max_iterations, "solver iterations per attempt", in_range(1, 100000));
    f("restarts", restarts, "attempts from seeds within the limits after the warm start",
      in_range(0, 1000));
    f("restart_seed", restart_seed, "seed of the restart configurations");
  }
};

struct IkResult {
  enum class Status {
    ok,            // q reaches the target within tolerances and limits
    out_of_reach,  // no attempt reached the target
    joint_limit,   // attempts reached the target only outside the joint limits
  };
  Status status = Status::out_of_reach;
  // ok: the solution; otherwise the warm start, clamped into the limits.
  Eigen::VectorXd q;
  // Of the solution, else of the closest attempt (limits ignored).
  double position_residual = 0.0;     // m
  double orientation_residual = 0.0;  // rad
  int iterations = 0;                 // solver iterations over all attempts
  int restarts = 0;                   // attempts after the warm start
};

const char* to_string(IkResult::Status status);

class ArmKinematics {
 public:
  // The most movable joints an arm's chain may have: the solver's matrices
  // live on the stack, sized for this.
  static constexpr int kMaxJoints = 16;

  // Throws ConfigError when `tool` is not below `base` in the model or the
  // chain has more than kMaxJoints movable joints.
  ArmKinematics(const RobotModel& model, const std::string& base, const std::string& tool,
                const IkParams& params = {});

  int joints() const { return static_cast<int>(lower_.size()); }
  const Eigen::VectorXd& lower() const { return lower_; }
  const Eigen::VectorXd& upper() const { return upper_; }
  const std::vector<std::string>& joint_names() const { return names_; }

  // The tool frame in the base frame at joint positions q (std::invalid_argument
  // unless q has joints() entries).
  Eigen::Isometry3d forward(const Eigen::VectorXd& q) const;

  // Joint positions putting the tool frame at `target` (in the base frame),
  // tried first from `warm_start`. Deterministic: the same call gives the
  // same result.
  IkResult solve(const Eigen::Isometry3d& target, const Eigen::VectorXd& warm_start) const;

 private:
  using JointVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxJoints, 1>;
  using Jacobian = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxJoints>;
  // The tool pose at q and, when `jacobian` is given, the geometric Jacobian
  // (linear rows first) in the base frame.
  Eigen::Isometry3d pose_and_jacobian(const JointVector& q, Jacobian* jacobian) const;
  // Levenberg-Marquardt from q towards target, pulling joints back inside
  // their limits when `respect_limits`; returns the iterations and sets
  // `pose` to the tool pose at the final q.
  int descend(const Eigen::Isometry3d& target, JointVector& q, bool respect_limits,
              Eigen::Isometry3d& pose) const;

  // Shifts revolute joints by whole turns into their limits where that is possible.
  void wrap_revolute(JointVector& q) const;
  bool within_limits(const JointVector& q) const;

  IkParams params_;
  KDL::Chain chain_;
  std::vector<std::string> names_;
  std::vector<bool> revolute_;
  Eigen::VectorXd lower_, upper_;
  Eigen::MatrixXd restart_seeds_;  // one column per restart
};

}  // namespace corrmp
