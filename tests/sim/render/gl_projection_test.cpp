// Tests that the OpenGL matrices reproduce the pinhole model pixel for pixel and that
// window depth converts back to metric depth.
#include "sim/render/gl_projection.hpp"

#include <gtest/gtest.h>

namespace corrmp {
namespace {

// OpenCV pixel (u, v) and window depth of a world point through the OpenGL pipeline.
Eigen::Vector3d through_opengl(const CameraIntrinsics& k, const Eigen::Isometry3d& pose,
                               const Eigen::Vector3d& point) {
  const Eigen::Vector4d clip = gl_projection_matrix(k) * gl_view_matrix(pose) * point.homogeneous();
  const Eigen::Vector3d ndc = clip.head<3>() / clip.w();
  const double x_window = 0.5 * (ndc.x() + 1.0) * k.width;
  const double y_window = 0.5 * (ndc.y() + 1.0) * k.height;
  return Eigen::Vector3d(x_window - 0.5, k.height - y_window - 0.5, 0.5 * (ndc.z() + 1.0));
}

TEST(GlProjection, MatchesThePinholeProjection) {
  CameraIntrinsics k;
  k.width = 96;
  k.height = 64;
  k.fx = 70.0;
  k.fy = 75.0;
  k.cx = 40.3;
  k.cy = 35.1;
  k.near = 0.05;
  k.far = 5.0;
  const Eigen::Isometry3d pose = look_at(Eigen::Vector3d(0.0, -0.5, 1.4),
                                         Eigen::Vector3d(0.6, 0.2, 0.7), Eigen::Vector3d::UnitZ());
  for (const Eigen::Vector3d& point :
       {Eigen::Vector3d(0.6, 0.2, 0.7), Eigen::Vector3d(0.9, 0.4, 0.75),
        Eigen::Vector3d(0.3, -0.1, 0.8)}) {
    const Eigen::Vector3d gl = through_opengl(k, pose, point);
    const Eigen::Vector2d pinhole = *project(k, pose, point);
    EXPECT_NEAR(gl.x(), pinhole.x(), 1e-9);
    EXPECT_NEAR(gl.y(), pinhole.y(), 1e-9);
    const double z = (pose.inverse() * point).z();
    EXPECT_NEAR(metric_depth_from_window(gl.z(), k.near, k.far), z, 1e-9);
  }
}

TEST(GlProjection, ClippingPlanesMapToWindowDepthZeroAndOne) {
  const CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(32, 32, 1.0, 0.1, 4.0);
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  EXPECT_NEAR(through_opengl(k, identity, Eigen::Vector3d(0.0, 0.0, 0.1)).z(), 0.0, 1e-12);
  EXPECT_NEAR(through_opengl(k, identity, Eigen::Vector3d(0.0, 0.0, 4.0)).z(), 1.0, 1e-12);
  EXPECT_NEAR(metric_depth_from_window(0.0, 0.1, 4.0), 0.1, 1e-12);
  EXPECT_NEAR(metric_depth_from_window(1.0, 0.1, 4.0), 4.0, 1e-12);
}

TEST(GlViewMatrix, TurnsTheOpenCvFrameIntoTheOpenGlEyeFrame) {
  const Eigen::Matrix4d view = gl_view_matrix(Eigen::Isometry3d::Identity());
  // A point 1 m in front of the camera, 0.2 m below the axis (OpenCV +y).
  const Eigen::Vector4d eye = view * Eigen::Vector4d(0.0, 0.2, 1.0, 1.0);
  EXPECT_TRUE(eye.isApprox(Eigen::Vector4d(0.0, -0.2, -1.0, 1.0)));
}

}  // namespace
}  // namespace corrmp
