// The corridor task executed by the dual-arm torso's right arm.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

#include "core/parameter_error.hpp"
#include "core/task_declaration.hpp"
#include "envs/corridor_push/corridor_expert.hpp"
#include "envs/corridor_push/corridor_push.hpp"
#include "envs/corridor_push/path_sampling.hpp"

namespace corrmp {
namespace {

// As configs/common/corridor_arms.yaml.
CorridorPushParams on_arms() {
  CorridorPushParams params;
  params.robot.type = "dual_arm";
  params.robot.dual_arm.left_home = {-0.16, 1.15, 1.2, 1.3, -1.68, -1.14, -1.19};
  return params;
}

const Scenario kPush{{"corridor_offset", 0.021}, {"object_dx", 0.0}, {"object_dy", 0.0}};

TEST(CorridorOnArms, TheExpertSucceedsThroughTheArmWhichLagsTheCommandByMillimetres) {
  CorridorPush env{on_arms()};
  ASSERT_NE(env.robot(), nullptr);
  EXPECT_EQ(env.report().failure_categories,
            (std::vector<std::string>{"out of reach", "joint limit", "self collision",
                                      "tracking error", "physics fault", "physics blow-up",
                                      "the object touched the corridor", "the object stopped"}));
  const Demonstration demo = CorridorExpert{CorridorExpertParams{}}.demonstrate(env, kPush, false);
  const Outcome outcome = env.outcome();
  EXPECT_TRUE(outcome.success) << outcome.failure;
  EXPECT_EQ(demo.decision, "push");
  // The arm ends where the last waypoint commanded it, within the IK tolerance
  // and the controller's lag, but not exactly there as a floating gripper does.
  const Eigen::RowVectorXd commanded = demo.find("post")->y.bottomRows(1);
  const double gap = (env.effector_position() - commanded).norm();
  EXPECT_GT(gap, 0.0);
  EXPECT_LT(gap, 0.003);
  EXPECT_GT(env.robot()->ik_stats().solves, 1000);
  EXPECT_EQ(env.robot()->ik_stats().failures, 0);
  EXPECT_EQ(outcome.details.at("ik_solves"), env.robot()->ik_stats().solves);
  EXPECT_GT(outcome.details.at("max_tracking_error"), 0.0);
  EXPECT_TRUE(CorridorPush{CorridorPushParams{}}.outcome().details.empty());
}

TEST(CorridorOnArms, AnObjectLeftWhereItWasFailsInTheTasksOwnCategory) {
  CorridorPush env{on_arms()};
  env.reset(kPush);
  const Eigen::MatrixXd still = env.effector_position().replicate(2, 1);
  ASSERT_EQ(env.execute("pre", still), "");
  const Outcome outcome = env.outcome();
  ASSERT_FALSE(outcome.success);
  const std::vector<std::string>& categories = env.report().failure_categories;
  EXPECT_EQ(
      std::count_if(categories.begin(), categories.end(),
                    [&](const std::string& c) { return in_failure_category(outcome.failure, c); }),
      1)
      << outcome.failure;
  EXPECT_TRUE(in_failure_category(outcome.failure, "the object stopped")) << outcome.failure;
}

TEST(CorridorOnArms, ATrialReplaysBitIdentically) {
  CorridorPush env{on_arms()};
  const Eigen::MatrixXd path = sample_path(
      {{0.45, -0.285, 0.07}, {0.45, -0.285, 0.03}, {0.45, -0.15, 0.03}}, 30, {1.0, 1.0});
  auto play = [&](CorridorPush& e) {
    e.reset(kPush);
    EXPECT_EQ(e.execute("pre", path), "");
    return std::make_pair(e.effector_position(), e.object_position());
  };
  const auto first = play(env);
  const auto again = play(env);
  CorridorPush fresh{on_arms()};
  const auto other = play(fresh);
  EXPECT_EQ(first.first, again.first);
  EXPECT_EQ(first.second, again.second);
  EXPECT_EQ(first.first, other.first);
  EXPECT_EQ(first.second, other.second);
  EXPECT_GT(first.second.y(), -0.2 + 0.01);  // the arm pushed the object
}

TEST(CorridorOnArms, TheExecutedPathIsTheToolsWhichLagsTheCommandByMillimetres) {
  CorridorPush env{on_arms()};
  env.reset(kPush);
  const Eigen::MatrixXd path = sample_path(
      {{0.45, -0.285, 0.07}, {0.45, -0.285, 0.03}, {0.45, -0.15, 0.03}}, 30, {1.0, 1.0});
  ASSERT_EQ(env.execute("pre", path), "");
  const Eigen::MatrixXd executed = env.executed_path();
  ASSERT_EQ(executed.rows(), path.rows());
  const Eigen::VectorXd gaps = (executed - path).rowwise().norm();
  // Within the IK tolerance and the controller's lag (as at the expert's end
  // above), but not exactly on the command as a floating gripper is.
  EXPECT_LT(gaps.maxCoeff(), 0.003);
  EXPECT_GT(gaps.maxCoeff(), 0.0);
  EXPECT_EQ(Eigen::RowVectorXd(executed.bottomRows(1)), env.effector_position());
}

TEST(CorridorOnArms, ACorridorOutOfTheArmsReachFailsAsOutOfReach) {
  CorridorPushParams params = on_arms();
  params.robot.dual_arm.base_position = {-1.5, 0.0, 0.0};
  CorridorPush env{params};
  env.reset(kPush);
  const Eigen::MatrixXd path = sample_path({{0.45, -0.285, 0.07}, {0.45, -0.2, 0.07}}, 10, {1.0});
  EXPECT_EQ(env.execute("pre", path), "out of reach");
  EXPECT_EQ(env.executed_path().rows(), 0);  // no row reached
  EXPECT_EQ(env.outcome().failure, "out of reach");
  EXPECT_FALSE(env.outcome().success);
}

TEST(CorridorOnArms, TheHeadCameraSeesTheArm) {
  CorridorPush floating{CorridorPushParams{}};
  CorridorPush arms{on_arms()};
  // The gripper in front of the object, in view (at the start the arm is not).
  const Eigen::MatrixXd path = sample_path({{0.45, -0.285, 0.07}, {0.40, -0.10, 0.07}}, 10, {1.0});
  ASSERT_EQ(floating.execute("pre", path), "");
  ASSERT_EQ(arms.execute("pre", path), "");
  const cv::Mat without = floating.observe(true).rgb, with = arms.observe(true).rgb;
  ASSERT_EQ(without.size(), with.size());
  cv::Mat differs;
  cv::compare(without.reshape(1), with.reshape(1), differs, cv::CMP_NE);
  EXPECT_GT(cv::countNonZero(differs), 0.02 * differs.total());
}

TEST(CorridorOnArms, AnUnusableRobotIsRefusedNamingTheKey) {
  CorridorPushParams params;
  params.robot.dual_arm.urdf = "assets/robots/none.urdf";
  params.robot.type = "dual_arm";
  const auto build = [&] { CorridorPush env{params}; };
  EXPECT_THAT(
      build, ::testing::Throws<ParameterError>(::testing::Property(&ParameterError::key, "robot")));
  EXPECT_THAT(build, ::testing::ThrowsMessage<ParameterError>(
                         ::testing::HasSubstr("assets/robots/none.urdf")));
}

// The base offset is drawn after the floating task's keys, which stay as they were, and only
// when its range is set: a zero range leaves the scenarios unchanged.
TEST(CorridorOnArms, TheBaseOffsetIsDrawnLastAndOnlyWhenSet) {
  CorridorPushParams offset = on_arms();
  offset.base_offset_range = {0.1, 0.05, 0.0};
  offset.object_noise = 0.01;
  CorridorPushParams still = on_arms();
  still.object_noise = 0.01;
  CorridorPushParams floating;
  floating.object_noise = 0.01;
  Rng a(3), b(3), c(3);
  Scenario with = CorridorPush{offset}.sample_scenario(a);
  const Scenario without = CorridorPush{still}.sample_scenario(b);
  EXPECT_EQ(without, CorridorPush{floating}.sample_scenario(c));
  EXPECT_EQ(without.count("base_dx"), 0u);
  EXPECT_LE(std::abs(with.at("base_dx")), 0.1);
  EXPECT_LE(std::abs(with.at("base_dy")), 0.05);
  EXPECT_NE(with.at("base_dx"), 0.0);
  EXPECT_EQ(with.at("base_dz"), 0.0);
  for (const char* key : {"base_dx", "base_dy", "base_dz"}) with.erase(key);
  EXPECT_EQ(with, without);
}

// The offset moves the robot's base: the corridor and the object stay where they are in the
// world, so they move relative to the robot.
TEST(CorridorOnArms, TheBaseOffsetMovesTheCorridorRelativeToTheRobot) {
  CorridorPush env{on_arms()};
  const auto base_of = [&] {  // the torso, fixed on the base link
    for (const PlacedShape& shape : env.robot()->shapes())
      if (shape.link == "torso") return Eigen::Vector3d(shape.shape.origin.translation());
    ADD_FAILURE() << "no shape of the torso";
    return Eigen::Vector3d(Eigen::Vector3d::Zero());
  };
  env.reset(kPush);
  const Eigen::Vector3d base = base_of(), object = env.object_position();
  const double corridor = env.corridor_x();
  Scenario moved = kPush;
  moved["base_dx"] = -0.05;
  moved["base_dy"] = 0.03;
  env.reset(moved);
  EXPECT_LT((base_of() - base - Eigen::Vector3d(-0.05, 0.03, 0.0)).norm(), 1e-6);
  EXPECT_EQ(env.corridor_x(), corridor);
  EXPECT_LT((env.object_position() - object).norm(), 1e-6);
  const Eigen::MatrixXd path = sample_path({{0.45, -0.285, 0.07}, {0.45, -0.25, 0.07}}, 10, {1.0});
  EXPECT_EQ(env.execute("pre", path), "");  // still within reach
  // Far enough back, the start is out of the arm's reach: the trial fails at reset.
  moved["base_dx"] = -1.5;
  env.reset(moved);
  EXPECT_EQ(env.execute("pre", path), "out of reach");
}

TEST(CorridorOnArms, FloatingGrippersRefuseABaseOffset) {
  CorridorPushParams floating;
  floating.base_offset_range = {0.1, 0.0, 0.0};
  const auto build = [&] { CorridorPush env{floating}; };
  EXPECT_THAT(build, ::testing::Throws<ParameterError>(
                         ::testing::Property(&ParameterError::key, "base_offset_range")));
}

}  // namespace
}  // namespace corrmp
