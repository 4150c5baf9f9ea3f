#include "sim/robot/arm_kinematics.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/config/config_error.hpp"
#include "core/seeds.hpp"
#include "sim/robot/kdl_chain.hpp"

namespace corrmp {
namespace {

Eigen::Vector3d eigen_vector(const KDL::Vector& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }

Eigen::Isometry3d isometry_of(const KDL::Frame& frame) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    pose.translation()(r) = frame.p(r);
    for (int c = 0; c < 3; ++c) pose.linear()(r, c) = frame.M(r, c);
  }
  return pose;
}

// The rotation taking `from` to `to` as axis times angle, in the base frame.
Eigen::Vector3d rotation_error(const Eigen::Matrix3d& from, const Eigen::Matrix3d& to) {
  const Eigen::AngleAxisd rotation(Eigen::Matrix3d(to * from.transpose()));
  return rotation.angle() * rotation.axis();
}

double angle_between(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  const Eigen::Matrix3d r = a.transpose() * b;
  const Eigen::Vector3d axis_sin(r(2, 1) - r(1, 2), r(0, 2) - r(2, 0), r(1, 0) - r(0, 1));
  return std::atan2(0.5 * axis_sin.norm(), 0.5 * (r.trace() - 1.0));
}

}  // namespace

const char* to_string(IkResult::Status status) {
  switch (status) {
    case IkResult::Status::ok:
      return "ok";
    case IkResult::Status::out_of_reach:
      return "out_of_reach";
    case IkResult::Status::joint_limit:
      return "joint_limit";
  }
  return "?";
}

ArmKinematics::ArmKinematics(const RobotModel& model, const std::string& base,
                             const std::string& tool, const IkParams& params)
    : params_(params), chain_(kdl_chain(model, base, tool)) {
  for (int index : model.chain(base, tool)) {
    const RobotJoint& joint = model.joints[index];
    if (joint.type == JointType::fixed) continue;
    names_.push_back(joint.name);
    revolute_.push_back(joint.type == JointType::revolute);
  }
  const int n = static_cast<int>(names_.size());
  if (n == 0)
    throw ConfigError(model.source + ": no movable joint from '" + base + "' to '" + tool + "'");
  if (n > kMaxJoints)
    throw ConfigError(model.source + ": " + std::to_string(n) + " movable joints from '" + base +
                      "' to '" + tool + "', an arm may have at most " + std::to_string(kMaxJoints));
  lower_.resize(n);
  upper_.resize(n);
  for (int j = 0; j < n; ++j) {
    const RobotJoint& joint = model.joints[model.joint_index(names_[j])];
    lower_(j) = joint.lower;
    upper_(j) = joint.upper;
  }
  Rng rng(params_.restart_seed);
  restart_seeds_.resize(n, params_.restarts);
  for (int s = 0; s < params_.restarts; ++s)
    for (int j = 0; j < n; ++j) restart_seeds_(j, s) = rng.uniform(lower_(j), upper_(j));
}

Eigen::Isometry3d ArmKinematics::pose_and_jacobian(const JointVector& q, Jacobian* jacobian) const {
  const int n = joints();
  // Each movable joint's axis and a point on it, in the base frame.
  Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, kMaxJoints> axes(3, n), points(3, n);
  KDL::Frame frame = KDL::Frame::Identity();
  int j = 0;
  for (const KDL::Segment& segment : chain_.segments) {
    const KDL::Joint& joint = segment.getJoint();
    if (joint.getType() == KDL::Joint::Fixed) {
      frame = frame * segment.pose(0.0);
      continue;
    }
    axes.col(j) = eigen_vector(frame.M * joint.JointAxis());
    points.col(j) = eigen_vector(frame * joint.JointOrigin());
    frame = frame * segment.pose(q(j));
    ++j;
  }
  const Eigen::Isometry3d tool = isometry_of(frame);
  if (jacobian) {
    jacobian->resize(6, n);
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector3d axis = axes.col(k);
      if (revolute_[k]) {
        jacobian->col(k).head<3>() = axis.cross(tool.translation() - points.col(k));
        jacobian->col(k).tail<3>() = axis;
      } else {
        jacobian->col(k).head<3>() = axis;
        jacobian->col(k).tail<3>().setZero();
      }
    }
  }
  return tool;
}

Eigen::Isometry3d ArmKinematics::forward(const Eigen::VectorXd& q) const {
  if (q.size() != joints())
    throw std::invalid_argument("ArmKinematics::forward: " + std::to_string(q.size()) +
                                " joint positions, the arm has " + std::to_string(joints()));
  return pose_and_jacobian(q, nullptr);
}

int ArmKinematics::descend(const Eigen::Isometry3d& target, JointVector& q, bool respect_limits,
                           Eigen::Isometry3d& pose) const {
  // Residuals in units of their tolerances: the tool's position and rotation
  // errors, then for each joint how far it is outside its limits (narrowed by
  // a small margin). The descent goes a hundred times further than the
  // tolerances so that nearby targets give nearby solutions.
  using JointMatrix =
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxJoints, kMaxJoints>;
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  const int n = joints();
  const double limit_margin = 1e-3;  // rad or m
  const double limit_weight = 1e2;   // 1 / the limit residual's tolerance (rad or m)
  Vector6 weights;
  weights << Eigen::Vector3d::Constant(1.0 / params_.position_tolerance),
      Eigen::Vector3d::Constant(1.0 / params_.orientation_tolerance);
  const double unbounded = respect_limits ? 0.0 : INFINITY;
  const JointVector low = lower_.array() + limit_margin - unbounded;
  const JointVector high = upper_.array() - limit_margin + unbounded;
  const double converged = 1e-2;
  // The weighted residuals at a configuration, the normal equations' matrix
  // and right-hand side: the tool's rows, plus each joint outside its
  // narrowed limits as a row of its own.
  struct Residual {
    Eigen::Isometry3d pose;
    Vector6 tool;
    JointVector limits;
    JointMatrix normal;
    JointVector gradient;
    double squared_norm() const { return tool.squaredNorm() + limits.squaredNorm(); }
  };
  Jacobian jacobian(6, n);
  auto evaluate = [&](const JointVector& at, Residual& r) {
    r.pose = pose_and_jacobian(at, &jacobian);
    r.tool.head<3>() = target.translation() - r.pose.translation();
    r.tool.tail<3>() = rotation_error(r.pose.linear(), target.linear());
    r.tool.array() *= weights.array();
    jacobian = weights.asDiagonal() * jacobian;
    r.limits = limit_weight * (at.cwiseMax(low).cwiseMin(high) - at);
    r.normal.noalias() = jacobian.transpose().lazyProduct(jacobian);
    r.gradient.noalias() = jacobian.transpose().lazyProduct(r.tool);
    for (int j = 0; j < n; ++j) {
      if (r.limits(j) == 0.0) continue;
      r.normal(j, j) += limit_weight * limit_weight;
      r.gradient(j) += limit_weight * r.limits(j);
    }
  };
  auto within = [&](const Residual& r) {
    return r.tool.head<3>().norm() <= converged && r.tool.tail<3>().norm() <= converged &&
           r.limits.norm() <= converged;
  };
  Residual current, trial;
  JointVector step(n), moved(n);
  JointMatrix damped(n, n);
  Eigen::LDLT<JointMatrix> ldlt(n);
  wrap_revolute(q);
  evaluate(q, current);
  double damping = 1e-3 * std::max(current.normal.diagonal().maxCoeff(), 1.0);
  double growth = 2.0;
  int iterations = 0;
  while (iterations < params_.max_iterations && !within(current)) {
    ++iterations;
    damped = current.normal;
    damped.diagonal().array() += damping;
    step = ldlt.compute(damped).solve(current.gradient);
    if (!(step.norm() > 1e-14 * (1.0 + q.norm()))) break;
    moved = q + step;
    wrap_revolute(moved);
    evaluate(moved, trial);
    const double predicted = 0.5 * step.dot(damping * step + current.gradient);
    const double gain = 0.5 * (current.squared_norm() - trial.squared_norm()) / predicted;
    if (gain > 0.0) {
      q = moved;
      std::swap(current, trial);
      damping *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * gain - 1.0, 3));
      growth = 2.0;
    } else {
      damping *= growth;
      growth *= 2.0;
    }
  }
  pose = current.pose;
  return iterations;
}

void ArmKinematics::wrap_revolute(JointVector& q) const {
  const double turn = 2.0 * M_PI;
  for (int j = 0; j < q.size(); ++j) {
    if (!revolute_[j] || (q(j) >= lower_(j) && q(j) <= upper_(j))) continue;
    const double shifted = q(j) - turn * std::floor((q(j) - lower_(j)) / turn);
    if (shifted <= upper_(j)) q(j) = shifted;
  }
}

bool ArmKinematics::within_limits(const JointVector& q) const {
  return (q.array() >= lower_.array()).all() && (q.array() <= upper_.array()).all();
}

IkResult ArmKinematics::solve(const Eigen::Isometry3d& target,
                              const Eigen::VectorXd& warm_start) const {
  if (warm_start.size() != joints())
    throw std::invalid_argument("ArmKinematics::solve: warm start of " +
                                std::to_string(warm_start.size()) + " joints, the arm has " +
                                std::to_string(joints()));
  IkResult result;
  result.q = warm_start.cwiseMax(lower_).cwiseMin(upper_);
  bool reached = false;
  double best_score = INFINITY;
  for (int attempt = 0; attempt <= params_.restarts; ++attempt) {
    JointVector q =
        attempt == 0 ? JointVector(result.q) : JointVector(restart_seeds_.col(attempt - 1));
    result.restarts = attempt;
    // Within the limits first; when that fails, ignoring them, to tell a
    // target out of reach from one reached only outside the limits.
    for (const bool respect_limits : {true, false}) {
      Eigen::Isometry3d pose;
      result.iterations += descend(target, q, respect_limits, pose);
      const double position = (pose.translation() - target.translation()).norm();
      const double orientation = angle_between(pose.linear(), target.linear());
      const double score =
          position / params_.position_tolerance + orientation / params_.orientation_tolerance;
      if (score < best_score) {
        best_score = score;
        result.position_residual = position;
        result.orientation_residual = orientation;
      }
      if (position > params_.position_tolerance || orientation > params_.orientation_tolerance)
        continue;
      reached = true;
      wrap_revolute(q);
      if (within_limits(q)) {
        result.status = IkResult::Status::ok;
        result.q = q;
        result.position_residual = position;
        result.orientation_residual = orientation;
        return result;
      }
      break;
    }
  }
  result.status = reached ? IkResult::Status::joint_limit : IkResult::Status::out_of_reach;
  return result;
}

}  // namespace corrmp
