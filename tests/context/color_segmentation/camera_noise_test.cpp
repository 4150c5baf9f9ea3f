// Tests of the simulated camera noise for the rope-end segmentation (paper, Section IV-C):
// the requested spread, "no depth" kept, determinism per seed, zero std a no-op.
#include "context/color_segmentation/camera_noise.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace corrmp {
namespace {

struct Images {
  cv::Mat rgb = cv::Mat(60, 80, CV_8UC3, cv::Scalar(120, 60, 200));
  cv::Mat depth = cv::Mat(60, 80, CV_32FC1, cv::Scalar(0.5f));
  Images() { depth(cv::Rect(0, 0, 80, 20)).setTo(0.0f); }  // top third: nothing hit
};

ColorSegmentationParams noisy(double rgb_std, double depth_std) {
  ColorSegmentationParams params;
  params.rgb_noise_std = rgb_std;
  params.depth_noise_std = depth_std;
  return params;
}

TEST(CameraNoise, HasTheRequestedSpreadAndKeepsNoDepth) {
  Images images;
  Rng rng(1);
  add_camera_noise(images.rgb, images.depth, noisy(5.0, 0.002), rng);
  cv::Mat rgb_diff;
  images.rgb.convertTo(rgb_diff, CV_64FC3);
  rgb_diff -= cv::Scalar(120, 60, 200);
  cv::Scalar mean, std;
  cv::meanStdDev(rgb_diff.reshape(1), mean, std);
  EXPECT_NEAR(mean[0], 0.0, 0.1);
  EXPECT_NEAR(std[0], 5.0, 0.2);
  EXPECT_EQ(cv::countNonZero(images.depth(cv::Rect(0, 0, 80, 20))), 0);
  cv::meanStdDev(images.depth(cv::Rect(0, 20, 80, 40)), mean, std);
  EXPECT_NEAR(mean[0], 0.5, 2e-4);
  EXPECT_NEAR(std[0], 0.002, 2e-4);
}

TEST(CameraNoise, SameSeedSameImagesAndZeroStdUntouched) {
  Images a, b, c;
  Rng rng_a(42), rng_b(42), rng_c(42);
  add_camera_noise(a.rgb, a.depth, noisy(3.0, 0.001), rng_a);
  add_camera_noise(b.rgb, b.depth, noisy(3.0, 0.001), rng_b);
  EXPECT_EQ(cv::norm(a.rgb, b.rgb, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a.depth, b.depth, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a.rgb, c.rgb, cv::NORM_INF), 0.0);

  add_camera_noise(c.rgb, c.depth, noisy(0.0, 0.0), rng_c);
  const Images clean;
  EXPECT_EQ(cv::norm(c.rgb, clean.rgb, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(c.depth, clean.depth, cv::NORM_INF), 0.0);
  Rng fresh(42);
  EXPECT_EQ(rng_c(), fresh());  // nothing was drawn
}

TEST(CameraNoise, RejectsWrongImages) {
  Images images;
  Rng rng(1);
  cv::Mat grey(60, 80, CV_8UC1);
  EXPECT_THROW(add_camera_noise(grey, images.depth, noisy(1.0, 0.0), rng), std::invalid_argument);
  cv::Mat small(10, 10, CV_32FC1);
  EXPECT_THROW(add_camera_noise(images.rgb, small, noisy(1.0, 0.0), rng), std::invalid_argument);
  EXPECT_THROW(add_camera_noise(images.rgb, images.depth, noisy(-1.0, 0.0), rng),
               std::invalid_argument);
}

}  // namespace
}  // namespace corrmp
