// Tests of PNG export: colour in the right channel order, depth in millimetres, and
// clear errors for unwritable files.
#include "sim/render/rgbd_png.hpp"

#include "sim/render/offscreen_renderer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <stdexcept>
#include <string>

namespace corrmp {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

std::string temp_path(const std::string& name) {
  return ::testing::TempDir() + "corrmp_render_" + name;
}

TEST(WritePng, RenderedImageReadsBackWithColourAndMillimetreDepth) {
  const CameraIntrinsics k = CameraIntrinsics::from_vertical_fov(48, 32, 1.0);
  RenderOptions options;
  options.lighting = false;
  OffscreenRenderer renderer(k, options);
  RenderScene scene;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.0, 0.0, 1.0);
  scene.items.push_back(
      {Box{Eigen::Vector3d::Constant(0.1)}, pose, Eigen::Vector3f(1.0f, 0.0f, 0.0f)});
  scene.background = Eigen::Vector3f(0.0f, 0.0f, 1.0f);
  const RgbdImage image = renderer.render(scene, Eigen::Isometry3d::Identity());

  const std::string rgb_path = temp_path("rgb.png");
  const std::string depth_path = temp_path("depth.png");
  write_png(image, rgb_path, depth_path);

  const cv::Mat bgr = cv::imread(rgb_path, cv::IMREAD_UNCHANGED);
  ASSERT_EQ(bgr.type(), CV_8UC3);
  ASSERT_EQ(bgr.size(), image.rgb.size());
  EXPECT_EQ(bgr.at<cv::Vec3b>(16, 24), cv::Vec3b(0, 0, 255));  // red box, BGR on disk
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 0), cv::Vec3b(255, 0, 0));    // blue background

  const cv::Mat millimetres = cv::imread(depth_path, cv::IMREAD_UNCHANGED);
  ASSERT_EQ(millimetres.type(), CV_16UC1);
  EXPECT_EQ(millimetres.at<uint16_t>(16, 24), 900);
  EXPECT_EQ(millimetres.at<uint16_t>(0, 0), 0);
}

TEST(WritePng, DepthIsOptionalAndClampedToSixteenBits) {
  RgbdImage image;
  image.rgb = cv::Mat(2, 2, CV_8UC3, cv::Scalar(10, 20, 30));
  image.depth = cv::Mat(2, 2, CV_32FC1, cv::Scalar(70.0));
  const std::string rgb_path = temp_path("only_rgb.png");
  write_png(image, rgb_path);
  EXPECT_EQ(cv::imread(rgb_path).at<cv::Vec3b>(0, 0), cv::Vec3b(30, 20, 10));
  const std::string depth_path = temp_path("far_depth.png");
  write_png(image, rgb_path, depth_path);
  EXPECT_EQ(cv::imread(depth_path, cv::IMREAD_UNCHANGED).at<uint16_t>(1, 1), 65535);
}

TEST(WritePng, FailsClearly) {
  RgbdImage image;
  EXPECT_THROW(write_png(image, temp_path("empty.png")), std::runtime_error);
  image.rgb = cv::Mat(2, 2, CV_8UC3, cv::Scalar::all(0));
  EXPECT_THAT([&] { write_png(image, "/nonexistent-dir/x.png"); },
              ThrowsMessage<std::runtime_error>(HasSubstr("/nonexistent-dir/x.png")));
  EXPECT_THROW(write_png(image, temp_path("rgb_ok.png"), temp_path("no_depth.png")),
               std::runtime_error);
}

}  // namespace
}  // namespace corrmp
