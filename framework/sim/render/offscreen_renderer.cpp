// OSMesa off-screen rendering of RenderScenes into RGB-D images (see
// offscreen_renderer.hpp; matrices and depth conversion in gl_projection.hpp).
#include "sim/render/offscreen_renderer.hpp"

#include "sim/render/gl_projection.hpp"
#include "sim/render/unit_meshes.hpp"

#include <GL/osmesa.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace corrmp {
namespace {

// Display lists of the unit meshes, in this order from the first list name.
enum MeshList : GLuint {
  kBoxList,
  kCylinderList,
  kTubeList,
  kSphereList,
  kHemisphereList,
  kListCount
};

void check_size(double value, bool allow_zero, const char* what, size_t item) {
  if (!std::isfinite(value) || value < 0.0 || (value == 0.0 && !allow_zero)) {
    throw std::invalid_argument(
        fmt::format("OffscreenRenderer::render: item {}: {} must be {}, got {}", item, what,
                    allow_zero ? "finite and non-negative" : "finite and positive", value));
  }
}

Eigen::Matrix4d scaling(double sx, double sy, double sz) {
  return Eigen::Vector4d(sx, sy, sz, 1.0).asDiagonal();
}

Eigen::Matrix4d translation_z(double z) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(2, 3) = z;
  return m;
}

void compile_list(GLuint list, const TriangleMesh& mesh) {
  glNewList(list, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    glNormal3fv(mesh.normals[i].data());
    glVertex3fv(mesh.positions[i].data());
  }
  glEnd();
  glEndList();
}

}  // namespace

void RenderOptions::validate() const {
  if (segments < 3) {
    throw std::invalid_argument(
        fmt::format("render options: segments must be at least 3, got {}", segments));
  }
  if (!(ambient >= 0.0f && ambient <= 1.0f)) {
    throw std::invalid_argument(
        fmt::format("render options: ambient must be in [0, 1], got {}", ambient));
  }
  if (!(diffuse >= 0.0f && diffuse <= 1.0f)) {
    throw std::invalid_argument(
        fmt::format("render options: diffuse must be in [0, 1], got {}", diffuse));
  }
  if (!(direction_to_light.allFinite() && direction_to_light.norm() > 0.0f)) {
    throw std::invalid_argument("render options: direction_to_light must be finite and non-zero");
  }
}

struct OffscreenRenderer::Context {
  CameraIntrinsics intrinsics;
  RenderOptions options;
  std::string gl_renderer;
  OSMesaContext osmesa = nullptr;
  std::vector<GLubyte> framebuffer;  // RGBA, OSMesa's colour buffer
  GLuint first_list = 0;
  cv::Mat rgb_bottom_up;                // CV_8UC3 read-back, row 0 at the bottom
  std::vector<GLuint> depth_bottom_up;  // window depth scaled to [0, 2^32 - 1]

  ~Context() {
    if (osmesa != nullptr) OSMesaDestroyContext(osmesa);
  }

  void make_current() {
    if (!OSMesaMakeCurrent(osmesa, framebuffer.data(), GL_UNSIGNED_BYTE, intrinsics.width,
                           intrinsics.height)) {
      throw std::runtime_error(fmt::format("OffscreenRenderer: OSMesaMakeCurrent failed for {}x{}",
                                           intrinsics.width, intrinsics.height));
    }
  }

  void check_gl(const char* where) const {
    const GLenum error = glGetError();
    if (error != GL_NO_ERROR) {
      throw std::runtime_error(
          fmt::format("OffscreenRenderer: OpenGL error 0x{:04x} {}", error, where));
    }
  }

  void set_up_gl_state() {
    GLint max_width = 0;
    GLint max_height = 0;
    OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &max_width);
    OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &max_height);
    if (intrinsics.width > max_width || intrinsics.height > max_height) {
      throw std::runtime_error(
          fmt::format("OffscreenRenderer: {}x{} exceeds OSMesa's maximum {}x{}", intrinsics.width,
                      intrinsics.height, max_width, max_height));
    }
    GLint depth_bits = 0;
    glGetIntegerv(GL_DEPTH_BITS, &depth_bits);
    if (depth_bits < 24) {
      throw std::runtime_error(
          fmt::format("OffscreenRenderer: got a {}-bit depth buffer, need 24", depth_bits));
    }
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    gl_renderer = name != nullptr ? name : "unknown";

    glViewport(0, 0, intrinsics.width, intrinsics.height);
    glMatrixMode(GL_PROJECTION);
    const Eigen::Matrix4d projection = gl_projection_matrix(intrinsics);
    glLoadMatrixd(projection.data());
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    glEnable(GL_CULL_FACE);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_NORMALIZE);  // the unit meshes are scaled non-uniformly
    glDisable(GL_DITHER);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);

    if (options.lighting) {
      const GLfloat ambient[] = {options.ambient, options.ambient, options.ambient, 1.0f};
      const GLfloat diffuse[] = {options.diffuse, options.diffuse, options.diffuse, 1.0f};
      const GLfloat black[] = {0.0f, 0.0f, 0.0f, 1.0f};
      // With the identity modelview, GL_POSITION is taken in eye coordinates: the
      // light stays fixed to the camera. Eye frame = camera frame with y, z negated.
      const Eigen::Vector3f d = options.direction_to_light.normalized();
      const GLfloat position[] = {d.x(), -d.y(), -d.z(), 0.0f};
      glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
      glLightfv(GL_LIGHT0, GL_AMBIENT, black);
      glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
      glLightfv(GL_LIGHT0, GL_SPECULAR, black);
      glLightfv(GL_LIGHT0, GL_POSITION, position);
      glEnable(GL_LIGHT0);
      glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
      glEnable(GL_COLOR_MATERIAL);
      glEnable(GL_LIGHTING);
    } else {
      glDisable(GL_LIGHTING);
    }

    first_list = glGenLists(kListCount);
    if (first_list == 0) throw std::runtime_error("OffscreenRenderer: glGenLists failed");
    compile_list(first_list + kBoxList, unit_box_mesh());
    compile_list(first_list + kCylinderList, unit_cylinder_mesh(options.segments));
    compile_list(first_list + kTubeList, unit_tube_mesh(options.segments));
    compile_list(first_list + kSphereList, unit_sphere_mesh(options.segments));
    compile_list(first_list + kHemisphereList, unit_hemisphere_mesh(options.segments));
    check_gl("while setting up the context");
  }

  void draw(const Eigen::Matrix4d& modelview, MeshList list) const {
    glLoadMatrixd(modelview.data());
    glCallList(first_list + list);
  }

  void draw_item(const RenderItem& item, const Eigen::Matrix4d& view, size_t index) const {
    const Eigen::Matrix4d placed = view * item.pose.matrix();
    glColor3f(item.colour.x(), item.colour.y(), item.colour.z());
    std::visit(
        [&](const auto& shape) {
          using Shape = std::decay_t<decltype(shape)>;
          if constexpr (std::is_same_v<Shape, Box>) {
            const Eigen::Vector3d& e = shape.half_extents;
            for (int i = 0; i < 3; ++i) check_size(e[i], false, "box half extent", index);
            draw(placed * scaling(e.x(), e.y(), e.z()), kBoxList);
          } else if constexpr (std::is_same_v<Shape, Cylinder>) {
            check_size(shape.radius, false, "cylinder radius", index);
            check_size(shape.half_height, false, "cylinder half height", index);
            draw(placed * scaling(shape.radius, shape.radius, shape.half_height), kCylinderList);
          } else if constexpr (std::is_same_v<Shape, Capsule>) {
            const double r = shape.radius;
            const double h = shape.half_height;
            check_size(r, false, "capsule radius", index);
            check_size(h, true, "capsule half height", index);
            if (h > 0.0) draw(placed * scaling(r, r, h), kTubeList);
            draw(placed * translation_z(h) * scaling(r, r, r), kHemisphereList);
            draw(placed * translation_z(-h) * scaling(r, -r, -r), kHemisphereList);
          } else {
            check_size(shape.radius, false, "sphere radius", index);
            draw(placed * scaling(shape.radius, shape.radius, shape.radius), kSphereList);
          }
        },
        item.shape);
  }
};

OffscreenRenderer::OffscreenRenderer(const CameraIntrinsics& intrinsics,
                                     const RenderOptions& options)
    : context_(std::make_unique<Context>()) {
  intrinsics.validate();
  options.validate();
  context_->intrinsics = intrinsics;
  context_->options = options;
  context_->osmesa = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (context_->osmesa == nullptr) {
    throw std::runtime_error(
        "OffscreenRenderer: OSMesaCreateContextExt(OSMESA_RGBA, 24-bit depth) failed");
  }
  context_->framebuffer.assign(size_t(4) * intrinsics.width * intrinsics.height, 0);
  context_->rgb_bottom_up.create(intrinsics.height, intrinsics.width, CV_8UC3);
  context_->depth_bottom_up.resize(size_t(intrinsics.width) * intrinsics.height);
  context_->make_current();
  context_->set_up_gl_state();
}

OffscreenRenderer::~OffscreenRenderer() = default;
OffscreenRenderer::OffscreenRenderer(OffscreenRenderer&&) noexcept = default;
OffscreenRenderer& OffscreenRenderer::operator=(OffscreenRenderer&&) noexcept = default;

RgbdImage OffscreenRenderer::render(const RenderScene& scene,
                                    const Eigen::Isometry3d& world_from_camera) {
  Context& c = *context_;
  c.make_current();
  const int width = c.intrinsics.width;
  const int height = c.intrinsics.height;

  glClearColor(scene.background.x(), scene.background.y(), scene.background.z(), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const Eigen::Matrix4d view = gl_view_matrix(world_from_camera);
  for (size_t i = 0; i < scene.items.size(); ++i) c.draw_item(scene.items[i], view, i);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, c.rgb_bottom_up.data);
  glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, c.depth_bottom_up.data());
  c.check_gl("while rendering");

  RgbdImage image;
  cv::flip(c.rgb_bottom_up, image.rgb, 0);
  image.depth.create(height, width, CV_32FC1);
  const double near = c.intrinsics.near;
  const double far = c.intrinsics.far;
  constexpr double kDepthScale = 1.0 / 4294967295.0;
  for (int row = 0; row < height; ++row) {
    const GLuint* source = c.depth_bottom_up.data() + size_t(height - 1 - row) * width;
    auto* target = image.depth.ptr<float>(row);
    for (int col = 0; col < width; ++col) {
      // The cleared buffer holds exactly 1.0, the largest value.
      target[col] = source[col] == 0xffffffffu
                        ? 0.0f
                        : float(metric_depth_from_window(source[col] * kDepthScale, near, far));
    }
  }
  return image;
}

const CameraIntrinsics& OffscreenRenderer::intrinsics() const { return context_->intrinsics; }
const RenderOptions& OffscreenRenderer::options() const { return context_->options; }
const std::string& OffscreenRenderer::gl_renderer() const { return context_->gl_renderer; }

}  // namespace corrmp
