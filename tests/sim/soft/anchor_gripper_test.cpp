// Tests of the anchoring gripper of the rope task (paper, Section IV-C):
// closing counts the enclosed nodes (0 = missed enclose), near misses, moving
// a closed gripper carries the rope, opening releases gradually.
#include "sim/soft/anchor_gripper.hpp"

#include <gtest/gtest.h>

namespace corrmp {
namespace {

// A rope hanging from a pinned node at (0, 0, 1) along -z... laid straight down.
struct Hanging {
  SoftWorld world{SoftWorldParams{}};
  RopeParams params = [] {
    RopeParams p;
    p.length = 0.4;
    p.nodes = 41;
    return p;
  }();
  Rope rope{world, params, straight_rope(params, {0, 0, 1}, {0, 0, -1})};
  Hanging() { rope.pin(0, true); }
};

// Fingers point along +y, close along x.
Eigen::Matrix3d side_grasp() {
  Eigen::Matrix3d r;
  r.col(0) = Eigen::Vector3d::UnitX();
  r.col(1) = Eigen::Vector3d::UnitZ();
  r.col(2) = -Eigen::Vector3d::UnitY();
  return r;
}

TEST(AnchorGripper, ClosingAroundTheRopeAnchorsTheNodesInTheGap) {
  Hanging h;
  AnchorGripper gripper(h.rope, AnchorGripperParams{}, side_grasp(), {0, 0, 0.795});
  EXPECT_FALSE(gripper.near_miss());
  // Finger width 2 cm along z at 1 cm spacing: nodes 20 and 21 (z 0.8, 0.79).
  EXPECT_EQ(gripper.close(), 2);
  EXPECT_EQ(gripper.anchored(), 2);
  EXPECT_TRUE(gripper.closed());
}

TEST(AnchorGripper, ClosingBesideTheRopeMissesAndReportsANearMiss) {
  Hanging h;
  // The rope is 2.1 cm from the gap centre along x: against the finger.
  AnchorGripper near(h.rope, AnchorGripperParams{}, side_grasp(), {0.021, 0, 0.795});
  EXPECT_TRUE(near.near_miss());
  EXPECT_EQ(near.close(), 0);
  AnchorGripper far(h.rope, AnchorGripperParams{}, side_grasp(), {0.1, 0, 0.795});
  EXPECT_FALSE(far.near_miss());
  EXPECT_EQ(far.close(), 0);
}

TEST(AnchorGripper, AClosedGripperCarriesTheRopeAndReleasesItGradually) {
  Hanging h;
  AnchorGripperParams params;
  params.release_time = 0.2;
  AnchorGripper gripper(h.rope, params, side_grasp(), {0, 0, 0.795});
  ASSERT_EQ(gripper.close(), 2);
  Eigen::Vector3d target(0, 0, 0.795);
  for (int t = 0; t < 300; ++t) {
    target.x() += 0.1 / 300;
    gripper.tick_to(target);
    h.world.step();
  }
  ASSERT_EQ(h.world.blow_up(), "");
  EXPECT_NEAR(h.rope.node(20).x(), 0.1, 0.005);
  gripper.open();
  EXPECT_TRUE(gripper.releasing());
  // Half-way through the ramp the anchors still act.
  for (int t = 0; t < 60; ++t) {
    gripper.tick_to(target);
    h.world.step();
  }
  EXPECT_EQ(gripper.anchored(), 2);
  for (int t = 0; t < 70; ++t) {
    gripper.tick_to(target);
    h.world.step();
  }
  EXPECT_EQ(gripper.anchored(), 0);
  EXPECT_FALSE(gripper.releasing());
  // Let go: the rope swings back under the pin.
  for (int t = 0; t < 1200; ++t) {
    gripper.tick_to(target);
    h.world.step();
  }
  EXPECT_LT(std::abs(h.rope.node(20).x()), 0.03);
}

TEST(AnchorGripper, AColourOfTwoValuesIsRefused) {
  Hanging h;
  AnchorGripperParams params;
  params.colour = {0.25, 0.25};
  EXPECT_THROW(AnchorGripper(h.rope, params, side_grasp(), {0, 0, 0.795}), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp
