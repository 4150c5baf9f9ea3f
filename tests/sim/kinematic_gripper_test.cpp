// Tests of the kinematic gripper: tracking accuracy, bounded speed, the
// positions reported per waypoint, pushing.
#include "sim/kinematic_gripper.hpp"

#include <gtest/gtest.h>

namespace corrmp {
namespace {

TEST(KinematicGripper, TracksWaypointsExactlyAtBoundedSpeed) {
  BulletWorld world(PhysicsParams{});
  GripperParams params;
  params.max_speed = 0.1;
  KinematicGripper gripper(world, params, Eigen::Vector3d(0, 0, 0.2));
  Eigen::MatrixXd waypoints(3, 3);
  waypoints << 0.0, 0.0, 0.2, 0.1, 0.0, 0.2, 0.1, 0.05, 0.15;
  std::vector<Eigen::Vector3d> visited;
  const TrackingResult result = gripper.follow(waypoints, [&] {
    visited.push_back(gripper.position());
    return std::string();
  });
  ASSERT_TRUE(result.ok) << result.failure;
  EXPECT_LT((gripper.position() - Eigen::Vector3d(0.1, 0.05, 0.15)).norm(), 1e-12);
  // Path length 0.1 + 0.0707 m at 0.1 m/s and 240 Hz.
  const double length = 0.1 + std::sqrt(2.0) * 0.05;
  EXPECT_NEAR(result.ticks, std::ceil(0.1 / (0.1 / 240)) + std::ceil((length - 0.1) / (0.1 / 240)),
              1.0);
  for (size_t i = 1; i < visited.size(); ++i) {
    EXPECT_LE((visited[i] - visited[i - 1]).norm(), 0.1 / 240 + 1e-12);
  }
  // The corner waypoint is visited exactly.
  bool corner = false;
  for (const auto& p : visited) corner |= (p - Eigen::Vector3d(0.1, 0, 0.2)).norm() < 1e-12;
  EXPECT_TRUE(corner);
  // The fingers' bodies follow the tool centre point.
  EXPECT_NEAR(world.position(gripper.bodies()[1]).y(), 0.05, 1e-9);
}

TEST(KinematicGripper, ReportsWhereItWasAtEachWaypointReached) {
  BulletWorld world(PhysicsParams{});
  KinematicGripper gripper(world, GripperParams{}, Eigen::Vector3d(0, 0, 0.2));
  Eigen::MatrixXd waypoints(4, 3);
  waypoints << 0.0, 0.0, 0.2, 0.01, 0.0, 0.2, 0.01, 0.01, 0.2, 0.0, 0.01, 0.2;
  const TrackingResult result = gripper.follow(waypoints, nullptr);
  ASSERT_TRUE(result.ok) << result.failure;
  // One row per waypoint, the first (where it already was) reached without a tick.
  ASSERT_EQ(result.reached.rows(), 4);
  ASSERT_EQ(result.reached.cols(), 3);
  EXPECT_LT((result.reached - waypoints).cwiseAbs().maxCoeff(), 1e-12);
  // Stopped on the way to the third waypoint: the first two rows.
  gripper.place(Eigen::Vector3d(0, 0, 0.2));
  int ticks = 0;
  const TrackingResult stopped = gripper.follow(waypoints, [&] {
    return ++ticks == result.ticks / 2 + 1 ? std::string("stop") : std::string();
  });
  EXPECT_FALSE(stopped.ok);
  ASSERT_EQ(stopped.reached.rows(), 2);
  EXPECT_LT((stopped.reached - waypoints.topRows(2)).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(KinematicGripper, PushesAnObjectAlongAndStopsOnAFailure) {
  BulletWorld world(PhysicsParams{});
  SceneBodySpec table;
  table.name = "table";
  table.size = {1, 1, 0.04};
  table.position = {0, 0, -0.02};
  SceneBodySpec box = table;
  box.name = "box";
  box.size = {0.04, 0.04, 0.04};
  box.position = {0, 0.05, 0.02};
  box.mass = 0.2;
  world.add_body(table);
  const int b = world.add_body(box);
  KinematicGripper gripper(world, GripperParams{}, Eigen::Vector3d(0, 0, 0.03));
  Eigen::MatrixXd push(2, 3);
  push << 0, 0, 0.03, 0, 0.1, 0.03;
  ASSERT_TRUE(gripper.follow(push, nullptr).ok);
  for (int i = 0; i < 60; ++i) world.step();
  // The box's near face ends at the fingers' front face, or slid a little past it.
  EXPECT_GE(world.position(b).y(), 0.1 + 0.015 + 0.02 - 1e-3);
  EXPECT_LE(world.position(b).y(), 0.1 + 0.015 + 0.02 + 0.008);
  EXPECT_NEAR(world.position(b).x(), 0.0, 4e-3);
  Eigen::MatrixXd bad(1, 3);
  bad << std::nan(""), 0, 0;
  const TrackingResult failed = gripper.follow(bad, nullptr);
  EXPECT_FALSE(failed.ok);
  EXPECT_NE(failed.failure.find("not finite"), std::string::npos);
  EXPECT_EQ(failed.reached.rows(), 0);
  int calls = 0;
  const TrackingResult stopped =
      gripper.follow(push, [&] { return ++calls == 3 ? std::string("stop") : std::string(); });
  EXPECT_FALSE(stopped.ok);
  EXPECT_EQ(stopped.ticks, 3);
}

}  // namespace
}  // namespace corrmp
