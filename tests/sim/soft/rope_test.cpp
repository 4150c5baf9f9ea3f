// Tests of the soft-body rope of the knotting task (paper, Section IV-C): it
// keeps its length hanging under gravity, its self-contact pass keeps crossing
// pieces apart, and a trial replays bitwise.
#include "sim/soft/rope.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/soft/soft_world.hpp"

namespace corrmp {
namespace {

TEST(Rope, KeepsLengthAndLinksHangingUnderGravity) {
  SoftWorld world(SoftWorldParams{});
  RopeParams params;
  params.length = 0.5;
  params.nodes = 51;
  Rope rope(world, params, straight_rope(params, {0, 0, 1}, {1, 0, 0}));
  rope.pin(0, true);
  for (int t = 0; t < 1200; ++t) world.step();
  EXPECT_EQ(world.blow_up(), "");
  EXPECT_NEAR(rope.node(0).z(), 1.0, 1e-6);
  // The rope swung down: its free end is now well below the pin.
  EXPECT_LT(rope.node(50).z(), 0.7);
  EXPECT_NEAR(rope.length(), 0.5, 0.5 * 0.03);
  for (int i = 0; i < 50; ++i) {
    EXPECT_NEAR((rope.node(i + 1) - rope.node(i)).norm(), 0.01, 0.003) << "link " << i;
  }
}

TEST(Rope, EndPointIsTheCentroidOfTheColouredEnd) {
  SoftWorld world(SoftWorldParams{});
  RopeParams params;
  params.length = 0.5;
  params.nodes = 51;
  params.end_length = 0.05;
  Rope rope(world, params, straight_rope(params, {0, 0, 1}, {1, 0, 0}));
  EXPECT_EQ(rope.first_end_node(), 45);
  EXPECT_NEAR(rope.end_point().x(), 0.475, 1e-6);
}

// Nodes every `spacing` along the polyline through `corners`.
std::vector<Eigen::Vector3d> walk(const std::vector<Eigen::Vector3d>& corners, double spacing) {
  std::vector<Eigen::Vector3d> nodes{corners.front()};
  for (size_t k = 1; k < corners.size(); ++k) {
    const Eigen::Vector3d d = corners[k] - corners[k - 1];
    const int steps = static_cast<int>(std::lround(d.norm() / spacing));
    for (int i = 1; i <= steps; ++i) nodes.push_back(corners[k - 1] + d * i / steps);
  }
  return nodes;
}

// One rope: a piece along x at z = 1, pinned at its ends, a turn, then a piece
// along y 3 cm above it, pinned at its ends, which falls onto the first. With
// the self-contact pass the pieces stay two radii apart.
double closest_crossing_distance() {
  SoftWorld world(SoftWorldParams{});
  const std::vector<Eigen::Vector3d> positions =
      walk({{-0.12, 0, 1}, {0.12, 0, 1}, {0.12, 0, 1.03}, {0, -0.12, 1.03}, {0, 0.12, 1.03}}, 0.01);
  RopeParams params;
  params.nodes = static_cast<int>(positions.size());
  params.length = 0.01 * (params.nodes - 1);
  Rope rope(world, params, positions);
  const int first_end = 24, second_start = params.nodes - 25;
  for (int i : {0, first_end, second_start, params.nodes - 1}) rope.pin(i, true);
  double closest = 1e9;
  for (int t = 0; t < 600; ++t) {
    world.step();
    for (int i = 0; i <= first_end; ++i) {
      for (int j = second_start; j < params.nodes; ++j) {
        closest = std::min(closest, (rope.node(i) - rope.node(j)).norm());
      }
    }
  }
  EXPECT_EQ(world.blow_up(), "");
  // The upper piece did fall: its middle sags onto the lower piece.
  EXPECT_LT(rope.node(params.nodes - 13).z(), 1.02);
  return closest;
}

TEST(Rope, SelfContactKeepsCrossingPiecesApart) {
  // Node-to-node distance at a crossing of two segments is at least the
  // segment distance; two radii = 1 cm, allow 2 mm of penetration.
  EXPECT_GT(closest_crossing_distance(), 0.008);
}

// Two coincident nodes make a zero-length segment; the self-contact pass must
// treat it as a point (it divided by its length).
TEST(Rope, SelfContactWithAZeroLengthSegmentStaysFinite) {
  SoftWorld world(SoftWorldParams{});
  RopeParams params;
  params.length = 0.2;
  params.nodes = 21;
  Rope rope(world, params, straight_rope(params, {0, 0, 1}, {1, 0, 0}));
  // Nodes 10 and 11 both 4 mm above segment 5-6: closer than two radii.
  const Eigen::Vector3d above = rope.node(5) + Eigen::Vector3d(0.005, 0, 0.004);
  rope.set_node(10, above);
  rope.set_node(11, above);
  rope.self_contact();
  for (int i = 0; i < rope.node_count(); ++i) {
    ASSERT_TRUE(rope.node(i).allFinite()) << "node " << i;
  }
  // The pass pushed the point away from the segment below it.
  EXPECT_GT(rope.node(10).z() - rope.node(5).z(), 0.004);
}

TEST(Rope, ColoursNeedThreeValues) {
  SoftWorld world(SoftWorldParams{});
  RopeParams params;
  params.end_colour = {0.9, 0.1};
  EXPECT_THROW(Rope(world, params, straight_rope(params, {0, 0, 1}, {1, 0, 0})),
               std::invalid_argument);
}

TEST(Rope, TwoRunsAreBitwiseEqual) {
  auto run = [] {
    SoftWorld world(SoftWorldParams{});
    RopeParams params;
    Rope rope(world, params, straight_rope(params, {-0.4, 0, 1}, {1, 0, 0.2}));
    world.add_bar("bar", {0, 0, 0.9}, 0.0125, 0.4, 1.0);
    rope.pin(0, true);
    for (int t = 0; t < 900; ++t) world.step();
    return rope.nodes();
  };
  const auto a = run();
  const auto b = run();
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x(), b[i].x());
    EXPECT_EQ(a[i].y(), b[i].y());
    EXPECT_EQ(a[i].z(), b[i].z());
  }
}

}  // namespace
}  // namespace corrmp
