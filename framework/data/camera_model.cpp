// Pinhole camera model, look-at poses, projection and back-projection (see
// camera_model.hpp for the conventions).
#include "data/camera_model.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace corrmp {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

CameraIntrinsics CameraIntrinsics::from_vertical_fov(int width, int height, double fov_y,
                                                     double near, double far) {
  if (!(fov_y > 0.0 && fov_y < kPi)) {
    throw std::invalid_argument(
        fmt::format("camera: vertical field of view {} rad is not in (0, pi)", fov_y));
  }
  CameraIntrinsics intrinsics;
  intrinsics.width = width;
  intrinsics.height = height;
  intrinsics.fy = 0.5 * height / std::tan(0.5 * fov_y);
  intrinsics.fx = intrinsics.fy;
  intrinsics.cx = 0.5 * (width - 1);
  intrinsics.cy = 0.5 * (height - 1);
  intrinsics.near = near;
  intrinsics.far = far;
  intrinsics.validate();
  return intrinsics;
}

void CameraIntrinsics::validate() const {
  const auto fail = [](const char* what, double value) {
    throw std::invalid_argument(fmt::format("camera intrinsics: {} (got {})", what, value));
  };
  if (width <= 0) fail("width must be positive", width);
  if (height <= 0) fail("height must be positive", height);
  if (!(std::isfinite(fx) && fx > 0.0)) fail("fx must be positive and finite", fx);
  if (!(std::isfinite(fy) && fy > 0.0)) fail("fy must be positive and finite", fy);
  if (!std::isfinite(cx)) fail("cx must be finite", cx);
  if (!std::isfinite(cy)) fail("cy must be finite", cy);
  if (!(std::isfinite(near) && near > 0.0)) fail("near must be positive and finite", near);
  if (!(std::isfinite(far) && far > near)) fail("far must be finite and greater than near", far);
}

Eigen::Isometry3d look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                          const Eigen::Vector3d& up) {
  const Eigen::Vector3d forward = target - eye;
  if (!(forward.norm() > 0.0)) throw std::invalid_argument("look_at: eye and target coincide");
  const Eigen::Vector3d z = forward.normalized();
  const Eigen::Vector3d right = z.cross(up);
  if (!(right.norm() > 1e-9 * up.norm())) {
    throw std::invalid_argument("look_at: up is parallel to the viewing direction");
  }
  const Eigen::Vector3d x = right.normalized();
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
  world_from_camera.linear().col(0) = x;
  world_from_camera.linear().col(1) = z.cross(x);
  world_from_camera.linear().col(2) = z;
  world_from_camera.translation() = eye;
  return world_from_camera;
}

std::optional<Eigen::Vector2d> project(const CameraIntrinsics& intrinsics,
                                       const Eigen::Isometry3d& world_from_camera,
                                       const Eigen::Vector3d& point_world) {
  const Eigen::Vector3d p = world_from_camera.inverse() * point_world;
  if (!(p.z() > 0.0)) return std::nullopt;
  return Eigen::Vector2d(intrinsics.fx * p.x() / p.z() + intrinsics.cx,
                         intrinsics.fy * p.y() / p.z() + intrinsics.cy);
}

Eigen::Vector3d back_project(const CameraIntrinsics& intrinsics,
                             const Eigen::Isometry3d& world_from_camera,
                             const Eigen::Vector2d& pixel, double depth) {
  const Eigen::Vector3d p((pixel.x() - intrinsics.cx) * depth / intrinsics.fx,
                          (pixel.y() - intrinsics.cy) * depth / intrinsics.fy, depth);
  return world_from_camera * p;
}

}  // namespace corrmp
