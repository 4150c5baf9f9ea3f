// OpenGL projection and view matrices for the pinhole camera (formulas in
// gl_projection.hpp).
#include "sim/render/gl_projection.hpp"

namespace corrmp {

Eigen::Matrix4d gl_projection_matrix(const CameraIntrinsics& k) {
  const double w = k.width;
  const double h = k.height;
  const double n = k.near;
  const double f = k.far;
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = 2.0 * k.fx / w;
  p(0, 2) = 1.0 - (2.0 * k.cx + 1.0) / w;
  p(1, 1) = 2.0 * k.fy / h;
  p(1, 2) = (2.0 * k.cy + 1.0) / h - 1.0;
  p(2, 2) = -(f + n) / (f - n);
  p(2, 3) = -2.0 * f * n / (f - n);
  p(3, 2) = -1.0;
  return p;
}

Eigen::Matrix4d gl_view_matrix(const Eigen::Isometry3d& world_from_camera) {
  const Eigen::Vector4d flip(1.0, -1.0, -1.0, 1.0);
  return flip.asDiagonal() * world_from_camera.inverse().matrix();
}

}  // namespace corrmp
