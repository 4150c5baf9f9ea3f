// Pinhole model of the simulated head camera (the robot observes the table-top scene
// with its head camera, paper Sec. IV-A; the rope experiment reads an RGB-D image,
// Sec. IV-C). The renderer draws exactly this model, so a world point projected here
// lands on the pixel where the renderer draws it, and a pixel with its rendered depth
// back-projects onto the surface that was drawn.
//
// Conventions (OpenCV):
//   camera frame: x right, y down, z forward (the optical axis); the pose
//     world_from_camera maps camera coordinates to world coordinates.
//   pixels: u is the column (to the right), v the row (downwards), row 0 at the top;
//     integer (u, v) is the centre of pixel (column u, row v), so the image spans
//     [-0.5, width - 0.5] x [-0.5, height - 0.5].
//   projection: a camera-frame point (X, Y, Z), Z > 0, is seen at
//     u = fx * X / Z + cx,  v = fy * Y / Z + cy.
//   depth: Z, the distance along the optical axis (not the ray length), in metres.
#pragma once

#include <Eigen/Geometry>

#include <optional>

namespace corrmp {

struct CameraIntrinsics {
  int width = 0;
  int height = 0;
  double fx = 0.0;  // focal lengths in pixels
  double fy = 0.0;
  double cx = 0.0;  // principal point in pixels (pixel-centre convention above)
  double cy = 0.0;
  double near = 0.01;  // clipping planes along z, metres: nothing closer or farther is drawn
  double far = 10.0;

  // Square pixels with the principal point on the image centre, cx = (width - 1) / 2,
  // cy = (height - 1) / 2, and fx = fy = (height / 2) / tan(fov_y / 2), so the top
  // and bottom image edges are fov_y / 2 from the optical axis. fov_y in radians.
  static CameraIntrinsics from_vertical_fov(int width, int height, double fov_y, double near = 0.01,
                                            double far = 10.0);

  // Throws std::invalid_argument naming the first bad field (sizes and focal lengths
  // must be positive, 0 < near < far, all values finite).
  void validate() const;
};

// Camera pose at `eye` looking at `target`, its image "up" (-y) as close to `up` as
// possible: z = normalize(target - eye), x = normalize(z x up), y = z x x.
// Throws std::invalid_argument if eye == target or up is parallel to the view direction.
Eigen::Isometry3d look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                          const Eigen::Vector3d& up);

// Pixel (u, v) where a world point is seen, or nothing if it is not in front of the
// camera (Z <= 0). The pixel may lie outside the image.
std::optional<Eigen::Vector2d> project(const CameraIntrinsics& intrinsics,
                                       const Eigen::Isometry3d& world_from_camera,
                                       const Eigen::Vector3d& point_world);

// World point seen at pixel (u, v) with depth Z (metres along the optical axis):
// X = (u - cx) Z / fx, Y = (v - cy) Z / fy, then mapped by world_from_camera.
Eigen::Vector3d back_project(const CameraIntrinsics& intrinsics,
                             const Eigen::Isometry3d& world_from_camera,
                             const Eigen::Vector2d& pixel, double depth);

}  // namespace corrmp
