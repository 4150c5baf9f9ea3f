// The head camera over a Bullet world.
#include "sim/head_camera.hpp"

#include <cmath>

namespace corrmp {

namespace {

Eigen::Vector3d vector3(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

RenderShape shape_of(const BodyInfo& info) {
  const auto& s = info.size;
  if (info.shape == "box") return Box{Eigen::Vector3d(s[0] / 2, s[1] / 2, s[2] / 2)};
  if (info.shape == "cylinder") return Cylinder{s[0], s[1] / 2};
  if (info.shape == "capsule") return Capsule{s[0], s[1] / 2};
  return Sphere{s[0]};
}

}  // namespace

RenderScene render_scene_of(const BulletWorld& world, const Eigen::Vector3f& background) {
  RenderScene scene;
  scene.background = background;
  for (int i = 0; i < world.body_count(); ++i) {
    const BodyInfo& info = world.info(i);
    scene.items.push_back(RenderItem{shape_of(info), world.pose(i), info.colour});
  }
  return scene;
}

HeadCamera::HeadCamera(const HeadCameraParams& params)
    : params_(params),
      renderer_(CameraIntrinsics::from_vertical_fov(params.width, params.height,
                                                    params.vertical_fov_deg * M_PI / 180.0)),
      world_from_camera_(
          look_at(vector3(params.eye), vector3(params.target), Eigen::Vector3d::UnitZ())) {}

RgbdImage HeadCamera::capture(const BulletWorld& world) {
  const Eigen::Vector3f background(params_.background[0], params_.background[1],
                                   params_.background[2]);
  return renderer_.render(render_scene_of(world, background), world_from_camera_);
}

RgbdImage HeadCamera::capture(RenderScene scene) {
  scene.background =
      Eigen::Vector3f(params_.background[0], params_.background[1], params_.background[2]);
  return renderer_.render(scene, world_from_camera_);
}

}  // namespace corrmp
