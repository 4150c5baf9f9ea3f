// Test scenes for the rope-end segmentation (paper, Section IV-C): a rope drawn as a node
// chain whose last few centimetres are red, hanging from a grey bar, with dark grippers,
// an orange and a pink box as distractors, over a light background, seen by the head camera.
#pragma once

#include <Eigen/Geometry>

#include <vector>

#include "core/seeds.hpp"
#include "data/camera_model.hpp"
#include "sim/render/render_scene.hpp"

namespace corrmp::test {

inline const Eigen::Vector3f kRopeEndRed(0.85f, 0.1f, 0.1f);
inline const Eigen::Vector3f kRopeBlueGrey(0.6f, 0.68f, 0.78f);
inline const Eigen::Vector3f kBarGrey(0.5f, 0.5f, 0.5f);
inline const Eigen::Vector3f kGripperDark(0.22f, 0.22f, 0.27f);
inline const Eigen::Vector3f kOrange(0.95f, 0.55f, 0.1f);
inline const Eigen::Vector3f kPink(0.95f, 0.6f, 0.7f);
inline const Eigen::Vector3f kLightBackground(0.92f, 0.92f, 0.9f);
constexpr double kRopeRadius = 0.005;
constexpr int kRedNodes = 5;  // the red end: 4 segments of 1 cm
constexpr double kNodeSpacing = 0.01;

// The head camera: eye (-0.45, 0, 0.75) looking at (0, 0, 0.3), 320x240, 45 degrees fov_y.
CameraIntrinsics head_camera_intrinsics();
Eigen::Isometry3d head_camera_pose();

// Rope nodes from the bar to the free end (the last kRedNodes are the red end).
struct RopePlacement {
  std::vector<Eigen::Vector3d> nodes;
  Eigen::Vector3d red_centroid;  // mean of the red end's centre-line nodes
};

// The free end at `end`, the red part running from it towards `direction` (normalised
// here), the body continuing that way for 10 cm and then to the top of the bar.
RopePlacement rope_with_end_at(const Eigen::Vector3d& end, const Eigen::Vector3d& direction);

// A random rope-end placement in front of the bar, well inside the image.
RopePlacement random_rope(Rng& rng);

struct SceneContents {
  bool red_end = true;      // false: the whole rope is blue-grey
  bool distractors = true;  // grippers, orange and pink boxes
};

RenderScene rope_scene(const RopePlacement& rope, const SceneContents& contents = {});

}  // namespace corrmp::test
