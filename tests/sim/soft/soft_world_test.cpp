// Tests of the soft-rigid world of the rope task (paper, Section IV-C): rope
// resting on the bar, blow-up detection.
#include "sim/soft/soft_world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sim/soft/rope.hpp"

namespace corrmp {
namespace {

TEST(SoftWorld, RopeDrapedOverTheBarRestsOnItsSurface) {
  SoftWorld world(SoftWorldParams{});
  world.add_bar("bar", {0, 0, 1}, 0.0125, 0.4, 1.0);
  RopeParams params;
  params.length = 0.4;
  params.nodes = 41;
  Rope rope(world, params, straight_rope(params, {-0.2, 0, 1.02}, {1, 0, 0}));
  for (int t = 0; t < 1200; ++t) world.step();
  ASSERT_EQ(world.blow_up(), "");
  // The middle node lies on top of the bar: one bar radius plus one rope radius
  // above its axis, give or take a few millimetres of sinking.
  const Eigen::Vector3d top = rope.node(20);
  EXPECT_NEAR(top.z() - 1.0, 0.0125 + 0.005, 0.004);
  EXPECT_LT(rope.node(0).z(), 0.9);
  EXPECT_LT(rope.node(40).z(), 0.9);
}

TEST(SoftWorld, BlowUpReportsANonFiniteNode) {
  SoftWorld world(SoftWorldParams{});
  RopeParams params;
  Rope rope(world, params, straight_rope(params, {0, 0, 1}, {1, 0, 0}));
  world.step();
  EXPECT_EQ(world.blow_up(), "");
  rope.set_node(7, Eigen::Vector3d(std::numeric_limits<double>::quiet_NaN(), 0, 1));
  const std::string fault = world.blow_up();
  EXPECT_NE(fault.find("node 7"), std::string::npos) << fault;
}

TEST(SoftWorld, BlowUpReportsAStretchedLinkAndANodeOutOfBounds) {
  SoftWorld world(SoftWorldParams{});
  RopeParams params;
  Rope rope(world, params, straight_rope(params, {0, 0, 1}, {1, 0, 0}));
  rope.set_node(80, rope.node(80) + Eigen::Vector3d(0, 0, 0.2));
  EXPECT_NE(world.blow_up().find("stretched"), std::string::npos);
  rope.set_node(80, Eigen::Vector3d(0, 0, 50));
  EXPECT_NE(world.blow_up().find("from the origin"), std::string::npos);
}

TEST(SoftWorld, RefusesANonPositiveTimeStep) {
  SoftWorldParams params;
  params.time_step = 0;
  EXPECT_THROW(SoftWorld world(params), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp
