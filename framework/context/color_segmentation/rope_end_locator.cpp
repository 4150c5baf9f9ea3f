// Colour segmentation, clustering and back-projection of the rope end (paper, Section IV-C).
#include "context/color_segmentation/rope_end_locator.hpp"

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace corrmp {
namespace {

// Angular distance between two hues on the colour circle, in [0, 180] degrees.
double hue_distance(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

void check_rgb(const cv::Mat& rgb, const char* where) {
  if (rgb.empty() || rgb.type() != CV_8UC3) {
    throw std::invalid_argument(fmt::format("{}: rgb must be a non-empty CV_8UC3 image", where));
  }
}

void check_inputs(const cv::Mat& rgb, const cv::Mat& depth, const CameraIntrinsics& intrinsics) {
  constexpr const char* kWhere = "locate_colour_blob";
  check_rgb(rgb, kWhere);
  if (depth.type() != CV_32FC1 || depth.size() != rgb.size()) {
    throw std::invalid_argument("locate_colour_blob: depth must be CV_32FC1 of the rgb size");
  }
  intrinsics.validate();
  if (rgb.cols != intrinsics.width || rgb.rows != intrinsics.height) {
    throw std::invalid_argument(
        fmt::format("locate_colour_blob: image is {}x{} but the intrinsics are {}x{}", rgb.cols,
                    rgb.rows, intrinsics.width, intrinsics.height));
  }
}

// Label of the largest component of at least min_area pixels, or 0 (the background label).
int largest_component(const cv::Mat& stats, int min_area) {
  int best = 0;
  int best_area = 0;
  for (int label = 1; label < stats.rows; ++label) {
    const int area = stats.at<int>(label, cv::CC_STAT_AREA);
    if (area >= min_area && area > best_area) {
      best = label;
      best_area = area;
    }
  }
  return best;
}

double median_of(std::vector<double> values) {
  const auto middle = values.begin() + values.size() / 2;
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

cv::Mat colour_mask(const cv::Mat& rgb, const ColorSegmentationParams& params) {
  check_rgb(rgb, "colour_mask");
  params.validate();
  cv::Mat unit_rgb;
  rgb.convertTo(unit_rgb, CV_32FC3, 1.0 / 255.0);
  cv::Mat hsv;  // float HSV: hue in [0, 360), saturation and value in [0, 1]
  cv::cvtColor(unit_rgb, hsv, cv::COLOR_RGB2HSV);
  cv::Mat mask(rgb.size(), CV_8UC1, cv::Scalar(0));
  for (int v = 0; v < hsv.rows; ++v) {
    const auto* in = hsv.ptr<cv::Vec3f>(v);
    auto* out = mask.ptr<uchar>(v);
    for (int u = 0; u < hsv.cols; ++u) {
      const bool passes = hue_distance(in[u][0], params.hue_centre) <= params.hue_half_width &&
                          in[u][1] >= params.saturation_min && in[u][2] >= params.value_min;
      out[u] = passes ? 255 : 0;
    }
  }
  if (params.morphology_kernel > 1) {
    const cv::Mat kernel = cv::getStructuringElement(
        cv::MORPH_ELLIPSE, cv::Size(params.morphology_kernel, params.morphology_kernel));
    cv::morphologyEx(mask, mask, cv::MORPH_OPEN, kernel);
    cv::morphologyEx(mask, mask, cv::MORPH_CLOSE, kernel);
  }
  return mask;
}

std::optional<LocatedBlob> locate_colour_blob(const cv::Mat& rgb, const cv::Mat& depth,
                                              const CameraIntrinsics& intrinsics,
                                              const Eigen::Isometry3d& world_from_camera,
                                              const ColorSegmentationParams& params) {
  check_inputs(rgb, depth, intrinsics);
  const cv::Mat mask = colour_mask(rgb, params);

  cv::Mat labels, stats, centroids;
  cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  const int chosen = largest_component(stats, params.min_blob_area);
  if (chosen == 0) return std::nullopt;

  LocatedBlob blob;
  blob.mask = (labels == chosen);
  blob.pixel_count = stats.at<int>(chosen, cv::CC_STAT_AREA);
  blob.pixel_centroid =
      Eigen::Vector2d(centroids.at<double>(chosen, 0), centroids.at<double>(chosen, 1));

  std::vector<cv::Point> pixels;
  std::vector<double> depths;
  for (int v = 0; v < labels.rows; ++v) {
    const auto* label_row = labels.ptr<int>(v);
    const auto* depth_row = depth.ptr<float>(v);
    for (int u = 0; u < labels.cols; ++u) {
      if (label_row[u] != chosen || !(depth_row[u] > 0.0f) || !std::isfinite(depth_row[u])) {
        continue;
      }
      pixels.emplace_back(u, v);
      depths.push_back(depth_row[u]);
    }
  }
  if (depths.empty()) return std::nullopt;

  const double median_depth = median_of(depths);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < pixels.size(); ++i) {
    if (std::abs(depths[i] - median_depth) > params.max_depth_deviation) continue;
    sum += back_project(intrinsics, world_from_camera, Eigen::Vector2d(pixels[i].x, pixels[i].y),
                        depths[i]);
    ++blob.depth_pixel_count;
  }
  const Eigen::Vector3d surface_point = sum / blob.depth_pixel_count;
  const Eigen::Vector3d ray = (surface_point - world_from_camera.translation()).normalized();
  blob.position_world = surface_point + params.surface_offset * ray;
  return blob;
}

}  // namespace corrmp
