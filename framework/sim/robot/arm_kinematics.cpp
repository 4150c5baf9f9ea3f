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

using Vector6 = Eigen::Matrix<double, 6, 1>;

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

Eigen::Isometry3d ArmKinematics::pose_and_jacobian(const Eigen::VectorXd& q,
                                                   Jacobian* jacobian) const {
  const int n = joints();
  // Each movable joint's axis and a point on it, in the base frame.
  Eigen::Matrix<double, 3, Eigen::Dynamic> axes(3, n), points(3, n);
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
  return pose_and_jacobian(q, nullptr);
}

int ArmKinematics::descend(const Eigen::Isometry3d& target, Eigen::VectorXd& q,
                           bool respect_limits) const {
  // Residuals in units of their tolerances: the tool's position and rotation
  // errors, then for each joint how far it is outside its limits (narrowed by
  // a small margin). The descent goes a hundred times further than the
  // tolerances so that nearby targets give nearby solutions.
  const int n = joints();
  const double limit_margin = 1e-3;     // rad or m
  const double limit_tolerance = 1e-2;  // rad or m
  Eigen::VectorXd weights(6 + n);
  weights << Eigen::Vector3d::Constant(1.0 / params_.position_tolerance),
      Eigen::Vector3d::Constant(1.0 / params_.orientation_tolerance),
      Eigen::VectorXd::Constant(n, 1.0 / limit_tolerance);
  const double unbounded = respect_limits ? 0.0 : INFINITY;
  const Eigen::VectorXd low = lower_.array() + limit_margin - unbounded;
  const Eigen::VectorXd high = upper_.array() - limit_margin + unbounded;
  const double converged = 1e-2;
  Jacobian tool_jacobian(6, n);
  Eigen::MatrixXd jacobian(6 + n, n);
  auto evaluate = [&](const Eigen::VectorXd& at, Eigen::VectorXd& error, Eigen::MatrixXd& normal,
                      Eigen::VectorXd& gradient) {
    const Eigen::Isometry3d pose = pose_and_jacobian(at, &tool_jacobian);
    error.head<3>() = target.translation() - pose.translation();
    error.segment<3>(3) = rotation_error(pose.linear(), target.linear());
    error.tail(n) = at.cwiseMax(low).cwiseMin(high) - at;
    jacobian.topRows<6>() = tool_jacobian;
    jacobian.bottomRows(n) = (error.tail(n).array() != 0.0).cast<double>().matrix().asDiagonal();
    error.array() *= weights.array();
    jacobian = weights.asDiagonal() * jacobian;
    normal = jacobian.transpose() * jacobian;
    gradient = jacobian.transpose() * error;
  };
  auto within = [&](const Eigen::VectorXd& error) {
    return error.head<3>().norm() <= converged && error.segment<3>(3).norm() <= converged &&
           error.tail(n).norm() <= converged;
  };
  Eigen::VectorXd error(6 + n), trial_error(6 + n);
  Eigen::MatrixXd normal(n, n), trial_normal(n, n);
  Eigen::VectorXd gradient(n), trial_gradient(n), step(n), trial(n);
  wrap_revolute(q);
  evaluate(q, error, normal, gradient);
  double damping = 1e-3 * std::max(normal.diagonal().maxCoeff(), 1.0);
  double growth = 2.0;
  int iterations = 0;
  while (iterations < params_.max_iterations && !within(error)) {
    ++iterations;
    Eigen::MatrixXd damped = normal;
    damped.diagonal().array() += damping;
    step = damped.ldlt().solve(gradient);
    if (!(step.norm() > 1e-14 * (1.0 + q.norm()))) break;
    trial = q + step;
    wrap_revolute(trial);
    evaluate(trial, trial_error, trial_normal, trial_gradient);
    const double predicted = 0.5 * step.dot(damping * step + gradient);
    const double gain = 0.5 * (error.squaredNorm() - trial_error.squaredNorm()) / predicted;
    if (gain > 0.0) {
      q = trial;
      error = trial_error;
      normal.swap(trial_normal);
      gradient.swap(trial_gradient);
      damping *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * gain - 1.0, 3));
      growth = 2.0;
    } else {
      damping *= growth;
      growth *= 2.0;
    }
  }
  return iterations;
}

void ArmKinematics::wrap_revolute(Eigen::VectorXd& q) const {
  const double turn = 2.0 * M_PI;
  for (int j = 0; j < q.size(); ++j) {
    if (!revolute_[j] || (q(j) >= lower_(j) && q(j) <= upper_(j))) continue;
    const double shifted = q(j) - turn * std::floor((q(j) - lower_(j)) / turn);
    if (shifted <= upper_(j)) q(j) = shifted;
  }
}

bool ArmKinematics::within_limits(const Eigen::VectorXd& q) const {
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
    Eigen::VectorXd q = attempt == 0 ? result.q : Eigen::VectorXd(restart_seeds_.col(attempt - 1));
    result.restarts = attempt;
    // Within the limits first; when that fails, ignoring them, to tell a
    // target out of reach from one reached only outside the limits.
    for (const bool respect_limits : {true, false}) {
      result.iterations += descend(target, q, respect_limits);
      const Eigen::Isometry3d pose = forward(q);
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
