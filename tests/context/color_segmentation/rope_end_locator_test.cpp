// Tests of the rope-end locator (paper, Section IV-C): rendered head-camera scenes with a
// red rope end at known places give its centre-line centroid within a few millimetres, also
// with camera noise; distractor colours and scenes without red give nothing.
#include "context/color_segmentation/rope_end_locator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "context/color_segmentation/camera_noise.hpp"
#include "rope_scene.hpp"
#include "sim/render/offscreen_renderer.hpp"

namespace corrmp {
namespace {

using test::head_camera_intrinsics;
using test::head_camera_pose;

constexpr double kPi = 3.14159265358979323846;
constexpr int kPlacements = 12;
// The located point is the centroid of the visible red surface, which reaches one rope radius
// past the last node (the end cap): that biases it by about half a radius towards the free
// end, more when the end points at the camera. Across the rope axis it is much closer.
constexpr double kToleranceM = 0.006;
constexpr double kMedianToleranceM = 0.004;
constexpr double kAcrossAxisToleranceM = 0.0025;
constexpr double kNoisyToleranceM = 0.0065;

// Default thresholds with the seen surface pushed back by the mean depth of a tube's
// visible half (pi/4 of the radius).
ColorSegmentationParams rope_end_params() {
  ColorSegmentationParams params;
  params.surface_offset = kPi / 4.0 * test::kRopeRadius;
  return params;
}

class RopeEndLocator : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { renderer_ = new OffscreenRenderer(head_camera_intrinsics()); }
  static void TearDownTestSuite() {
    delete renderer_;
    renderer_ = nullptr;
  }

  RgbdImage render(const RenderScene& scene) {
    return renderer_->render(scene, head_camera_pose());
  }

  std::optional<LocatedBlob> locate(const RgbdImage& image, const ColorSegmentationParams& params) {
    return locate_colour_blob(image.rgb, image.depth, head_camera_intrinsics(), head_camera_pose(),
                              params);
  }

  struct Errors {
    std::vector<double> total;        // |located - centroid of the red nodes| (m)
    std::vector<double> across_axis;  // its part perpendicular to the red end's axis (m)
  };

  // Errors of the located end over kPlacements random placements; fails if one is missed.
  Errors placement_errors(const ColorSegmentationParams& params, uint64_t seed) {
    Rng placement_rng(seed);
    Rng noise_rng(seed + 1);
    Errors errors;
    for (int i = 0; i < kPlacements; ++i) {
      const test::RopePlacement rope = test::random_rope(placement_rng);
      RgbdImage image = render(test::rope_scene(rope));
      add_camera_noise(image.rgb, image.depth, params, noise_rng);
      const std::optional<LocatedBlob> blob = locate(image, params);
      EXPECT_TRUE(blob.has_value()) << "placement " << i;
      if (!blob) continue;
      const Eigen::Vector3d error = blob->position_world - rope.red_centroid;
      const Eigen::Vector3d axis =
          (rope.nodes[rope.nodes.size() - test::kRedNodes] - rope.nodes.back()).normalized();
      errors.total.push_back(error.norm());
      errors.across_axis.push_back((error - error.dot(axis) * axis).norm());
    }
    return errors;
  }

  static double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.at(values.size() / 2);
  }
  static double largest(const std::vector<double>& values) {
    return *std::max_element(values.begin(), values.end());
  }

  static void report(const char* what, const Errors& errors) {
    std::cout << what << ": error median " << median(errors.total) * 1e3 << " mm, max "
              << largest(errors.total) * 1e3 << " mm; across the axis median "
              << median(errors.across_axis) * 1e3 << " mm, max "
              << largest(errors.across_axis) * 1e3 << " mm (" << errors.total.size()
              << " placements)\n";
  }

  static OffscreenRenderer* renderer_;
};

OffscreenRenderer* RopeEndLocator::renderer_ = nullptr;

TEST_F(RopeEndLocator, FindsTheRedEndWithinAFewMillimetresOverRandomPlacements) {
  const Errors errors = placement_errors(rope_end_params(), 11);
  ASSERT_EQ(errors.total.size(), size_t(kPlacements));
  for (double error : errors.total) EXPECT_LT(error, kToleranceM);
  for (double error : errors.across_axis) EXPECT_LT(error, kAcrossAxisToleranceM);
  EXPECT_LT(median(errors.total), kMedianToleranceM);
  report("noise-free", errors);
}

TEST_F(RopeEndLocator, StillWithinToleranceWithSmallCameraNoise) {
  ColorSegmentationParams params = rope_end_params();
  params.rgb_noise_std = 6.0;
  params.depth_noise_std = 0.002;
  const Errors errors = placement_errors(params, 23);
  ASSERT_EQ(errors.total.size(), size_t(kPlacements));
  for (double error : errors.total) EXPECT_LT(error, kNoisyToleranceM);
  EXPECT_LT(median(errors.total), kMedianToleranceM);
  report("noisy (rgb 6, depth 2 mm)", errors);
}

TEST_F(RopeEndLocator, SurfaceOffsetMovesThePointAlongTheViewingRay) {
  const test::RopePlacement rope =
      test::rope_with_end_at({-0.04, 0.0, 0.2}, Eigen::Vector3d(0.0, 1.0, 0.3));
  const RgbdImage image = render(test::rope_scene(rope));
  ColorSegmentationParams params;
  const Eigen::Vector3d seen = locate(image, params).value().position_world;
  params.surface_offset = 0.01;
  const Eigen::Vector3d pushed = locate(image, params).value().position_world;
  const Eigen::Vector3d ray = (seen - head_camera_pose().translation()).normalized();
  EXPECT_NEAR((pushed - seen).norm(), 0.01, 1e-9);
  EXPECT_NEAR((pushed - seen).normalized().dot(ray), 1.0, 1e-9);
}

TEST_F(RopeEndLocator, NothingWithoutRedInView) {
  Rng rng(5);
  const test::RopePlacement rope = test::random_rope(rng);
  EXPECT_FALSE(locate(render(test::rope_scene(rope, {false, true})), rope_end_params()));
  // The red end far outside the image.
  const test::RopePlacement outside =
      test::rope_with_end_at({0.0, 2.0, 0.2}, Eigen::Vector3d(0.0, 1.0, 0.0));
  EXPECT_FALSE(locate(render(test::rope_scene(outside)), rope_end_params()));
}

TEST_F(RopeEndLocator, DistractorsAreInViewAndLargerButNotTaken) {
  Rng rng(7);
  const test::RopePlacement rope = test::random_rope(rng);
  const RgbdImage image = render(test::rope_scene(rope, {false, true}));
  // A wide, pale window does take the orange or pink box, which are larger than the red end:
  // the default thresholds are what keeps them out.
  ColorSegmentationParams wide = rope_end_params();
  wide.hue_half_width = 40.0;
  wide.saturation_min = 0.2;
  const std::optional<LocatedBlob> wrong = locate(image, wide);
  ASSERT_TRUE(wrong.has_value());
  EXPECT_GT(wrong->pixel_count, 300);
  EXPECT_EQ(cv::countNonZero(colour_mask(image.rgb, rope_end_params())), 0);
}

TEST_F(RopeEndLocator, MaskCoversTheRenderedRedPixels) {
  RenderOptions unlit;
  unlit.lighting = false;
  OffscreenRenderer flat(head_camera_intrinsics(), unlit);
  Rng rng(3);
  for (int i = 0; i < 4; ++i) {
    const test::RopePlacement rope = test::random_rope(rng);
    const RenderScene scene = test::rope_scene(rope);
    const RgbdImage image = render(scene);
    // Every pixel where the red end was drawn, found by rendering it alone as exactly red.
    RenderScene red_only = scene;
    for (RenderItem& item : red_only.items) {
      const bool red = item.colour == test::kRopeEndRed;
      item.colour = red ? Eigen::Vector3f(1.0f, 0.0f, 0.0f) : Eigen::Vector3f::Zero();
    }
    const RgbdImage truth_image = flat.render(red_only, head_camera_pose());
    cv::Mat truth;
    cv::inRange(truth_image.rgb, cv::Scalar(255, 0, 0), cv::Scalar(255, 0, 0), truth);

    const LocatedBlob blob = locate(image, rope_end_params()).value();
    ASSERT_EQ(blob.mask.type(), CV_8UC1);
    ASSERT_EQ(blob.mask.size(), image.rgb.size());
    EXPECT_EQ(cv::countNonZero(blob.mask), blob.pixel_count);
    const int overlap = cv::countNonZero(blob.mask & truth);
    const int either = cv::countNonZero(blob.mask | truth);
    EXPECT_GT(double(overlap) / either, 0.85) << "placement " << i;
    EXPECT_NEAR(blob.pixel_count, cv::countNonZero(truth), 0.15 * cv::countNonZero(truth));
    EXPECT_GE(blob.depth_pixel_count, blob.pixel_count * 9 / 10);
  }
}

TEST_F(RopeEndLocator, TakesTheLargestClusterAndHonoursTheMinimumArea) {
  const test::RopePlacement rope =
      test::rope_with_end_at({-0.04, 0.05, 0.2}, Eigen::Vector3d(0.0, 1.0, 0.5));
  RenderScene scene = test::rope_scene(rope);
  Eigen::Isometry3d bead = Eigen::Isometry3d::Identity();
  bead.translation() = Eigen::Vector3d(-0.04, -0.1, 0.2);
  scene.items.push_back({Sphere{0.004}, bead, test::kRopeEndRed});
  const RgbdImage image = render(scene);
  const LocatedBlob blob = locate(image, rope_end_params()).value();
  EXPECT_LT((blob.position_world - rope.red_centroid).norm(), kToleranceM);

  ColorSegmentationParams strict = rope_end_params();
  strict.min_blob_area = blob.pixel_count + 1;
  EXPECT_FALSE(locate(image, strict));
  strict.min_blob_area = blob.pixel_count;
  EXPECT_TRUE(locate(image, strict));
}

TEST(RopeEndLocatorInputs, RejectsWrongTypesAndSizes) {
  const CameraIntrinsics k = head_camera_intrinsics();
  const cv::Mat rgb(k.height, k.width, CV_8UC3, cv::Scalar(0, 0, 0));
  const cv::Mat depth(k.height, k.width, CV_32FC1, cv::Scalar(0));
  const ColorSegmentationParams params;
  EXPECT_NO_THROW(locate_colour_blob(rgb, depth, k, head_camera_pose(), params));
  const cv::Mat grey(k.height, k.width, CV_8UC1, cv::Scalar(0));
  EXPECT_THROW(locate_colour_blob(grey, depth, k, head_camera_pose(), params),
               std::invalid_argument);
  const cv::Mat small_depth(10, 10, CV_32FC1, cv::Scalar(0));
  EXPECT_THROW(locate_colour_blob(rgb, small_depth, k, head_camera_pose(), params),
               std::invalid_argument);
  CameraIntrinsics other = k;
  other.width = 100;
  EXPECT_THROW(locate_colour_blob(rgb, depth, other, head_camera_pose(), params),
               std::invalid_argument);
  ColorSegmentationParams even = params;
  even.morphology_kernel = 4;
  EXPECT_THROW(locate_colour_blob(rgb, depth, k, head_camera_pose(), even), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp
