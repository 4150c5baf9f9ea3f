// Tests of the rope_knot environment and its expert as the framework sees
// them: the correction labels, the expert's segments (a relative cor-MP, the
// whole-skill recording with the critical points' spans), replaying the
// expert through the environment with the executed path it records, the camera's model, determinism
// and parallel collection.
#include "envs/rope_knot/rope_knot.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <set>

#include "core/thread_budget.hpp"
#include "envs/rope_knot/rope_expert.hpp"
#include "envs/rope_knot/rope_knot_script.hpp"

namespace corrmp {
namespace {

TEST(RopeKnot, CorrectionsAreLabelledByTheAxesTheyMoveAlong) {
  const double t = 0.01;
  EXPECT_EQ(classify_rope_correction({0.005, -0.005, 0.009}, t), "none");
  EXPECT_EQ(classify_rope_correction({0.02, 0.0, 0.0}, t), "posterior-to-anterior");
  EXPECT_EQ(classify_rope_correction({-0.02, 0.005, 0.0}, t), "anterior-to-posterior");
  EXPECT_EQ(classify_rope_correction({0.0, -0.03, 0.0}, t), "lateral");
  EXPECT_EQ(classify_rope_correction({0.0, 0.0, 0.02}, t), "vertical");
  EXPECT_EQ(classify_rope_correction({0.02, 0.03, 0.0}, t), "combined");
  for (const auto& label : {"none", "lateral", "combined"}) {
    EXPECT_NE(std::find(rope_correction_labels().begin(), rope_correction_labels().end(), label),
              rope_correction_labels().end());
  }
}

// Both grippers' positions (metres) and grips; the errors are in centimetres.
TEST(RopeKnot, DeclaresItsColumnsAndErrorUnit) {
  const TaskReport task = RopeKnot{RopeKnotEnvironmentParams{}}.report();
  EXPECT_EQ(task.trajectory_columns.size(), 8u);
  EXPECT_EQ(task.trajectory_columns.front(), "left_x");
  EXPECT_EQ(task.error_unit, "cm");
  EXPECT_EQ(task.error_scale, 100.0);
}

// The executed path of the last segment: a row per commanded row, in its frame, the grips
// as commanded and each floating gripper where it was commanded but for the left hand's
// drift (the scenario has no tracking noise).
void expect_executed_as_commanded(const RopeKnot& env, const Eigen::MatrixXd& rows,
                                  const std::string& segment) {
  const Eigen::MatrixXd executed = env.executed_path();
  ASSERT_EQ(executed.rows(), rows.rows()) << segment;
  ASSERT_EQ(executed.cols(), 8) << segment;
  const Eigen::Vector3d drift = env.scene().left_drift();
  for (Eigen::Index k = 0; k < rows.rows(); ++k) {
    EXPECT_EQ(executed(k, 3), rows(k, 3) >= 0.5 ? 1.0 : 0.0) << segment << " row " << k;
    EXPECT_EQ(executed(k, 7), rows(k, 7) >= 0.5 ? 1.0 : 0.0) << segment << " row " << k;
    const Eigen::Vector3d left = (executed.row(k) - rows.row(k)).segment<3>(0).transpose();
    EXPECT_LT(std::min(left.norm(), (left - drift).norm()), 1e-9) << segment << " row " << k;
    EXPECT_LT((executed.row(k) - rows.row(k)).segment<3>(4).norm(), 1e-9)
        << segment << " row " << k;
  }
}

TEST(RopeKnot, TheExpertsSegmentsReplayThroughTheEnvironment) {
  RopeKnot env{RopeKnotEnvironmentParams{}};
  RopeExpert expert{RopeExpertParams{}};
  const Scenario scenario{{"grasp_offset", 0.02}, {"drift_y", -0.015}};
  const Demonstration demo = expert.demonstrate(env, scenario, false);
  ASSERT_TRUE(env.outcome().success) << env.outcome().failure;
  for (const char* name : {"pre", "cor", "post", "full"}) ASSERT_NE(demo.find(name), nullptr);
  const SegmentTrajectory& pre = *demo.find("pre");
  const SegmentTrajectory& cor = *demo.find("cor");
  const SegmentTrajectory& post = *demo.find("post");
  const SegmentTrajectory& full = *demo.find("full");
  EXPECT_EQ(cor.y.cols(), 8);
  EXPECT_EQ(cor.y.rows(), env.params().task.cor_points);
  // The correction is relative: it starts at zero offset, the grips as they are.
  EXPECT_LT(cor.y.row(0).head<3>().norm(), 1e-12);
  EXPECT_EQ(cor.y(0, 7), 1.0);  // the right gripper still holds the rope
  EXPECT_EQ(demo.decision,
            classify_rope_correction(cor.y.row(cor.y.rows() - 1).head<3>().transpose(),
                                     env.params().decision_threshold));
  EXPECT_EQ(full.y.rows(), pre.y.rows() + cor.y.rows() + post.y.rows());
  EXPECT_DOUBLE_EQ(pre.phase_begin, 0.0);
  EXPECT_LT(pre.phase_end, cor.phase_begin);
  EXPECT_LT(cor.phase_end, post.phase_begin);
  EXPECT_DOUBLE_EQ(post.phase_end, 1.0);

  // The environment executes the same segments, the relative one from where
  // the grippers are, and ties the knot again.
  env.reset(scenario);
  EXPECT_EQ(env.execute("pre", pre.y), "");
  expect_executed_as_commanded(env, pre.y, "pre");
  EXPECT_LT((env.segment_start("cor") - cor.y.row(0)).norm(), 1e-9);
  EXPECT_EQ(env.execute("cor", cor.y), "");
  expect_executed_as_commanded(env, cor.y, "cor");
  EXPECT_EQ(env.execute("post", post.y), "");
  expect_executed_as_commanded(env, post.y, "post");
  const Outcome outcome = env.outcome();
  EXPECT_TRUE(outcome.success) << outcome.failure;
  EXPECT_EQ(outcome.metrics.at("knot"), 1.0);
  EXPECT_EQ(outcome.metrics.at("enclosed"), 1.0);
  EXPECT_EQ(outcome.details.count("critical_end_dx"), 1u);
}

TEST(RopeKnot, ObservationsCarryTheCameraModelAndTheTrueOffset) {
  RopeKnot env{RopeKnotEnvironmentParams{}};
  env.reset({});
  const Observation seen = env.observe(true);
  ASSERT_TRUE(seen.camera.has_value());
  EXPECT_EQ(seen.rgb.cols, env.params().camera.width);
  EXPECT_EQ(seen.depth.rows, env.params().camera.height);
  EXPECT_EQ(seen.camera->intrinsics.width, env.params().camera.width);
  const Eigen::Vector3d end(seen.value("rope_end_x"), seen.value("rope_end_y"),
                            seen.value("rope_end_z"));
  const Eigen::Vector3d gripper(seen.value("gripper_mid_x"), seen.value("gripper_mid_y"),
                                seen.value("gripper_mid_z"));
  const Eigen::Vector3d offset(seen.value("rope_end_dx"), seen.value("rope_end_dy"),
                               seen.value("rope_end_dz"));
  EXPECT_LT((end - gripper - offset).norm(), 1e-12);
  std::vector<std::string> keys;
  for (const auto& [key, value] : seen.state) keys.push_back(key);
  std::vector<std::string> declared = env.state_names();
  std::sort(declared.begin(), declared.end());
  EXPECT_EQ(keys, declared);
  EXPECT_FALSE(env.observe(false).camera.has_value());
}

TEST(RopeKnot, ATrialIsDeterministic) {
  const Scenario scenario{{"grasp_offset", -0.01}, {"span_offset", 0.02}, {"drift_x", 0.01}};
  std::vector<Eigen::MatrixXd> runs;
  std::vector<std::string> failures;
  for (int i = 0; i < 2; ++i) {
    RopeKnot env{RopeKnotEnvironmentParams{}};
    env.reset(scenario);
    failures.push_back(env.execute("pre", pre_waypoints(env.params().task)));
    Eigen::MatrixXd nodes(static_cast<Eigen::Index>(env.scene().rope_nodes().size()), 3);
    for (size_t k = 0; k < env.scene().rope_nodes().size(); ++k) {
      nodes.row(static_cast<Eigen::Index>(k)) = env.scene().rope_nodes()[k].transpose();
    }
    runs.push_back(nodes);
  }
  EXPECT_EQ(failures[0], failures[1]);
  EXPECT_EQ(runs[0], runs[1]);  // bit for bit
}

// Parallel collection: the same split, images included, for any
// thread budget; each thread demonstrates in its own clone.
TEST(RopeExpert, CollectsTheSameDemonstrationsWhateverTheThreadBudget) {
  RopeExpertParams params;
  params.train = 3;
  params.validation = 1;
  params.images = true;
  std::vector<DemonstrationSplit> splits;
  const int saved = thread_budget();
  for (int budget : {1, 2}) {
    set_thread_budget(budget);
    RopeKnot env{RopeKnotEnvironmentParams{}};
    Rng rng(4);
    splits.push_back(RopeExpert{params}.collect(&env, rng));
  }
  set_thread_budget(saved);
  ASSERT_EQ(splits[0].train.size(), 3u);
  ASSERT_EQ(splits[1].train.size(), 3u);
  ASSERT_EQ(splits[1].validation.size(), 1u);
  std::vector<Demonstration> one = splits[0].train, two = splits[1].train;
  one.push_back(splits[0].validation.at(0));
  two.push_back(splits[1].validation.at(0));
  for (size_t d = 0; d < one.size(); ++d) {
    EXPECT_EQ(one[d].scenario, two[d].scenario);
    EXPECT_EQ(one[d].decision, two[d].decision);
    for (size_t s = 0; s < one[d].segments.size(); ++s) {
      EXPECT_EQ(one[d].segments[s].y, two[d].segments[s].y);
      EXPECT_EQ(one[d].segments[s].start.state, two[d].segments[s].start.state);
      const cv::Mat& a = one[d].segments[s].start.rgb;
      const cv::Mat& b = two[d].segments[s].start.rgb;
      ASSERT_EQ(a.empty(), b.empty());
      if (!a.empty()) {
        EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
      }
    }
  }
  std::set<std::string> scenarios;
  for (const Demonstration& demo : one) scenarios.insert(demo.scenario);
  EXPECT_GT(scenarios.size(), 1u);
}

TEST(RopeKnot, ABrokenTrajectoryIsAFailedTrialNotACrash) {
  RopeKnot env{RopeKnotEnvironmentParams{}};
  env.reset({});
  Eigen::MatrixXd bad = Eigen::MatrixXd::Zero(3, 8);
  bad(1, 2) = std::numeric_limits<double>::quiet_NaN();
  const std::string failure = env.execute("pre", bad);
  EXPECT_EQ(failure.rfind("invalid trajectory", 0), 0u) << failure;
  EXPECT_FALSE(env.outcome().success);
  EXPECT_EQ(env.outcome().failure, failure);
  EXPECT_EQ(env.execute("post", Eigen::MatrixXd::Zero(2, 8)), failure);  // stays failed
  EXPECT_EQ(env.executed_path().rows(), 0);
}

}  // namespace
}  // namespace corrmp
