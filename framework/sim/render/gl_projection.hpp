// The OpenGL matrices and depth conversion that make the off-screen renderer draw the
// pinhole camera of camera_model.hpp exactly (the robot's head camera, paper Sec. IV-A
// and V). Pure maths, no OpenGL calls, so it is tested without a context.
//
// OpenGL's eye frame is x right, y up, z backward; the OpenCV camera frame is x right,
// y down, z forward, so  gl_eye_from_camera = diag(1, -1, -1)  and
//   view = gl_eye_from_camera * world_from_camera^-1.
//
// Window coordinates put pixel centres at half-integers with the origin at the bottom
// left, so the OpenCV pixel (u, v) (centre convention, row 0 on top) has the window
// position x_w = u + 1/2, y_w = H - v - 1/2. Solving x_ndc = 2 x_w / W - 1,
// y_ndc = 2 y_w / H - 1 for u = fx X/Z + cx, v = fy Y/Z + cy with eye coordinates
// (x_e, y_e, z_e) = (X, -Y, -Z) and w_clip = -z_e = Z gives the projection matrix
//
//   [ 2 fx / W   0          1 - (2 cx + 1) / W        0                 ]
//   [ 0          2 fy / H   (2 cy + 1) / H - 1        0                 ]
//   [ 0          0          -(f + n) / (f - n)        -2 f n / (f - n)  ]
//   [ 0          0          -1                        0                 ]
//
// (n, f = near, far). Reading the framebuffer bottom row first and flipping it puts
// row 0 on top. The depth buffer holds d = (f / (f - n)) (1 - n / Z) in [0, 1], so
//   Z = f n / (f - d (f - n)).
#pragma once

#include "data/camera_model.hpp"

#include <Eigen/Geometry>

namespace corrmp {

// Projection matrix (column-major, as glLoadMatrixd expects) for the intrinsics.
Eigen::Matrix4d gl_projection_matrix(const CameraIntrinsics& intrinsics);

// Modelview matrix of the world frame: OpenGL eye coordinates from world coordinates.
Eigen::Matrix4d gl_view_matrix(const Eigen::Isometry3d& world_from_camera);

// Metric depth Z (metres along the optical axis) of a window depth value d in [0, 1].
inline double metric_depth_from_window(double d, double near, double far) {
  return far * near / (far - d * (far - near));
}

}  // namespace corrmp
