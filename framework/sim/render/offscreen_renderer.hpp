// Off-screen RGB-D camera: draws a RenderScene with Mesa's OSMesa (software OpenGL, no
// display needed) as seen by the pinhole camera of camera_model.hpp and returns the
// colour image and the metric depth image. This is the robot's head camera in
// simulation (paper Sec. IV-A: camera images feed the "Learning the Context"
// autoencoder of Sec. III-B; Sec. IV-C: the rope end is segmented from an RGB-D image).
//
// Drawing is fixed-function OpenGL: ambient light plus one directional light fixed to
// the camera, Lambertian colours, smooth normals on curved surfaces, back faces culled.
// Each renderer owns its OpenGL context and makes it current at every render() call,
// so several renderers (of different sizes) can be used in turn from one thread. One
// renderer must not be used by two threads at once.
#pragma once

#include "data/camera_model.hpp"
#include "sim/render/render_scene.hpp"
#include "sim/render/rgbd_image.hpp"

#include <Eigen/Geometry>

#include <memory>
#include <string>

namespace corrmp {

struct RenderOptions {
  // Sides of the tessellated cylinders, capsules and spheres (at least 3).
  int segments = 16;
  // false: every pixel of an item gets exactly the item's colour (no shading).
  bool lighting = true;
  // Shaded colour = colour * min(1, ambient + diffuse * max(0, normal . to_light)).
  float ambient = 0.35f;
  float diffuse = 0.65f;
  // Direction towards the light in the camera frame (x right, y down, z forward);
  // the default lights the scene from the camera, a little from above.
  Eigen::Vector3f direction_to_light = Eigen::Vector3f(0.0f, -0.5f, -1.0f);

  // Throws std::invalid_argument naming the first bad field.
  void validate() const;
};

class OffscreenRenderer {
 public:
  // Creates the OSMesa context (RGBA, 24-bit depth) of the intrinsics' size and
  // tessellates the unit meshes. Throws std::invalid_argument for bad intrinsics or
  // options, std::runtime_error if the context cannot be created or is too small.
  explicit OffscreenRenderer(const CameraIntrinsics& intrinsics,
                             const RenderOptions& options = RenderOptions());
  ~OffscreenRenderer();
  // A moved-from renderer may only be destroyed or assigned to.
  OffscreenRenderer(OffscreenRenderer&&) noexcept;
  OffscreenRenderer& operator=(OffscreenRenderer&&) noexcept;
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  // Draws the scene seen from world_from_camera (OpenCV camera frame) and reads the
  // picture back: rgb CV_8UC3 in R, G, B order, depth CV_32FC1 metres along the
  // optical axis, 0 where nothing was hit; row 0 on top. Both images are newly
  // allocated. Throws std::invalid_argument for a primitive with a non-positive or
  // non-finite size, std::runtime_error if OpenGL reports an error.
  RgbdImage render(const RenderScene& scene, const Eigen::Isometry3d& world_from_camera);

  const CameraIntrinsics& intrinsics() const;
  const RenderOptions& options() const;
  // OpenGL's GL_RENDERER string, for example "llvmpipe (LLVM 15.0.6, 256 bits)".
  const std::string& gl_renderer() const;

 private:
  struct Context;
  std::unique_ptr<Context> context_;
};

}  // namespace corrmp
