// The rope_knot environment (rope_knot.hpp).
#include "envs/rope_knot/rope_knot.hpp"

#include <fmt/format.h>

#include <cmath>

#include "envs/rope_knot/rope_knot_figure.hpp"
#include "sim/robot/robot_run_metrics.hpp"

namespace corrmp {

namespace {

constexpr const char* kPhysicsFault = "physics fault";
constexpr const char* kInvalidTrajectory = "invalid trajectory";

// The grippers as the robot commands them. The left hand's drift and the
// right hand's tracking noise are hardware errors the rows do not know of;
// they show in where the grippers are.
Eigen::RowVectorXd row_of(const RopeKnotScene& scene) {
  Eigen::RowVectorXd row(8);
  const Eigen::Vector3d left = scene.left_command(), right = scene.right_command();
  row << left.x(), left.y(), left.z(), scene.left_closed() ? 1.0 : 0.0, right.x(), right.y(),
      right.z(), scene.right_closed() ? 1.0 : 0.0;
  return row;
}

}  // namespace

const std::vector<std::string>& rope_correction_labels() {
  static const std::vector<std::string> labels{
      "none", "posterior-to-anterior", "anterior-to-posterior", "lateral", "vertical", "combined"};
  return labels;
}

std::string classify_rope_correction(const Eigen::Vector3d& d, double threshold) {
  const bool x = std::abs(d.x()) > threshold, y = std::abs(d.y()) > threshold,
             z = std::abs(d.z()) > threshold;
  const int moved = x + y + z;
  if (moved == 0) return "none";
  if (moved > 1) return "combined";
  if (x) return d.x() > 0 ? "posterior-to-anterior" : "anterior-to-posterior";
  return y ? "lateral" : "vertical";
}

// The scene starts in the nominal scenario.
RopeKnot::RopeKnot(const RopeKnotEnvironmentParams& params) : params_(params), scene_(params.task) {
  scene_.time_ik_solves_into(ik_times_);
}

RopeKnot::~RopeKnot() = default;

std::unique_ptr<Environment> RopeKnot::clone() const {
  auto copy = std::make_unique<RopeKnot>(params_);
  copy->ik_times_ = ik_times_;
  copy->scene_.time_ik_solves_into(ik_times_);
  return copy;
}

TaskReport RopeKnot::report() const {
  TaskReport report;
  report.trajectory_columns = {"left_x",  "left_y",  "left_z",  "left_grip",
                               "right_x", "right_y", "right_z", "right_grip"};
  report.error_unit = "cm";  // trajectories are in metres
  report.error_scale = 100.0;
  report.error_segments = {"pre", "cor", "post"};
  report.error_columns = {0, 1, 2, 4, 5, 6};     // positions, not grips
  report.relative_columns = {0, 1, 2, 4, 5, 6};  // a correction moves; the grips stay
  report.decision_segment = "cor";
  report.decision_labels = rope_correction_labels();
  report.plot_horizontal = 1;  // the left gripper seen from the robot: y right, z up
  report.plot_vertical = 2;
  report.outcome_metrics = {"knot", "enclosed"};
  report.failure_categories = {"missed enclose", "near miss", "knot lost while tightening",
                               kPhysicsFault, kInvalidTrajectory};
  if (params_.task.robot.on_arms()) {
    for (const char* arm : {"out of reach", "joint limit", "self collision", "tracking error"}) {
      report.failure_categories.push_back(arm);
    }
  }
  return report;
}

Scenario RopeKnot::sample_scenario(Rng& rng) const { return scene_.sample(rng); }

void RopeKnot::reset(const Scenario& scenario) {
  fault_.clear();
  executed_.resize(0, 8);
  critical_offset_.reset();
  scene_.reset(scenario);
  fault_ = scene_.arm_failure();  // the arms could not reach the start
}

std::vector<SegmentInfo> RopeKnot::segments() const {
  const RopeKnotParams& p = params_.task;
  return {
      {"pre", p.pre_points, false}, {"cor", p.cor_points, true}, {"post", p.post_points, false}};
}

Eigen::RowVectorXd RopeKnot::effector_position() const { return row_of(scene_); }

bool RopeKnot::is_relative(const std::string& segment) const {
  for (const auto& s : segments()) {
    if (s.name == segment) return s.relative;
  }
  return false;
}

std::string RopeKnot::execute(const std::string& segment, const Eigen::MatrixXd& trajectory) {
  executed_.resize(0, 8);
  if (!fault_.empty()) return fault_;
  if (trajectory.cols() != 8 || trajectory.rows() < 1 || !trajectory.allFinite()) {
    fault_ = fmt::format("{}: the '{}' trajectory is not a finite {}x8 matrix", kInvalidTrajectory,
                         segment, trajectory.rows());
    return fault_;
  }
  Eigen::MatrixXd rows = trajectory;
  const bool relative = is_relative(segment);
  const Eigen::RowVectorXd origin = row_of(scene_);
  if (relative) {
    for (int c : report().relative_columns) rows.col(c).array() += origin(c);
  }
  const std::string fault = scene_.execute(rows);
  executed_ = scene_.executed();
  if (relative) {
    for (int c : report().relative_columns) executed_.col(c).array() -= origin(c);
  }
  if (segment == "pre" && fault.empty()) critical_offset_ = scene_.end_offset();
  if (!fault.empty()) {
    // An arm failure is its own category; anything else stopping the rope is physics.
    const bool kept = fault.rfind(kPhysicsFault, 0) == 0 || !scene_.arm_failure().empty();
    fault_ = kept ? fault : fmt::format("{}: {}", kPhysicsFault, fault);
  }
  return fault_;
}

std::vector<std::string> RopeKnot::state_names() const {
  return {"gripper_mid_x", "gripper_mid_y", "gripper_mid_z", "right_x",
          "right_y",       "right_z",       "rope_end_dx",   "rope_end_dy",
          "rope_end_dz",   "rope_end_x",    "rope_end_y",    "rope_end_z"};
}

Observation RopeKnot::observe(bool with_image) {
  Observation observation;
  // The gripper mid-point where it is (the head camera sees the gripper as
  // well as the rope), so the context includes the hand's drift.
  const Eigen::Vector3d left = scene_.left_position(), right = scene_.right_position();
  const Eigen::Vector3d end = scene_.rope_end(), offset = scene_.end_offset();
  observation.state = {
      {"gripper_mid_x", left.x()}, {"gripper_mid_y", left.y()}, {"gripper_mid_z", left.z()},
      {"right_x", right.x()},      {"right_y", right.y()},      {"right_z", right.z()},
      {"rope_end_x", end.x()},     {"rope_end_y", end.y()},     {"rope_end_z", end.z()},
      {"rope_end_dx", offset.x()}, {"rope_end_dy", offset.y()}, {"rope_end_dz", offset.z()}};
  if (with_image) {
    if (!camera_) camera_ = std::make_unique<HeadCamera>(params_.camera);
    const RgbdImage image = camera_->capture(scene_.render_scene());
    observation.rgb = image.rgb;
    observation.depth = image.depth;
    observation.camera = CameraView{camera_->intrinsics(), camera_->world_from_camera()};
  }
  return observation;
}

Outcome RopeKnot::outcome() const {
  Outcome outcome;
  if (!fault_.empty()) {
    outcome.failure = fault_;
  } else {
    const RopeKnotOutcome knot = scene_.outcome();
    outcome.success = knot.knot;
    outcome.failure = knot.failure;
  }
  const auto starts = [&](const char* category) { return outcome.failure.rfind(category, 0) == 0; };
  outcome.metrics["knot"] = outcome.success ? 1.0 : 0.0;
  outcome.metrics["enclosed"] =
      starts("missed enclose") || starts("near miss") || (!fault_.empty()) ? 0.0 : 1.0;
  if (critical_offset_) {
    outcome.details["critical_end_dx"] = critical_offset_->x();
    outcome.details["critical_end_dy"] = critical_offset_->y();
    outcome.details["critical_end_dz"] = critical_offset_->z();
  }
  if (const DualArm* arms = scene_.arms()) add_robot_details(*arms, outcome.details);
  return outcome;
}

std::string RopeKnot::classify_decision(const Eigen::MatrixXd& trajectory) const {
  if (trajectory.rows() == 0 || trajectory.cols() < 3) return "";
  const Eigen::Vector3d displacement =
      (trajectory.row(trajectory.rows() - 1) - trajectory.row(0)).head<3>().transpose();
  return classify_rope_correction(displacement, params_.decision_threshold);
}

void RopeKnot::write_figures(const std::string& directory,
                             const std::vector<EvaluatedTrial>& trials,
                             const std::vector<Demonstration>& train) const {
  write_knotting_figure(trials, train, report().failure_categories, directory + "/knotting.png");
}

Environment::RunAdditions RopeKnot::run_additions(const std::vector<EvaluatedTrial>& trials,
                                                  const std::string& label) const {
  if (!params_.task.robot.on_arms()) return {};
  return {robot_run_metrics(trials), ik_time_log_line(*ik_times_, label)};
}

}  // namespace corrmp
