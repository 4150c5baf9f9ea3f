// Test scenes for the rope-end segmentation (see rope_scene.hpp).
#include "rope_scene.hpp"

#include "sim/render/node_chain.hpp"

#include <algorithm>
#include <cmath>

namespace corrmp::test {
namespace {

constexpr double kPi = 3.14159265358979323846;
const Eigen::Vector3d kBarCentre(0.05, 0.0, 0.3);
const Eigen::Vector3d kBarHalfExtents(0.015, 0.35, 0.015);

RenderItem box(const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extents,
               const Eigen::Vector3f& colour) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = centre;
  return {Box{half_extents}, pose, colour};
}

std::vector<Eigen::Vector3d> line(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                  double spacing) {
  const int segments = std::max(1, int(std::ceil((to - from).norm() / spacing)));
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i <= segments; ++i) points.push_back(from + (to - from) * i / segments);
  return points;
}

}  // namespace

CameraIntrinsics head_camera_intrinsics() {
  return CameraIntrinsics::from_vertical_fov(320, 240, kPi / 4.0);
}

Eigen::Isometry3d head_camera_pose() {
  return look_at(Eigen::Vector3d(-0.45, 0.0, 0.75), Eigen::Vector3d(0.0, 0.0, 0.3),
                 Eigen::Vector3d::UnitZ());
}

RopePlacement rope_with_end_at(const Eigen::Vector3d& end, const Eigen::Vector3d& direction) {
  const Eigen::Vector3d d = direction.normalized();
  const Eigen::Vector3d red_start = end + (kRedNodes - 1) * kNodeSpacing * d;
  const Eigen::Vector3d bend = red_start + 0.1 * d;
  const Eigen::Vector3d on_bar(kBarCentre.x(), bend.y(),
                               kBarCentre.z() + kBarHalfExtents.z() + kRopeRadius);
  RopePlacement rope;
  for (const Eigen::Vector3d& p : line(on_bar, bend, kNodeSpacing)) rope.nodes.push_back(p);
  const std::vector<Eigen::Vector3d> body = line(bend, red_start, kNodeSpacing);
  rope.nodes.insert(rope.nodes.end(), body.begin() + 1, body.end());
  rope.red_centroid = Eigen::Vector3d::Zero();
  for (int k = kRedNodes - 2; k >= 0; --k) rope.nodes.push_back(end + k * kNodeSpacing * d);
  for (int k = 0; k < kRedNodes; ++k) rope.red_centroid += end + k * kNodeSpacing * d;
  rope.red_centroid /= kRedNodes;
  return rope;
}

RopePlacement random_rope(Rng& rng) {
  const Eigen::Vector3d end(rng.uniform(-0.08, 0.0), rng.uniform(-0.12, 0.12),
                            rng.uniform(0.12, 0.28));
  const Eigen::Vector3d direction(rng.uniform(-0.3, 0.6), rng.uniform(-0.8, 0.8),
                                  rng.uniform(0.4, 1.0));
  return rope_with_end_at(end, direction);
}

RenderScene rope_scene(const RopePlacement& rope, const SceneContents& contents) {
  RenderScene scene;
  scene.background = kLightBackground;
  scene.items.push_back(box(kBarCentre, kBarHalfExtents, kBarGrey));
  const auto red_begin = rope.nodes.end() - kRedNodes;
  add_node_chain(scene, {rope.nodes.begin(), red_begin + 1}, kRopeRadius, kRopeBlueGrey);
  add_node_chain(scene, {red_begin, rope.nodes.end()}, kRopeRadius,
                 contents.red_end ? kRopeEndRed : kRopeBlueGrey);
  if (contents.distractors) {
    const Eigen::Vector3d finger(0.02, 0.012, 0.04);
    for (double side : {-1.0, 1.0}) {
      scene.items.push_back(box({-0.05, side * 0.2, 0.45}, finger, kGripperDark));
      scene.items.push_back(box({-0.05, side * 0.17, 0.45}, finger, kGripperDark));
      scene.items.push_back(box({-0.05, side * 0.185, 0.5}, {0.03, 0.03, 0.01}, kGripperDark));
    }
    scene.items.push_back(box({-0.02, -0.23, 0.12}, Eigen::Vector3d::Constant(0.03), kOrange));
    scene.items.push_back(box({-0.02, 0.23, 0.12}, Eigen::Vector3d::Constant(0.03), kPink));
  }
  return scene;
}

}  // namespace corrmp::test
