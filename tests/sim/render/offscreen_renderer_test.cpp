// Tests of the OSMesa head camera: known scenes give the expected colours where the
// pinhole model says, the expected metric depth, and independent renderers coexist.
#include "sim/render/offscreen_renderer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace corrmp {
namespace {

constexpr double kPi = 3.14159265358979323846;

const Eigen::Vector3f kRed(1.0f, 0.0f, 0.0f);
const Eigen::Vector3f kGreen(0.0f, 1.0f, 0.0f);
const Eigen::Vector3f kBlue(0.0f, 0.0f, 1.0f);
const Eigen::Vector3f kBackground(0.2f, 0.4f, 0.6f);
const cv::Vec3b kRedPixel(255, 0, 0);
const cv::Vec3b kGreenPixel(0, 255, 0);
const cv::Vec3b kBackgroundPixel(51, 102, 153);

RenderOptions unlit() {
  RenderOptions options;
  options.lighting = false;
  return options;
}

Eigen::Isometry3d at(double x, double y, double z) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

RenderScene scene_with(std::vector<RenderItem> items) {
  RenderScene scene;
  scene.items = std::move(items);
  scene.background = kBackground;
  return scene;
}

cv::Vec3b rgb_at(const RgbdImage& image, int u, int v) { return image.rgb.at<cv::Vec3b>(v, u); }
float depth_at(const RgbdImage& image, int u, int v) { return image.depth.at<float>(v, u); }

// Colour of the pixel nearest to a world point, with the point's projection.
cv::Vec3b rgb_where_projected(const RgbdImage& image, const CameraIntrinsics& k,
                              const Eigen::Isometry3d& pose, const Eigen::Vector3d& point) {
  const Eigen::Vector2d pixel = project(k, pose, point).value();
  return rgb_at(image, int(std::lround(pixel.x())), int(std::lround(pixel.y())));
}

TEST(OffscreenRenderer, ReturnsImagesOfTheIntrinsicsSizeAndTypes) {
  const CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(40, 30, 1.0);
  OffscreenRenderer renderer(k);
  const RgbdImage image = renderer.render(scene_with({}), Eigen::Isometry3d::Identity());
  EXPECT_EQ(image.rgb.type(), CV_8UC3);
  EXPECT_EQ(image.depth.type(), CV_32FC1);
  EXPECT_EQ(image.rgb.cols, 40);
  EXPECT_EQ(image.rgb.rows, 30);
  EXPECT_EQ(image.depth.size(), image.rgb.size());
  EXPECT_EQ(cv::countNonZero(image.depth), 0);
  EXPECT_FALSE(renderer.gl_renderer().empty());
}

TEST(OffscreenRenderer, BoxInFrontHasItsColourAndDepthExactlyWherePinholePredicts) {
  const CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(64, 64, kPi / 3.0);
  OffscreenRenderer renderer(k, unlit());
  const RenderScene scene =
      scene_with({{Box{Eigen::Vector3d::Constant(0.1)}, at(0.0, 0.0, 1.0), kRed}});
  const RgbdImage image = renderer.render(scene, Eigen::Isometry3d::Identity());

  EXPECT_EQ(rgb_at(image, 32, 32), kRedPixel);
  EXPECT_NEAR(depth_at(image, 32, 32), 0.9, 1e-3);
  EXPECT_EQ(rgb_at(image, 0, 0), kBackgroundPixel);
  EXPECT_EQ(depth_at(image, 0, 0), 0.0f);

  // The front face covers the pixels whose centre rays meet |X|, |Y| <= 0.1 at Z = 0.9.
  // Pixels a quarter pixel or more from the edge must be classified right; a half-pixel
  // misalignment of the projection would fail here.
  const double margin = 0.25 * 0.9 / k.fx;
  int red_pixels = 0;
  for (int v = 0; v < k.height; ++v) {
    for (int u = 0; u < k.width; ++u) {
      const double x = (u - k.cx) / k.fx * 0.9;
      const double y = (v - k.cy) / k.fy * 0.9;
      const double extent = std::max(std::abs(x), std::abs(y));
      if (extent < 0.1 - margin) {
        ASSERT_EQ(rgb_at(image, u, v), kRedPixel) << "u=" << u << " v=" << v;
        ASSERT_NEAR(depth_at(image, u, v), 0.9, 1e-3) << "u=" << u << " v=" << v;
        ++red_pixels;
      } else if (extent > 0.1 + margin) {
        ASSERT_EQ(rgb_at(image, u, v), kBackgroundPixel) << "u=" << u << " v=" << v;
        ASSERT_EQ(depth_at(image, u, v), 0.0f) << "u=" << u << " v=" << v;
      }
    }
  }
  EXPECT_EQ(red_pixels, 12 * 12);
}

TEST(OffscreenRenderer, LightingKeepsTheHueAndShadesFacesByTheirAngle) {
  const CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(64, 64, kPi / 3.0);
  OffscreenRenderer renderer(k);
  // A box turned 45 degrees about the vertical (y) axis shows two faces at +-45 degrees,
  // and the light comes from the camera: both faces are lit equally, neither fully.
  Eigen::Isometry3d turned = at(0.0, 0.0, 1.0);
  turned.linear() = Eigen::AngleAxisd(kPi / 4.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const RenderScene scene = scene_with({{Box{Eigen::Vector3d::Constant(0.1)}, turned, kRed},
                                        {Sphere{0.1}, at(0.3, 0.0, 1.5), kGreen}});
  const RgbdImage image = renderer.render(scene, Eigen::Isometry3d::Identity());
  const cv::Vec3b left = rgb_at(image, 29, 32);
  const cv::Vec3b right = rgb_at(image, 34, 32);
  for (const cv::Vec3b& pixel : {left, right}) {
    EXPECT_GT(pixel[0], 120);
    EXPECT_LT(pixel[0], 250);
    EXPECT_LT(pixel[1], 10);
    EXPECT_LT(pixel[2], 10);
  }
  EXPECT_NEAR(left[0], right[0], 3);
  const cv::Vec3b sphere =
      rgb_where_projected(image, k, Eigen::Isometry3d::Identity(), Eigen::Vector3d(0.3, 0.0, 1.5));
  EXPECT_GT(sphere[1], 150);
  EXPECT_LT(sphere[0], 10);
  EXPECT_EQ(rgb_at(image, 0, 0), kBackgroundPixel);  // the background is not lit
}

TEST(OffscreenRenderer, SphereAppearsWhereProjectPredicts) {
  const CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(64, 48, kPi / 3.0);
  OffscreenRenderer renderer(k, unlit());
  const Eigen::Vector3d centre(0.3, 0.0, 1.5);
  const RgbdImage image = renderer.render(scene_with({{Sphere{0.1}, at(0.3, 0.0, 1.5), kGreen}}),
                                          Eigen::Isometry3d::Identity());
  const Eigen::Vector2d pixel = project(k, Eigen::Isometry3d::Identity(), centre).value();
  EXPECT_GT(pixel.x(), k.cx + 5.0);  // right of centre
  const int u = int(std::lround(pixel.x()));
  const int v = int(std::lround(pixel.y()));
  EXPECT_EQ(rgb_at(image, u, v), kGreenPixel);
  // The nearest surface point along the ray through the centre, within the 16-segment
  // tessellation's sag of a few millimetres.
  const double z_surface = (centre.norm() - 0.1) * centre.z() / centre.norm();
  EXPECT_NEAR(depth_at(image, u, v), z_surface, 5e-3);
  // Nothing green left of the image centre.
  for (int row = 0; row < k.height; ++row) {
    for (int col = 0; col < k.width / 2; ++col) {
      ASSERT_EQ(rgb_at(image, col, row), kBackgroundPixel) << col << "," << row;
    }
  }
}

TEST(OffscreenRenderer, PositiveYIsDownInTheImage) {
  const CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(48, 48, kPi / 3.0);
  OffscreenRenderer renderer(k, unlit());
  const RgbdImage image =
      renderer.render(scene_with({{Box{Eigen::Vector3d::Constant(0.1)}, at(0.0, 0.3, 1.5), kRed}}),
                      Eigen::Isometry3d::Identity());
  cv::Mat red;
  cv::inRange(image.rgb, cv::Scalar(255, 0, 0), cv::Scalar(255, 0, 0), red);
  ASSERT_GT(cv::countNonZero(red), 20);
  EXPECT_EQ(cv::countNonZero(red.rowRange(0, k.height / 2)), 0);
  EXPECT_EQ(cv::countNonZero(red.colRange(0, 16)), 0);
  EXPECT_EQ(cv::countNonZero(red.colRange(32, 48)), 0);
}

TEST(OffscreenRenderer, TiltedViewDepthBackProjectsOntoTheSurfaces) {
  const CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(96, 72, 1.0, 0.05, 5.0);
  RenderOptions options;
  options.segments = 48;
  OffscreenRenderer renderer(k, options);
  // A table whose top (z = 0.7) reaches under the camera, and a ball lying on it.
  const Eigen::Vector3d ball(0.55, 0.1, 0.76);
  const RenderScene scene =
      scene_with({{Box{Eigen::Vector3d(1.0, 1.0, 0.35)}, at(0.5, 0.0, 0.35), kBlue},
                  {Sphere{0.06}, at(ball.x(), ball.y(), ball.z()), kRed}});
  const Eigen::Isometry3d camera = look_at(
      Eigen::Vector3d(0.0, -0.6, 1.2), Eigen::Vector3d(0.5, 0.0, 0.7), Eigen::Vector3d::UnitZ());
  const RgbdImage image = renderer.render(scene, camera);
  int table_pixels = 0;
  int ball_pixels = 0;
  for (int v = 0; v < k.height; ++v) {
    for (int u = 0; u < k.width; ++u) {
      const float depth = depth_at(image, u, v);
      if (depth == 0.0f) continue;
      const Eigen::Vector3d p = back_project(k, camera, Eigen::Vector2d(u, v), depth);
      const bool red = rgb_at(image, u, v)[0] > rgb_at(image, u, v)[2];
      if (red) {
        EXPECT_NEAR((p - ball).norm(), 0.06, 3e-3) << "u=" << u << " v=" << v;
        ++ball_pixels;
      } else {
        EXPECT_NEAR(p.z(), 0.7, 3e-3) << "u=" << u << " v=" << v;
        ++table_pixels;
      }
    }
  }
  EXPECT_GT(table_pixels, k.width * k.height / 3);
  EXPECT_GT(ball_pixels, 30);
}

TEST(OffscreenRenderer, CylinderAndCapsuleHaveTheirExtent) {
  const CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(64, 64, kPi / 3.0);
  OffscreenRenderer renderer(k, unlit());
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  // Cylinder along the optical axis: the near cap at Z = 0.9.
  const RgbdImage cylinder =
      renderer.render(scene_with({{Cylinder{0.1, 0.1}, at(0.0, 0.0, 1.0), kRed}}), identity);
  EXPECT_NEAR(depth_at(cylinder, 32, 32), 0.9, 1e-3);
  // Capsule lying along x: body from x = -0.1 to 0.1, caps reaching to +-0.15.
  Eigen::Isometry3d along_x = at(0.0, 0.0, 1.0);
  along_x.linear() = Eigen::AngleAxisd(kPi / 2.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const RgbdImage capsule =
      renderer.render(scene_with({{Capsule{0.05, 0.1}, along_x, kGreen}}), identity);
  const Eigen::Vector3d inside_cap(0.12, 0.0, 1.0);
  const Eigen::Vector3d beyond_cap(0.18, 0.0, 1.0);
  EXPECT_EQ(rgb_where_projected(capsule, k, identity, inside_cap), kGreenPixel);
  EXPECT_EQ(rgb_where_projected(capsule, k, identity, beyond_cap), kBackgroundPixel);
  EXPECT_NEAR(depth_at(capsule, 32, 32), 0.95, 2e-3);
}

TEST(OffscreenRenderer, NearerItemsHideFartherOnesWhateverTheDrawingOrder) {
  const CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(32, 32, kPi / 3.0);
  OffscreenRenderer renderer(k, unlit());
  const RenderItem near_box{Box{Eigen::Vector3d::Constant(0.05)}, at(0.0, 0.0, 0.8), kRed};
  const RenderItem far_box{Box{Eigen::Vector3d::Constant(0.8)}, at(0.0, 0.0, 2.0), kGreen};
  for (const auto& items :
       {std::vector<RenderItem>{near_box, far_box}, std::vector<RenderItem>{far_box, near_box}}) {
    const RgbdImage image = renderer.render(scene_with(items), Eigen::Isometry3d::Identity());
    EXPECT_EQ(rgb_at(image, 16, 16), kRedPixel);
    EXPECT_NEAR(depth_at(image, 16, 16), 0.75, 1e-3);
    EXPECT_EQ(rgb_at(image, 16, 4), kGreenPixel);
    EXPECT_NEAR(depth_at(image, 16, 4), 1.2, 1e-3);
  }
}

TEST(OffscreenRenderer, ItemsOutsideTheClippingRangeAreNotDrawn) {
  CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(32, 32, kPi / 3.0, 0.1, 2.0);
  OffscreenRenderer renderer(k, unlit());
  const RgbdImage image =
      renderer.render(scene_with({{Box{Eigen::Vector3d::Constant(0.1)}, at(0.0, 0.0, 3.0), kRed},
                                  {Box{Eigen::Vector3d::Constant(0.1)}, at(0.0, 0.0, -1.0), kRed}}),
                      Eigen::Isometry3d::Identity());
  EXPECT_EQ(cv::countNonZero(image.depth), 0);
  EXPECT_EQ(rgb_at(image, 16, 16), kBackgroundPixel);
}

TEST(OffscreenRenderer, RenderersOfDifferentSizesCoexist) {
  const CameraIntrinsics small = CameraIntrinsics::from_vertical_fov(32, 24, kPi / 3.0);
  const CameraIntrinsics large = CameraIntrinsics::from_vertical_fov(80, 60, kPi / 3.0);
  const RenderScene scene =
      scene_with({{Box{Eigen::Vector3d::Constant(0.1)}, at(0.0, 0.0, 1.0), kRed},
                  {Sphere{0.1}, at(0.3, 0.0, 1.5), kGreen}});
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();

  OffscreenRenderer first(small, unlit());
  const RgbdImage small_alone = first.render(scene, identity);
  OffscreenRenderer second(large, unlit());
  const RgbdImage large_image = second.render(scene, identity);
  const RgbdImage small_again = first.render(scene, identity);

  EXPECT_EQ(large_image.rgb.size(), cv::Size(80, 60));
  EXPECT_EQ(small_again.rgb.size(), cv::Size(32, 24));
  EXPECT_EQ(cv::norm(small_alone.rgb, small_again.rgb, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(small_alone.depth, small_again.depth, cv::NORM_INF), 0.0);
  for (const auto& [image, k] : {std::pair{&small_again, small}, std::pair{&large_image, large}}) {
    EXPECT_EQ(rgb_where_projected(*image, k, identity, Eigen::Vector3d(0.0, 0.0, 0.9)), kRedPixel);
    EXPECT_EQ(rgb_where_projected(*image, k, identity, Eigen::Vector3d(0.3, 0.0, 1.4)),
              kGreenPixel);
  }
  {
    OffscreenRenderer short_lived(small, unlit());
    short_lived.render(scene, identity);
  }
  const RgbdImage large_again = second.render(scene, identity);
  EXPECT_EQ(cv::norm(large_image.rgb, large_again.rgb, cv::NORM_INF), 0.0);
}

TEST(OffscreenRenderer, MovedRendererKeepsWorking) {
  const CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(32, 32, kPi / 3.0);
  OffscreenRenderer original(k, unlit());
  OffscreenRenderer moved(std::move(original));
  const RgbdImage image =
      moved.render(scene_with({{Box{Eigen::Vector3d::Constant(0.1)}, at(0.0, 0.0, 1.0), kRed}}),
                   Eigen::Isometry3d::Identity());
  EXPECT_EQ(rgb_at(image, 16, 16), kRedPixel);
}

TEST(OffscreenRenderer, RejectsBadConfigurationAndBadItems) {
  CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(32, 32, 1.0);
  RenderOptions options;
  options.segments = 2;
  EXPECT_THROW(OffscreenRenderer(k, options), std::invalid_argument);
  options = RenderOptions();
  options.direction_to_light = Eigen::Vector3f::Zero();
  EXPECT_THROW(OffscreenRenderer(k, options), std::invalid_argument);
  CameraIntrinsics bad = k;
  bad.height = -1;
  EXPECT_THROW(OffscreenRenderer{bad}, std::invalid_argument);
  CameraIntrinsics huge = k;
  huge.width = 1 << 20;
  huge.height = 1;
  EXPECT_THROW(OffscreenRenderer{huge}, std::runtime_error);

  OffscreenRenderer renderer(k);
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  EXPECT_THROW(renderer.render(scene_with({{Sphere{-0.1}, at(0, 0, 1), kRed}}), identity),
               std::invalid_argument);
  EXPECT_THROW(
      renderer.render(scene_with({{Box{Eigen::Vector3d(0.1, 0.0, 0.1)}, at(0, 0, 1), kRed}}),
                      identity),
      std::invalid_argument);
  EXPECT_THROW(renderer.render(scene_with({{Cylinder{0.1, NAN}, at(0, 0, 1), kRed}}), identity),
               std::invalid_argument);
  // A capsule of zero body length is a sphere (16-segment tessellation: within 6 mm).
  const RgbdImage ball =
      renderer.render(scene_with({{Capsule{0.1, 0.0}, at(0, 0, 1), kRed}}), identity);
  EXPECT_NEAR(ball.depth.at<float>(16, 16), 0.9, 6e-3);
}

}  // namespace
}  // namespace corrmp
