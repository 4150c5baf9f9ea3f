// The robot's head camera looking at a Bullet world: every body drawn as its
// primitive in its colour by the OSMesa renderer, giving RGB and metric depth
// images (paper, Section III-B: the context is read from the camera image).
#pragma once

#include <memory>
#include <vector>

#include "core/config/field_rule.hpp"
#include "sim/bullet_world.hpp"
#include "sim/render/offscreen_renderer.hpp"

namespace corrmp {

struct HeadCameraParams {
  int width = 64;
  int height = 64;
  double vertical_fov_deg = 40.0;
  std::vector<double> eye{0.05, 0.0, 0.55};
  std::vector<double> target{0.45, -0.02, 0.0};
  std::vector<double> background{0.9, 0.9, 0.92};

  template <class Fields>
  void describe(Fields& f) {
    f("width", width, "image width (px)", in_range(8, 2048));
    f("height", height, "image height (px)", in_range(8, 2048));
    f("vertical_fov_deg", vertical_fov_deg, "vertical field of view (deg)", in_range(5, 170));
    f("eye", eye, "camera position [x, y, z] (m)", size_is(3));
    f("target", target, "point the camera looks at [x, y, z] (m)", size_is(3));
    f("background", background, "RGB of empty space", size_is(3).at_least(0.0).at_most(1.0));
  }
};

// The render scene of a world: one primitive per body.
RenderScene render_scene_of(const BulletWorld& world, const Eigen::Vector3f& background);

class HeadCamera {
 public:
  explicit HeadCamera(const HeadCameraParams& params);
  RgbdImage capture(const BulletWorld& world);
  // Any scene, for worlds that draw themselves (soft bodies); its background
  // is replaced by the camera's.
  RgbdImage capture(RenderScene scene);
  const Eigen::Isometry3d& world_from_camera() const { return world_from_camera_; }
  const CameraIntrinsics& intrinsics() const { return renderer_.intrinsics(); }

 private:
  HeadCameraParams params_;
  OffscreenRenderer renderer_;
  Eigen::Isometry3d world_from_camera_;
};

}  // namespace corrmp
