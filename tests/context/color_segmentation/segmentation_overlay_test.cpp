// Tests of the rope-end segmentation figure (paper, Section IV-C): BGR output of the input
// size, the mask tinted green, the picture unchanged away from the drawings.
#include "context/color_segmentation/segmentation_overlay.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace corrmp {
namespace {

CameraIntrinsics small_camera() { return CameraIntrinsics::from_vertical_fov(64, 48, 0.8); }

TEST(SegmentationOverlay, WithoutABlobIsTheBgrPicture) {
  const cv::Mat rgb(48, 64, CV_8UC3, cv::Scalar(10, 100, 200));
  const cv::Mat bgr =
      draw_segmentation_overlay(rgb, std::nullopt, small_camera(), Eigen::Isometry3d::Identity());
  ASSERT_EQ(bgr.type(), CV_8UC3);
  ASSERT_EQ(bgr.size(), rgb.size());
  EXPECT_EQ(bgr.at<cv::Vec3b>(5, 5), cv::Vec3b(200, 100, 10));
}

TEST(SegmentationOverlay, TintsTheMaskAndMarksThePoints) {
  const cv::Mat rgb(48, 64, CV_8UC3, cv::Scalar(200, 200, 200));
  LocatedBlob blob;
  blob.mask = cv::Mat(48, 64, CV_8UC1, cv::Scalar(0));
  blob.mask(cv::Rect(20, 20, 10, 10)).setTo(255);
  blob.pixel_count = 100;
  blob.pixel_centroid = Eigen::Vector2d(24.5, 24.5);
  blob.position_world = Eigen::Vector3d(0.0, 0.0, 1.0);  // projects onto the image centre
  const cv::Mat bgr = draw_segmentation_overlay(
      rgb, blob, small_camera(), Eigen::Isometry3d::Identity(), Eigen::Vector3d(0.1, 0.1, 1.0));
  const cv::Vec3b inside = bgr.at<cv::Vec3b>(28, 21);
  EXPECT_GT(inside[1], inside[0] + 50);  // green over blue
  EXPECT_GT(inside[1], inside[2] + 50);  // and red
  EXPECT_EQ(bgr.at<cv::Vec3b>(2, 2), cv::Vec3b(200, 200, 200));
  EXPECT_EQ(bgr.at<cv::Vec3b>(45, 2), cv::Vec3b(200, 200, 200));
  EXPECT_EQ(bgr.at<cv::Vec3b>(25, 25), cv::Vec3b(255, 0, 255));  // centroid cross, magenta
  EXPECT_EQ(bgr.at<cv::Vec3b>(20, 20), cv::Vec3b(0, 160, 0));    // outline, dark green
}

TEST(SegmentationOverlay, RejectsAMaskOfTheWrongSize) {
  const cv::Mat rgb(48, 64, CV_8UC3, cv::Scalar(0, 0, 0));
  LocatedBlob blob;
  blob.mask = cv::Mat(10, 10, CV_8UC1, cv::Scalar(0));
  EXPECT_THROW(draw_segmentation_overlay(rgb, blob, small_camera(), Eigen::Isometry3d::Identity()),
               std::invalid_argument);
}

}  // namespace
}  // namespace corrmp
