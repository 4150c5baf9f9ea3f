// Tests of the rope-knotting task on the dual-arm torso
// (configs/common/rope_arms.yaml): the arms carry the grippers along the
// nominal pre-MP where the floating grippers go, with the grippers'
// orientations, their executed path the tools' within millimetres of the command; a bar out of
// reach and a base moved away fail "out of reach"; the start of a trial replays bit for bit; the
// arms are drawn for the head camera in colours the rope-end segmentation does not take; the base
// offset is drawn after the other scenario keys; trials keep the robot's figures for the run's
// metrics.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "core/config/config_loader.hpp"
#include "core/config/config_reader.hpp"
#include "core/parameter_error.hpp"
#include "envs/rope_knot/rope_knot.hpp"
#include "envs/rope_knot/rope_knot_script.hpp"

namespace corrmp {
namespace {

// The rope task's parameters with the robot of configs/common/rope_arms.yaml.
RopeKnotParams on_arms() {
  ConfigNode root = load_config(std::string(PROJECT_DIR) + "/configs/common/rope_arms.yaml", {});
  RopeKnotParams params;
  ConfigReader::read(*root.find("environment"), "environment", params);
  return params;
}

// The largest gap between the floating and the arms' grippers over the rows, each
// executed alone; `command_gap` is the arms' largest gap between their executed path and
// the rows.
double largest_gap(RopeKnotScene& floating, RopeKnotScene& arms, const Eigen::MatrixXd& rows,
                   double& command_gap) {
  double gap = 0.0;
  command_gap = 0.0;
  for (Eigen::Index k = 0; k < rows.rows(); ++k) {
    EXPECT_EQ(floating.execute(rows.middleRows(k, 1)), "");
    EXPECT_EQ(arms.execute(rows.middleRows(k, 1)), "") << "row " << k;
    gap = std::max({gap, (floating.left_position() - arms.left_position()).norm(),
                    (floating.right_position() - arms.right_position()).norm()});
    // The executed row is where the tools were.
    EXPECT_EQ(arms.executed().rows(), 1);
    if (arms.executed().rows() != 1) continue;
    const Eigen::RowVectorXd executed = arms.executed().row(0);
    EXPECT_EQ(Eigen::Vector3d(executed.segment<3>(0)), arms.left_position());
    EXPECT_EQ(Eigen::Vector3d(executed.segment<3>(4)), arms.right_position());
    command_gap = std::max({command_gap, (executed - rows.row(k)).segment<3>(0).norm(),
                            (executed - rows.row(k)).segment<3>(4).norm()});
  }
  return gap;
}

TEST(RopeKnotOnArms, TheNominalPreMpPutsTheGrippersWhereFloatingOnesGo) {
  RopeKnotScene floating(RopeKnotParams{});
  RopeKnotScene arms(on_arms());
  ASSERT_NE(arms.arms(), nullptr);
  EXPECT_LT((floating.left_position() - arms.left_position()).norm(), 0.002);
  EXPECT_LT((floating.right_position() - arms.right_position()).norm(), 0.002);
  double command_gap = 0.0;
  const double gap = largest_gap(floating, arms, pre_waypoints(arms.params()), command_gap);
  EXPECT_LT(gap, 0.005);
  // The executed path lags the command by the arms' tracking error, not more.
  EXPECT_GT(command_gap, 0.0);
  EXPECT_LT(command_gap, 0.005);
  // The joints track within a few milliradians with the config's solver iterations.
  EXPECT_EQ(arms.params().robot.dual_arm.control.solver_iterations, 20);
  EXPECT_LT(arms.arms()->max_tracking_error(), 0.003);
  // The rows' commands are the floating ones'; the tools hold the grippers' orientations.
  EXPECT_LT((floating.left_command() - arms.left_command()).norm(), 1e-12);
  const Eigen::Matrix3d down = arms.arms()->tool_pose(Arm::right).linear();
  EXPECT_LT((down.col(2) - Eigen::Vector3d(0, 0, -1)).norm(), 0.02);
  const Eigen::Matrix3d side = arms.arms()->tool_pose(Arm::left).linear();
  EXPECT_LT((side.col(2) - Eigen::Vector3d(0, 1, 0)).norm(), 0.02);
  EXPECT_LT((side.col(0) - Eigen::Vector3d(1, 0, 0)).norm(), 0.02);
}

TEST(RopeKnotOnArms, ABarOutOfReachFailsOutOfReach) {
  RopeKnotParams params = on_arms();
  params.bar_centre = {1.3, 0.0, 0.35};
  RopeKnotScene scene(params);
  EXPECT_EQ(scene.arm_failure().rfind("out of reach: ", 0), 0u) << scene.arm_failure();
  EXPECT_EQ(scene.execute(pre_waypoints(params)), scene.arm_failure());
  EXPECT_EQ(scene.outcome().failure, "out of reach");
  EXPECT_FALSE(scene.outcome().knot);
}

TEST(RopeKnotOnArms, AnArmFailureIsTheTrialsFailureCategory) {
  RopeKnotEnvironmentParams params;
  params.task = on_arms();
  RopeKnot env(params);
  const auto& categories = env.report().failure_categories;
  EXPECT_NE(std::find(categories.begin(), categories.end(), "out of reach"), categories.end());
  const auto& floating = RopeKnot(RopeKnotEnvironmentParams{}).report().failure_categories;
  EXPECT_EQ(std::find(floating.begin(), floating.end(), "out of reach"), floating.end());
  // The base 40 cm further back: the grippers' start is beyond the arms.
  env.reset({{"base_dx", -0.4}});
  const std::string failure = env.execute("pre", pre_waypoints(params.task));
  EXPECT_EQ(failure.rfind("out of reach: ", 0), 0u) << failure;
  EXPECT_EQ(env.outcome().failure, failure);
  EXPECT_FALSE(env.outcome().success);
}

// A trial's row keeps the robot's figures, and the run's metrics and IK time come from them
// (sim/robot/robot_run_metrics.hpp); floating grippers add none.
TEST(RopeKnotOnArms, TrialsKeepTheRobotsFiguresAndTheRunReportsThem) {
  RopeKnotEnvironmentParams params;
  params.task = on_arms();
  RopeKnot env(params);
  const std::unique_ptr<Environment> clone = env.clone();
  clone->reset({});
  ASSERT_EQ(clone->execute("pre", pre_waypoints(params.task).topRows(10)), "");
  EvaluatedTrial trial;
  trial.details = clone->outcome().details;
  EXPECT_GT(trial.details.at("ik_solves"), 0.0);
  EXPECT_EQ(trial.details.at("ik_failures"), 0.0);
  EXPECT_GT(trial.details.at("max_tracking_error"), 0.0);
  // The clone's solves are timed with the environment it was cloned from.
  const Environment::RunAdditions added = env.run_additions({trial}, "r");
  std::map<std::string, double> metrics;
  for (const Metric& m : added.metrics) metrics[m.name] = m.value;
  EXPECT_EQ(metrics.at("ik_success_rate"), 1.0);
  EXPECT_EQ(metrics.at("ik_solves"), trial.details.at("ik_solves"));
  EXPECT_EQ(added.log.rfind("IK time (r): ", 0), 0u) << added.log;
  const RopeKnot floating(RopeKnotEnvironmentParams{});
  EXPECT_EQ(floating.outcome().details.count("ik_solves"), 0u);
  EXPECT_TRUE(floating.run_additions({trial}, "r").metrics.empty());
}

TEST(RopeKnotOnArms, TheStartOfATrialReplaysBitwise) {
  const Scenario scenario{{"grasp_offset", 0.01}, {"drift_y", -0.01}, {"base_dy", 0.02}};
  const Eigen::MatrixXd rows = pre_waypoints(on_arms()).topRows(10);
  std::vector<std::vector<Eigen::Vector3d>> nodes;
  std::vector<Eigen::Vector3d> tools;
  for (int i = 0; i < 2; ++i) {
    RopeKnotScene scene(on_arms());
    scene.reset(scenario);
    EXPECT_EQ(scene.execute(rows), "");
    nodes.push_back(scene.rope_nodes());
    tools.push_back(scene.left_position());
    tools.push_back(scene.right_position());
  }
  EXPECT_EQ(nodes[0], nodes[1]);  // bit for bit
  EXPECT_EQ(tools[0], tools[2]);
  EXPECT_EQ(tools[1], tools[3]);
}

// The head camera sees the arms, in colours of saturation below the rope-end
// segmentation's smallest (0.5): they never pass for the red end.
TEST(RopeKnotOnArms, TheArmsAreDrawnInColoursTheSegmentationLeaves) {
  const RopeKnotScene floating(RopeKnotParams{});
  const RopeKnotScene arms(on_arms());
  const RenderScene with = arms.render_scene(), without = floating.render_scene();
  ASSERT_GE(with.items.size(), without.items.size() + 20);  // 22 shapes less torso and head
  for (size_t i = without.items.size(); i < with.items.size(); ++i) {
    const Eigen::Vector3f c = with.items[i].colour;
    EXPECT_LT((c.maxCoeff() - c.minCoeff()) / c.maxCoeff(), 0.5f) << i;
  }
}

// The base offset is drawn after the floating task's keys, which stay as they were.
TEST(RopeKnotOnArms, TheBaseOffsetIsDrawnAfterTheOtherKeys) {
  RopeKnotParams params = on_arms();
  params.base_offset_range = {0.1, 0.05, 0.0};
  RopeKnotScene scene(params);
  Rng a(3), b(3);
  Scenario with = scene.sample(a);
  const Scenario without = RopeKnotScene(RopeKnotParams{}).sample(b);
  EXPECT_LE(std::abs(with.at("base_dx")), 0.1);
  EXPECT_LE(std::abs(with.at("base_dy")), 0.05);
  EXPECT_EQ(with.at("base_dz"), 0.0);
  for (const char* key : {"base_dx", "base_dy", "base_dz"}) with.erase(key);
  EXPECT_EQ(with, without);
  EXPECT_EQ(without.count("base_dx"), 0u);
  // Floating grippers have no base to move.
  RopeKnotParams floating;
  floating.base_offset_range = {0.1, 0.0, 0.0};
  EXPECT_THROW(RopeKnotScene{floating}, std::invalid_argument);
}

TEST(RopeKnotOnArms, AnUnusableRobotIsRefusedNamingTheKey) {
  RopeKnotParams params = on_arms();
  params.robot.dual_arm.urdf = "assets/robots/none.urdf";
  const auto build = [&] { RopeKnotScene scene{params}; };
  EXPECT_THAT(
      build, ::testing::Throws<ParameterError>(::testing::Property(&ParameterError::key, "robot")));
  EXPECT_THAT(build, ::testing::ThrowsMessage<ParameterError>(
                         ::testing::HasSubstr("assets/robots/none.urdf")));
}

TEST(RopeKnotOnArms, AStartOutOfReachKeepsTheStartAsTheCommand) {
  RopeKnotParams params = on_arms();
  params.bar_centre = {1.3, 0.0, 0.35};
  RopeKnotScene scene(params);
  const Eigen::Vector3d bar(1.3, 0.0, 0.35);
  const Eigen::Vector3d start(params.left_start_offset[0], params.left_start_offset[1],
                              params.left_start_offset[2]);
  EXPECT_LT((scene.left_command() - (bar + start)).norm(), 1e-9);
}

}  // namespace
}  // namespace corrmp
