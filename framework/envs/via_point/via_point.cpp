// The via-point reach (via_point.hpp).
#include "envs/via_point/via_point.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/parameter_error.hpp"
#include "envs/via_point/via_point_paths.hpp"

namespace corrmp {

ViaPoint::ViaPoint(const ViaPointParams& params) : params_(params) {
  if (params_.via_x - params_.approach <= 0.0) {
    throw ParameterError("approach",
                         "pre-MP would end behind the start: approach must be below "
                         "via_x");
  }
  if (params_.via_x + params_.approach >= params_.goal_x) {
    throw ParameterError("approach",
                         "cor-MP would end beyond the goal: via_x + approach must be below goal_x");
  }
  reset(Scenario{{"via_offset", 0.0}});
}

std::unique_ptr<Environment> ViaPoint::clone() const { return std::make_unique<ViaPoint>(params_); }

TaskReport ViaPoint::report() const {
  TaskReport report;
  report.trajectory_columns = {"x", "y"};
  report.error_unit = "mm";
  report.error_scale = 1000.0;
  report.error_segments = {"cor", "post"};
  report.error_columns = {0, 1};
  report.decision_segment = "cor";
  report.decision_labels = {"above", "straight", "below"};
  report.relative_columns = {0, 1};
  report.plot_horizontal = 0;
  report.plot_vertical = 1;
  report.outcome_metrics = {"passed_via", "reached_goal"};
  report.failure_categories = {"missed the via point", "missed the goal", "invalid trajectory"};
  return report;
}

Scenario ViaPoint::sample_scenario(Rng& rng) const {
  const double half = params_.via_range / 2;
  return {{"via_offset", rng.uniform(-half, half)}};
}

void ViaPoint::reset(const Scenario& scenario) {
  via_y_ = scenario.at("via_offset");
  effector_ = Eigen::Vector2d::Zero();
  closest_to_via_ = (effector_ - via_point()).norm();
  failure_.clear();
  executed_.resize(0, 2);
}

std::vector<SegmentInfo> ViaPoint::segments() const {
  return {{"pre", params_.pre_points}, {"cor", params_.cor_points}, {"post", params_.post_points}};
}

Eigen::RowVectorXd ViaPoint::effector_position() const { return effector_.transpose(); }

std::string ViaPoint::execute(const std::string&, const Eigen::MatrixXd& trajectory) {
  executed_.resize(0, 2);
  if (!failure_.empty()) return failure_;
  if (trajectory.cols() != 2 || !trajectory.allFinite()) {
    failure_ = fmt::format("invalid trajectory: {} columns, {}", trajectory.cols(),
                           trajectory.allFinite() ? "finite" : "not finite");
    return failure_;
  }
  // The effector moves straight to the trajectory's first point, then along it.
  Eigen::MatrixXd walked(trajectory.rows() + 1, 2);
  walked << effector_.transpose(), trajectory;
  closest_to_via_ = std::min(closest_to_via_, closest_distance(walked, via_point()));
  effector_ = trajectory.row(trajectory.rows() - 1).transpose();
  executed_ = trajectory;
  return "";
}

std::vector<std::string> ViaPoint::state_names() const {
  return {"effector_x", "effector_y", "via_x", "via_y", "goal_x", "goal_y"};
}

Observation ViaPoint::observe(bool) {
  Observation observation;
  observation.state = {{"effector_x", effector_.x()}, {"effector_y", effector_.y()},
                       {"via_x", params_.via_x},      {"via_y", via_y_},
                       {"goal_x", params_.goal_x},    {"goal_y", 0.0}};
  return observation;
}

Outcome ViaPoint::outcome() const {
  const double to_goal = (effector_ - goal()).norm();
  Outcome outcome;
  outcome.metrics = {{"passed_via", closest_to_via_ <= params_.via_tolerance ? 1.0 : 0.0},
                     {"reached_goal", to_goal <= params_.goal_tolerance ? 1.0 : 0.0}};
  outcome.details = {{"via_distance", closest_to_via_}, {"goal_distance", to_goal}};
  if (!failure_.empty()) {
    outcome.failure = failure_;
  } else if (closest_to_via_ > params_.via_tolerance) {
    outcome.failure = fmt::format("missed the via point by {:.1f} mm", 1000 * closest_to_via_);
  } else if (to_goal > params_.goal_tolerance) {
    outcome.failure = fmt::format("missed the goal by {:.1f} mm", 1000 * to_goal);
  } else {
    outcome.success = true;
  }
  return outcome;
}

std::string ViaPoint::decision_of(double bend) const {
  if (bend > params_.straight_band) return "above";
  if (bend < -params_.straight_band) return "below";
  return "straight";
}

std::string ViaPoint::classify_decision(const Eigen::MatrixXd& trajectory) const {
  // The bend: the largest departure along y from the line between the ends.
  double bend = 0.0;
  const Eigen::Index last = trajectory.rows() - 1;
  for (Eigen::Index i = 0; i <= last; ++i) {
    const double s = last > 0 ? static_cast<double>(i) / last : 0.0;
    const double off = trajectory(i, 1) - ((1 - s) * trajectory(0, 1) + s * trajectory(last, 1));
    if (std::abs(off) > std::abs(bend)) bend = off;
  }
  return decision_of(bend);
}

}  // namespace corrmp
