// Environment `via_point`: a deliberately small planar task, pure kinematics.
// A point effector starts at (0, 0) and must reach a goal at (goal_x, 0),
// passing a via point at (via_x, offset) whose offset along y is the
// scenario. pre-MP moves along the x axis to just before the via point (the
// critical point); cor-MP bends through the via point, above or below the
// axis or straight on, depending on the offset (its perfect context: the
// state value via_y); post-MP goes on to the goal. Success: the path passed
// within via_tolerance of the via point and ended within goal_tolerance of
// the goal. It is the template of a task (docs/architecture.md, "Adding a
// task").
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "envs/environment.hpp"
#include "envs/via_point/via_point_params.hpp"

namespace corrmp {

class ViaPoint : public Environment {
 public:
  explicit ViaPoint(const ViaPointParams& params);

  std::unique_ptr<Environment> clone() const override;
  TaskReport report() const override;
  Scenario sample_scenario(Rng& rng) const override;
  void reset(const Scenario& scenario) override;
  std::vector<SegmentInfo> segments() const override;
  Eigen::RowVectorXd effector_position() const override;
  std::string execute(const std::string& segment, const Eigen::MatrixXd& trajectory) override;
  // The effector walks the trajectory exactly: the rows executed are the rows given.
  Eigen::MatrixXd executed_path() const override { return executed_; }
  Observation observe(bool with_image) override;
  std::vector<std::string> state_names() const override;
  Outcome outcome() const override;
  std::string classify_decision(const Eigen::MatrixXd& trajectory) const override;

  const ViaPointParams& params() const { return params_; }
  Eigen::Vector2d via_point() const { return {params_.via_x, via_y_}; }
  Eigen::Vector2d goal() const { return {params_.goal_x, 0.0}; }
  // Where pre-MP ends (the critical point) and cor-MP ends, on the x axis.
  Eigen::Vector2d critical_point() const { return {params_.via_x - params_.approach, 0.0}; }
  Eigen::Vector2d after_via() const { return {params_.via_x + params_.approach, 0.0}; }
  // The decision a bend of `bend` (m, along y) makes: above, straight or below.
  std::string decision_of(double bend) const;

 private:
  ViaPointParams params_;
  double via_y_ = 0.0;
  Eigen::Vector2d effector_ = Eigen::Vector2d::Zero();
  double closest_to_via_ = 0.0;  // over the path executed since the reset
  std::string failure_;
  Eigen::MatrixXd executed_;  // of the last execute()
};

}  // namespace corrmp
