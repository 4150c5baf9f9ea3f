// Environment `rope_knot` (paper, Section IV-C "Knotting with the real
// robot", in simulation): two grippers tie a half hitch of a soft rope over a
// bar. Trajectory rows are [Lx, Ly, Lz, Lgrip, Rx, Ry, Rz, Rgrip] (metres;
// grip 1 closed, 0 open). pre-MP loops the rope over the bar and presents the
// free end; the critical point is just before the left gripper encloses it;
// cor-MP is a correction relative to the grippers' positions there (so it
// applies anywhere in the workspace); post-MP encloses, pulls the end through
// the loop, tightens and releases. The outcome is the knot check after the
// release, with a failure category. The head camera renders RGB-D with its
// camera model, for the colour-segmented rope-end context.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "envs/environment.hpp"
#include "envs/rope_knot/rope_knot_params.hpp"
#include "envs/rope_knot/rope_knot_scene.hpp"
#include "sim/head_camera.hpp"

namespace corrmp {

struct RopeKnotEnvironmentParams {
  RopeKnotParams task;
  // Behind the grippers and above the bar, looking at the critical point:
  // the rope end is seen in 97% of the demonstrations' images (94% at
  // 320 x 240, 69-89% from above or from a side).
  HeadCameraParams camera{480, 360, 30.0, {-0.1, 0.0, 0.6}, {0.35, 0.05, 0.15}, {0.92, 0.92, 0.9}};
  double decision_threshold = 0.01;

  // The task's parameters sit at the section's top level, beside these.
  template <class Fields>
  void describe(Fields& f) {
    task.describe(f);
    f("camera", camera, "the robot's head camera (RGB-D)");
    f("decision_threshold", decision_threshold,
      "a correction moving the enclosing gripper less than this along an axis (m) does not "
      "count as moving along it",
      positive());
  }
};

// The correction types of the paper's knotting demonstrations, by the left
// gripper's displacement d: "none" when no axis moves more than the
// threshold; "posterior-to-anterior" (+x, away from the robot),
// "anterior-to-posterior" (-x), "lateral" (y) or "vertical" (z) when one
// axis does; "combined" when several do.
std::string classify_rope_correction(const Eigen::Vector3d& displacement, double threshold);
const std::vector<std::string>& rope_correction_labels();

class RopeKnot : public Environment {
 public:
  explicit RopeKnot(const RopeKnotEnvironmentParams& params);
  ~RopeKnot() override;

  std::unique_ptr<Environment> clone() const override;
  TaskReport report() const override;
  Scenario sample_scenario(Rng& rng) const override;
  void reset(const Scenario& scenario) override;
  std::vector<SegmentInfo> segments() const override;
  Eigen::RowVectorXd effector_position() const override;
  std::string execute(const std::string& segment, const Eigen::MatrixXd& trajectory) override;
  // Where the grippers were, with the hand's drift and the tracking noise
  // (RopeKnotScene::executed): offsets from the segment's start as its rows
  // are for a relative segment.
  Eigen::MatrixXd executed_path() const override { return executed_; }
  Observation observe(bool with_image) override;
  cv::Size camera_size() const override { return {params_.camera.width, params_.camera.height}; }
  std::vector<std::string> state_names() const override;
  Outcome outcome() const override;
  std::string classify_decision(const Eigen::MatrixXd& trajectory) const override;
  void write_figures(const std::string& directory, const std::vector<EvaluatedTrial>& trials,
                     const std::vector<Demonstration>& train) const override;
  // On the arms: the robot's run metrics and its IK time per solve
  // (sim/robot/robot_run_metrics.hpp).
  RunAdditions run_additions(const std::vector<EvaluatedTrial>& trials,
                             const std::string& label) const override;

  const RopeKnotEnvironmentParams& params() const { return params_; }
  RopeKnotScene& scene() { return scene_; }
  const RopeKnotScene& scene() const { return scene_; }

 private:
  bool is_relative(const std::string& segment) const;

  RopeKnotEnvironmentParams params_;
  RopeKnotScene scene_;
  std::unique_ptr<HeadCamera> camera_;
  std::string fault_;
  Eigen::MatrixXd executed_;  // of the last execute()
  // The true rope-end offset from the left gripper after pre-MP.
  std::optional<Eigen::Vector3d> critical_offset_;
  // The wall time of the arms' IK solves, shared with the clones.
  std::shared_ptr<IkSolveTimes> ik_times_ = std::make_shared<IkSolveTimes>();
};

}  // namespace corrmp
