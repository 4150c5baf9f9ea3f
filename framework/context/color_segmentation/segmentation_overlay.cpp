// Drawing the rope-end segmentation over the camera picture (paper, Section IV-C).
#include "context/color_segmentation/segmentation_overlay.hpp"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace corrmp {
namespace {

// Colours in B, G, R order.
const cv::Scalar kMaskTint(0, 255, 0);
const cv::Scalar kOutline(0, 160, 0);
const cv::Scalar kCentroid(255, 0, 255);
const cv::Scalar kLocated(0, 255, 255);
const cv::Scalar kReference(255, 255, 0);
constexpr double kTintWeight = 0.45;
constexpr int kMarkerSize = 9;
constexpr int kCircleRadius = 5;

void circle_where_projected(cv::Mat& image, const CameraIntrinsics& intrinsics,
                            const Eigen::Isometry3d& world_from_camera,
                            const Eigen::Vector3d& point, const cv::Scalar& colour) {
  const std::optional<Eigen::Vector2d> pixel = project(intrinsics, world_from_camera, point);
  if (!pixel) return;
  const cv::Point centre(int(std::lround(pixel->x())), int(std::lround(pixel->y())));
  cv::circle(image, centre, kCircleRadius, colour, 1, cv::LINE_AA);
}

}  // namespace

cv::Mat draw_segmentation_overlay(const cv::Mat& rgb, const std::optional<LocatedBlob>& blob,
                                  const CameraIntrinsics& intrinsics,
                                  const Eigen::Isometry3d& world_from_camera,
                                  const std::optional<Eigen::Vector3d>& reference_world) {
  if (rgb.empty() || rgb.type() != CV_8UC3) {
    throw std::invalid_argument("draw_segmentation_overlay: rgb must be a non-empty CV_8UC3");
  }
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  if (blob) {
    if (blob->mask.type() != CV_8UC1 || blob->mask.size() != rgb.size()) {
      throw std::invalid_argument(
          "draw_segmentation_overlay: the blob's mask must be CV_8UC1 of the rgb size");
    }
    cv::Mat tinted = bgr.clone();
    tinted.setTo(kMaskTint, blob->mask);
    cv::Mat blended;
    cv::addWeighted(bgr, 1.0 - kTintWeight, tinted, kTintWeight, 0.0, blended);
    blended.copyTo(bgr, blob->mask);
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(blob->mask.clone(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
    cv::drawContours(bgr, contours, -1, kOutline, 1);
    const cv::Point centroid(int(std::lround(blob->pixel_centroid.x())),
                             int(std::lround(blob->pixel_centroid.y())));
    cv::drawMarker(bgr, centroid, kCentroid, cv::MARKER_CROSS, kMarkerSize, 1);
    circle_where_projected(bgr, intrinsics, world_from_camera, blob->position_world, kLocated);
  }
  if (reference_world) {
    circle_where_projected(bgr, intrinsics, world_from_camera, *reference_world, kReference);
  }
  return bgr;
}

}  // namespace corrmp
