#include "sim/robot/arm_kinematics.hpp"

#include <gtest/gtest.h>

#include "config/test_files.hpp"
#include "core/seeds.hpp"
#include "sim/robot/shipped_robot.hpp"

namespace corrmp {
namespace {

using testing::kShippedRobot;

// The tool pointing down (tool z = world -z), fingers closing along world x.
Eigen::Isometry3d pointing_down(const Eigen::Vector3d& position) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
  pose.translation() = position;
  return pose;
}

double angle_between(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle();
}

void expect_within_limits(const ArmKinematics& arm, const Eigen::VectorXd& q) {
  for (int j = 0; j < arm.joints(); ++j) {
    EXPECT_GE(q(j), arm.lower()(j)) << arm.joint_names()[j];
    EXPECT_LE(q(j), arm.upper()(j)) << arm.joint_names()[j];
  }
}

Eigen::VectorXd random_within_limits(const ArmKinematics& arm, Rng& rng) {
  Eigen::VectorXd q(arm.joints());
  for (int j = 0; j < arm.joints(); ++j) q(j) = rng.uniform(arm.lower()(j), arm.upper()(j));
  return q;
}

TEST(ArmKinematics, ReachesPosesOfRandomConfigurationsFromOtherWarmStarts) {
  const RobotModel model = load_robot_model(kShippedRobot);
  const IkParams params;
  for (const std::string side : {"left", "right"}) {
    ArmKinematics arm(model, "base", side + "_tool", params);
    ASSERT_EQ(arm.joints(), 7);
    Rng rng(11);
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::Isometry3d target = arm.forward(random_within_limits(arm, rng));
      const IkResult result = arm.solve(target, random_within_limits(arm, rng));
      ASSERT_EQ(result.status, IkResult::Status::ok) << side << " trial " << trial;
      const Eigen::Isometry3d reached = arm.forward(result.q);
      EXPECT_LE((reached.translation() - target.translation()).norm(), params.position_tolerance);
      EXPECT_LE(angle_between(reached.linear(), target.linear()), params.orientation_tolerance);
      EXPECT_NEAR(result.position_residual, (reached.translation() - target.translation()).norm(),
                  1e-12);
      expect_within_limits(arm, result.q);
    }
  }
}

TEST(ArmKinematics, FarTargetIsOutOfReach) {
  const RobotModel model = load_robot_model(kShippedRobot);
  ArmKinematics arm(model, "base", "right_tool");
  const Eigen::VectorXd start = Eigen::VectorXd::Zero(7);
  const IkResult result = arm.solve(pointing_down({2.0, -0.2, 0.3}), start);
  EXPECT_EQ(result.status, IkResult::Status::out_of_reach);
  EXPECT_GT(result.position_residual, 1.0);
  EXPECT_EQ(result.restarts, IkParams{}.restarts);
  EXPECT_EQ(result.q, start);
}

// Two joints whose pose is reached only at q = (-1, 0) (mod 2 pi), outside
// joint 1's range [0, 0.5].
TEST(ArmKinematics, TargetReachedOnlyOutsideTheLimitsIsAJointLimit) {
  const testing::TempDir dir;
  const std::string path = dir.write(
      "planar.urdf",
      "<robot name='planar'><link name='a'/><link name='b'/><link name='c'/><link name='tip'/>"
      "<joint name='j1' type='revolute'><parent link='a'/><child link='b'/><axis xyz='0 0 1'/>"
      "<limit lower='0' upper='0.5' velocity='1' effort='1'/></joint>"
      "<joint name='j2' type='revolute'><parent link='b'/><child link='c'/><axis xyz='0 0 1'/>"
      "<origin xyz='0.5 0 0'/><limit lower='-1' upper='1' velocity='1' effort='1'/></joint>"
      "<joint name='t' type='fixed'><parent link='c'/><child link='tip'/>"
      "<origin xyz='0.4 0 0'/></joint></robot>");
  ArmKinematics arm(load_robot_model(path), "a", "tip");
  const Eigen::Vector2d start(0.25, 0.0);
  const IkResult outside = arm.solve(arm.forward(Eigen::Vector2d(-1.0, 0.0)), start);
  EXPECT_EQ(outside.status, IkResult::Status::joint_limit);
  EXPECT_LE(outside.position_residual, IkParams{}.position_tolerance);
  expect_within_limits(arm, outside.q);

  const IkResult inside = arm.solve(arm.forward(Eigen::Vector2d(0.4, -0.6)), start);
  ASSERT_EQ(inside.status, IkResult::Status::ok);
  EXPECT_NEAR(inside.q(0), 0.4, 1e-3);
  EXPECT_NEAR(inside.q(1), -0.6, 1e-3);
}

TEST(ArmKinematics, TracksALineWithTheToolDownWithoutFlips) {
  const RobotModel model = load_robot_model(kShippedRobot);
  const IkParams params;
  ArmKinematics arm(model, "base", "right_tool", params);
  const Eigen::Vector3d from(0.35, -0.25, 0.05), to(0.50, 0.05, 0.10);
  const int steps = 60;  // about 6 mm apart
  // An elbow-down arm in front of the body, its joints well inside their limits.
  Eigen::VectorXd home(7);
  home << 0.33, 1.08, -0.72, 1.74, 1.80, -0.99, 1.08;
  IkResult previous = arm.solve(pointing_down(from), home);
  ASSERT_EQ(previous.status, IkResult::Status::ok);
  for (int k = 1; k <= steps; ++k) {
    const Eigen::Vector3d point = from + (to - from) * (double(k) / steps);
    const IkResult next = arm.solve(pointing_down(point), previous.q);
    ASSERT_EQ(next.status, IkResult::Status::ok) << "step " << k;
    EXPECT_EQ(next.restarts, 0) << "step " << k;
    EXPECT_LT((next.q - previous.q).cwiseAbs().maxCoeff(), 0.1) << "step " << k;
    expect_within_limits(arm, next.q);
    previous = next;
  }
}

TEST(ArmKinematics, SameCallGivesBitIdenticalJointPositions) {
  const RobotModel model = load_robot_model(kShippedRobot);
  ArmKinematics first(model, "base", "left_tool");
  ArmKinematics second(model, "base", "left_tool");
  const Eigen::Isometry3d target = pointing_down({0.40, 0.05, 0.30});
  const Eigen::VectorXd start = Eigen::VectorXd::Constant(7, 1.5);
  const IkResult a = first.solve(target, start);
  const IkResult b = first.solve(target, start);
  const IkResult c = second.solve(target, start);
  ASSERT_EQ(a.status, IkResult::Status::ok);
  EXPECT_EQ(a.q, b.q);
  EXPECT_EQ(a.q, c.q);
  EXPECT_EQ(a.iterations, c.iterations);
}

TEST(ArmKinematics, ChainWithoutMovableJointsIsRejected) {
  const RobotModel model = load_robot_model(kShippedRobot);
  EXPECT_NE(testing::config_error_of([&] {
              ArmKinematics(model, "base", "head_camera");
            }).find("no movable joint from 'base' to 'head_camera'"),
            std::string::npos);
}

}  // namespace
}  // namespace corrmp
