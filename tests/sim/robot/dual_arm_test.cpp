#include "sim/robot/dual_arm.hpp"

#include <gtest/gtest.h>

#include "config/test_files.hpp"

namespace corrmp {
namespace {

constexpr double kTick = 1.0 / 240.0;

// The tool pointing down (tool z = world -z), fingers closing along world x.
Eigen::Matrix3d pointing_down() { return Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal(); }

// The right arm's tool moved from its home position to `to` at `speed`, the
// left arm holding its home position; the executed right tool position after
// every tick, or the first failure.
struct Motion {
  std::vector<Eigen::Vector3d> executed, commanded;
  std::string failure;
};

Motion move_right(DualArm& arm, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                  double speed = 0.05) {
  Motion run;
  const Eigen::Vector3d left = arm.tool_position(Arm::left);
  const int ticks = static_cast<int>(std::ceil((to - from).norm() / (speed * kTick)));
  for (int k = 1; k <= ticks; ++k) {
    const Eigen::Vector3d target = from + (to - from) * (double(k) / ticks);
    run.failure = arm.track(left, target);
    if (!run.failure.empty()) break;
    run.commanded.push_back(target);
    run.executed.push_back(arm.tool_position(Arm::right));
  }
  return run;
}

TEST(DualArm, ResetPutsTheToolsAtTheHomePoses) {
  DualArmParams params;
  params.base_position = {0.1, -0.2, 0.05};
  DualArm arm(params, kTick);
  const RobotModel model = load_robot_model(std::string(PROJECT_DIR) + "/" + params.urdf);
  const Eigen::Translation3d base(0.1, -0.2, 0.05);
  const std::pair<Arm, const std::vector<double>*> homes[2] = {{Arm::left, &params.left_home},
                                                               {Arm::right, &params.right_home}};
  for (const auto& [side, home] : homes) {
    const ArmKinematics kinematics(model, "base", side == Arm::left ? "left_tool" : "right_tool");
    const Eigen::Isometry3d expected =
        base * kinematics.forward(Eigen::Map<const Eigen::VectorXd>(home->data(), 7));
    const Eigen::Isometry3d actual = arm.tool_pose(side);
    EXPECT_LT((actual.translation() - expected.translation()).norm(), 1e-5);
    EXPECT_LT(Eigen::AngleAxisd(actual.linear().transpose() * expected.linear()).angle(), 1e-5);
  }
  EXPECT_EQ(arm.max_tracking_error(), 0.0);
  EXPECT_FALSE(arm.shapes().empty());
}

TEST(DualArm, FollowsAStraightLineWithTheToolDown) {
  DualArm arm(DualArmParams{}, kTick);
  arm.set_tool_orientation(Arm::right, pointing_down());
  const Eigen::Vector3d start(0.45, -0.2, 0.07), end(0.45, -0.12, 0.03);
  // Slowly to the start with the new orientation, then along the line.
  ASSERT_EQ(move_right(arm, arm.tool_position(Arm::right), start, 0.02).failure, "");
  for (int settle = 0; settle < 60; ++settle)
    ASSERT_EQ(arm.track(arm.tool_position(Arm::left), start), "");
  const Motion run = move_right(arm, start, end);
  ASSERT_EQ(run.failure, "") << arm.failure_detail();
  double worst = 0.0;
  for (size_t k = 0; k < run.executed.size(); ++k)
    worst = std::max(worst, (run.executed[k] - run.commanded[k]).norm());
  EXPECT_LT(worst, 0.003);
  EXPECT_LT((run.executed.back() - end).norm(), 0.003);
  const Eigen::Matrix3d executed = arm.tool_pose(Arm::right).linear();
  EXPECT_LT(Eigen::AngleAxisd(executed.transpose() * pointing_down()).angle(), 0.02);
  EXPECT_GT(arm.ik_stats().solves + arm.ik_stats().reused,
            2 * static_cast<long>(run.executed.size()));
  EXPECT_EQ(arm.ik_stats().failures, 0);
  EXPECT_GT(arm.max_tracking_error(), 0.0);
  EXPECT_LT(arm.max_tracking_error(), DualArmParams{}.control.tracking_error_bound);
}

TEST(DualArm, FarTargetIsOutOfReach) {
  DualArm arm(DualArmParams{}, kTick);
  EXPECT_EQ(arm.track(arm.tool_position(Arm::left), {2.0, -0.2, 0.3}), "out of reach");
  EXPECT_NE(arm.failure_detail().find("right arm"), std::string::npos) << arm.failure_detail();
  EXPECT_EQ(arm.ik_stats().failures, 1);
}

TEST(DualArm, SameSequenceInFreshArmsIsBitIdentical) {
  auto run = [] {
    DualArm arm(DualArmParams{}, kTick);
    arm.set_tool_orientation(Arm::right, pointing_down());
    const Motion moved =
        move_right(arm, arm.tool_position(Arm::right), Eigen::Vector3d(0.45, -0.2, 0.07), 0.05);
    std::vector<double> values;
    for (const auto& p : moved.executed) values.insert(values.end(), p.data(), p.data() + 3);
    for (const PlacedShape& s : arm.shapes()) {
      const Eigen::Matrix4d m = s.shape.origin.matrix();
      values.insert(values.end(), m.data(), m.data() + 16);
    }
    values.push_back(arm.max_tracking_error());
    return std::make_pair(moved.failure, values);
  };
  const auto first = run();
  const auto second = run();
  EXPECT_EQ(first.first, "");
  EXPECT_EQ(first.second, second.second);
}

// A tool target that has not moved since the arm's last solve keeps that
// solution as its joint targets, without solving again.
TEST(DualArm, ATargetThatHasNotMovedKeepsItsJointTargets) {
  DualArm arm(DualArmParams{}, kTick);
  arm.set_tool_orientation(Arm::right, pointing_down());
  const Eigen::Vector3d end(0.45, -0.2, 0.07);
  const Motion moved = move_right(arm, arm.tool_position(Arm::right), end);
  ASSERT_EQ(moved.failure, "") << arm.failure_detail();
  const long ticks = static_cast<long>(moved.executed.size());
  EXPECT_EQ(arm.ik_stats().reused, ticks - 1);  // the left target, after its first tick
  EXPECT_EQ(arm.ik_stats().solves, 2 * ticks - arm.ik_stats().reused);
  // Both held: the left arm, braked at home since its first tick, is exactly
  // where its target was, and the right kept its last solve.
  const Eigen::Vector3d left = arm.tool_position(Arm::left), right = moved.commanded.back();
  for (int tick = 0; tick < 60; ++tick) ASSERT_EQ(arm.track(left, right), "");
  EXPECT_EQ(arm.ik_stats().reused, ticks - 1 + 60 + 60);
  EXPECT_EQ(arm.ik_stats().solves, ticks + 1);
  EXPECT_LT((arm.tool_position(Arm::right) - end).norm(), 1e-3);
  // A placement solves the placed arm's next target again.
  ASSERT_EQ(arm.place_tool(Arm::right, right), "");
  ASSERT_EQ(arm.track(left, right), "");
  EXPECT_EQ(arm.ik_stats().reused, ticks - 1 + 60 + 60 + 1);
}

TEST(DualArm, PlaceToolPutsTheToolThereAtRestOrLeavesTheArm) {
  DualArm arm(DualArmParams{}, kTick);
  arm.set_tool_orientation(Arm::right, pointing_down());
  const Eigen::Vector3d start(0.45, -0.285, 0.07);
  ASSERT_EQ(arm.place_tool(Arm::right, start), "") << arm.failure_detail();
  EXPECT_LT((arm.tool_position(Arm::right) - start).norm(), IkParams{}.position_tolerance);
  const Eigen::Vector3d placed = arm.tool_position(Arm::right);
  EXPECT_EQ(arm.place_tool(Arm::right, {2.0, -0.2, 0.3}), "out of reach");
  EXPECT_EQ(arm.tool_position(Arm::right), placed);
  // At rest there: holding the target keeps the tool within a tenth of a millimetre.
  for (int tick = 0; tick < 60; ++tick)
    ASSERT_EQ(arm.track(arm.tool_position(Arm::left), start), "");
  EXPECT_LT((arm.tool_position(Arm::right) - placed).norm(), 1e-4);
}

TEST(DualArm, NamesEachArmsLinksAndItsHand) {
  DualArm arm(DualArmParams{}, kTick);
  EXPECT_EQ(arm.hand_links(Arm::right), (std::vector<std::string>{"right_gripper", "right_finger_1",
                                                                  "right_finger_2", "right_tool"}));
  const std::vector<std::string>& links = arm.arm_links(Arm::left);
  ASSERT_EQ(links.size(), 11u);
  EXPECT_EQ(links.front(), "left_link_1");
  EXPECT_EQ(links.back(), "left_tool");
}

TEST(DualArm, UnusableConfigurationIsAConfigErrorNamingIt) {
  DualArmParams missing;
  missing.urdf = "assets/robots/no_such_robot.urdf";
  EXPECT_NE(testing::config_error_of([&] {
              DualArm(missing, kTick);
            }).find("assets/robots/no_such_robot.urdf"),
            std::string::npos);
  DualArmParams short_home;
  short_home.left_home = {0.0, 1.0, 0.0, 1.5, 0.0, -1.0};
  const std::string error = testing::config_error_of([&] { DualArm(short_home, kTick); });
  EXPECT_NE(error.find("left_home has 6 values"), std::string::npos) << error;
  DualArmParams own_tick;
  own_tick.control.time_step = kTick / 2;
  const std::string tick = testing::config_error_of([&] { DualArm(own_tick, kTick); });
  EXPECT_NE(tick.find("control.time_step"), std::string::npos) << tick;
  own_tick.control.time_step = kTick;
  EXPECT_NO_THROW(DualArm(own_tick, kTick));
}

}  // namespace
}  // namespace corrmp
