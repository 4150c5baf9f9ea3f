// Tests of the HSV colour mask of the rope-end segmentation (paper, Section IV-C) on
// synthetic images: the hue window wraps around red, saturation and value minima hold,
// and the opening removes specks while the closing fills pinholes.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include <cmath>

#include "context/color_segmentation/rope_end_locator.hpp"

namespace corrmp {
namespace {

// RGB pixel of a fully saturated, full-value colour of the given hue (degrees).
cv::Vec3b pure_hue(double hue) {
  cv::Mat hsv(1, 1, CV_32FC3, cv::Scalar(hue, 1.0, 1.0));
  cv::Mat rgb;
  cv::cvtColor(hsv, rgb, cv::COLOR_HSV2RGB);
  rgb.convertTo(rgb, CV_8UC3, 255.0);
  return rgb.at<cv::Vec3b>(0, 0);
}

bool passes(const cv::Vec3b& colour, const ColorSegmentationParams& params) {
  params.validate();
  ColorSegmentationParams no_cleaning = params;
  no_cleaning.morphology_kernel = 1;
  const cv::Mat image(4, 4, CV_8UC3, cv::Scalar(colour[0], colour[1], colour[2]));
  return cv::countNonZero(colour_mask(image, no_cleaning)) == 16;
}

TEST(ColourMask, HueWindowWrapsAroundRed) {
  ColorSegmentationParams params;  // centre 0, half width 15
  EXPECT_TRUE(passes(pure_hue(0.0), params));
  EXPECT_TRUE(passes(pure_hue(10.0), params));
  EXPECT_TRUE(passes(pure_hue(352.0), params));
  EXPECT_FALSE(passes(pure_hue(25.0), params));
  EXPECT_FALSE(passes(pure_hue(335.0), params));
  params.hue_centre = 355.0;
  params.hue_half_width = 8.0;
  EXPECT_TRUE(passes(pure_hue(2.0), params));
  EXPECT_FALSE(passes(pure_hue(5.0), params));
  EXPECT_FALSE(passes(pure_hue(120.0), params));
}

TEST(ColourMask, SaturationAndValueMinima) {
  const ColorSegmentationParams params;                    // saturation >= 0.5, value >= 0.2
  EXPECT_TRUE(passes(cv::Vec3b(217, 26, 26), params));     // the rope end's red
  EXPECT_FALSE(passes(cv::Vec3b(242, 153, 178), params));  // pink: too pale
  EXPECT_FALSE(passes(cv::Vec3b(40, 5, 5), params));       // too dark
  EXPECT_FALSE(passes(cv::Vec3b(60, 60, 70), params));     // dark gripper
  EXPECT_FALSE(passes(cv::Vec3b(242, 140, 26), params));   // orange: hue ~31 degrees
}

TEST(ColourMask, OpeningRemovesSpecksAndClosingFillsPinholes) {
  cv::Mat image(40, 40, CV_8UC3, cv::Scalar(230, 230, 230));
  cv::rectangle(image, cv::Rect(10, 10, 12, 12), cv::Scalar(217, 26, 26), cv::FILLED);
  image.at<cv::Vec3b>(15, 15) = cv::Vec3b(230, 230, 230);  // pinhole
  image.at<cv::Vec3b>(35, 35) = cv::Vec3b(217, 26, 26);    // speck
  ColorSegmentationParams params;
  params.morphology_kernel = 1;
  const cv::Mat raw = colour_mask(image, params);
  EXPECT_EQ(raw.at<uchar>(35, 35), 255);
  EXPECT_EQ(raw.at<uchar>(15, 15), 0);
  params.morphology_kernel = 3;
  const cv::Mat cleaned = colour_mask(image, params);
  EXPECT_EQ(cleaned.at<uchar>(35, 35), 0);
  EXPECT_EQ(cleaned.at<uchar>(15, 15), 255);
  EXPECT_EQ(cv::countNonZero(cleaned), 144 - 4);  // the 3x3 ellipse (a cross) rounds the corners
}

}  // namespace
}  // namespace corrmp
