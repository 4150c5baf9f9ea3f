// Tests of the rope node-chain primitives.
#include "sim/render/node_chain.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <variant>

namespace corrmp {
namespace {

TEST(SegmentPose, PutsTheCapsuleAxisOnTheSegment) {
  const Eigen::Vector3d from(0.1, 0.2, 0.3);
  const Eigen::Vector3d to(0.4, -0.2, 0.5);
  const Eigen::Isometry3d pose = segment_pose(from, to);
  const double half = 0.5 * (to - from).norm();
  EXPECT_TRUE((pose * Eigen::Vector3d(0.0, 0.0, -half)).isApprox(from, 1e-12));
  EXPECT_TRUE((pose * Eigen::Vector3d(0.0, 0.0, half)).isApprox(to, 1e-12));
  EXPECT_THROW(segment_pose(from, from), std::invalid_argument);
}

TEST(AddNodeChain, CapsulesJoinConsecutiveNodes) {
  RenderScene scene;
  const std::vector<Eigen::Vector3d> nodes = {Eigen::Vector3d(0.0, 0.0, 0.0),
                                              Eigen::Vector3d(0.1, 0.0, 0.0),
                                              Eigen::Vector3d(0.1, 0.1, 0.0)};
  const Eigen::Vector3f colour(1.0f, 0.5f, 0.0f);
  add_node_chain(scene, nodes, 0.01, colour);
  ASSERT_EQ(scene.items.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const RenderItem& item = scene.items[i];
    const auto* capsule = std::get_if<Capsule>(&item.shape);
    ASSERT_NE(capsule, nullptr);
    EXPECT_DOUBLE_EQ(capsule->radius, 0.01);
    EXPECT_NEAR(capsule->half_height, 0.05, 1e-12);
    const Eigen::Vector3d start = item.pose * Eigen::Vector3d(0.0, 0.0, -capsule->half_height);
    const Eigen::Vector3d end = item.pose * Eigen::Vector3d(0.0, 0.0, capsule->half_height);
    EXPECT_NEAR((start - nodes[i]).norm(), 0.0, 1e-12);
    EXPECT_NEAR((end - nodes[i + 1]).norm(), 0.0, 1e-12);
    EXPECT_TRUE(item.colour.isApprox(colour));
  }
}

TEST(AddNodeChain, SpheresStyleAndDegenerateChains) {
  const std::vector<Eigen::Vector3d> nodes = {Eigen::Vector3d(0.0, 0.0, 0.0),
                                              Eigen::Vector3d(0.0, 0.0, 0.0),
                                              Eigen::Vector3d(0.0, 0.0, 0.2)};
  RenderScene beads;
  add_node_chain(beads, nodes, 0.02, Eigen::Vector3f::Ones(), ChainStyle::kSpheres);
  ASSERT_EQ(beads.items.size(), 3u);
  EXPECT_TRUE(std::holds_alternative<Sphere>(beads.items[2].shape));
  EXPECT_TRUE(beads.items[2].pose.translation().isApprox(nodes[2]));

  RenderScene tube;
  add_node_chain(tube, nodes, 0.02, Eigen::Vector3f::Ones());
  ASSERT_EQ(tube.items.size(), 2u);  // the repeated node becomes a sphere
  EXPECT_TRUE(std::holds_alternative<Sphere>(tube.items[0].shape));
  EXPECT_TRUE(std::holds_alternative<Capsule>(tube.items[1].shape));

  RenderScene single;
  add_node_chain(single, {Eigen::Vector3d(1.0, 2.0, 3.0)}, 0.02, Eigen::Vector3f::Ones());
  ASSERT_EQ(single.items.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<Sphere>(single.items[0].shape));

  RenderScene empty;
  add_node_chain(empty, {}, 0.02, Eigen::Vector3f::Ones());
  EXPECT_TRUE(empty.items.empty());
  EXPECT_THROW(add_node_chain(empty, nodes, 0.0, Eigen::Vector3f::Ones()), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp
