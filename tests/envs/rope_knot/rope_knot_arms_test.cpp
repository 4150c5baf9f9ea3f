// Tests of the rope-knotting task on the dual-arm torso
// (configs/common/rope_arms.yaml): the arms carry the grippers along the
// nominal pre-MP where the floating grippers go, with the grippers'
// orientations; a bar out of reach and a base moved away fail "out of reach";
// the start of a trial replays bit for bit; the arms are drawn for the head camera in
// colours the rope-end segmentation does not take; the base offset is drawn
// after the other scenario keys.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

double largest_gap(RopeKnotScene& floating, RopeKnotScene& arms, const Eigen::MatrixXd& rows) {
  double gap = 0.0;
  for (Eigen::Index k = 0; k < rows.rows(); ++k) {
    EXPECT_EQ(floating.execute(rows.middleRows(k, 1)), "");
    EXPECT_EQ(arms.execute(rows.middleRows(k, 1)), "") << "row " << k;
    gap = std::max({gap, (floating.left_position() - arms.left_position()).norm(),
                    (floating.right_position() - arms.right_position()).norm()});
  }
  return gap;
}

TEST(RopeKnotOnArms, TheNominalPreMpPutsTheGrippersWhereFloatingOnesGo) {
  RopeKnotScene floating(RopeKnotParams{});
  RopeKnotScene arms(on_arms());
  ASSERT_NE(arms.arms(), nullptr);
  EXPECT_LT((floating.left_position() - arms.left_position()).norm(), 0.002);
  EXPECT_LT((floating.right_position() - arms.right_position()).norm(), 0.002);
  const double gap = largest_gap(floating, arms, pre_waypoints(arms.params()));
  EXPECT_LT(gap, 0.005);
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
  try {
    RopeKnotScene scene{params};
    FAIL() << "no error";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.key(), "robot");
    EXPECT_NE(std::string(e.what()).find("assets/robots/none.urdf"), std::string::npos);
  }
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
