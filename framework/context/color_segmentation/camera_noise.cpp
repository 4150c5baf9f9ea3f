// Gaussian RGB and depth noise on a simulated head-camera image (paper, Section IV-C).
#include "context/color_segmentation/camera_noise.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace corrmp {
namespace {

constexpr float kSmallestNoisyDepth = 1e-4f;  // m: noise never turns a hit into "nothing"

}  // namespace

void add_camera_noise(cv::Mat& rgb, cv::Mat& depth, const ColorSegmentationParams& params,
                      Rng& rng) {
  params.validate();
  if (rgb.type() != CV_8UC3) throw std::invalid_argument("add_camera_noise: rgb must be CV_8UC3");
  if (depth.type() != CV_32FC1) {
    throw std::invalid_argument("add_camera_noise: depth must be CV_32FC1");
  }
  if (rgb.size() != depth.size()) {
    throw std::invalid_argument("add_camera_noise: rgb and depth sizes differ");
  }
  if (params.rgb_noise_std > 0.0) {
    for (int v = 0; v < rgb.rows; ++v) {
      auto* row = rgb.ptr<cv::Vec3b>(v);
      for (int u = 0; u < rgb.cols; ++u) {
        for (int c = 0; c < 3; ++c) {
          const double noisy = row[u][c] + rng.normal(0.0, params.rgb_noise_std);
          row[u][c] = cv::saturate_cast<uchar>(std::lround(noisy));
        }
      }
    }
  }
  if (params.depth_noise_std > 0.0) {
    for (int v = 0; v < depth.rows; ++v) {
      auto* row = depth.ptr<float>(v);
      for (int u = 0; u < depth.cols; ++u) {
        if (!(row[u] > 0.0f)) continue;
        const double noisy = row[u] + rng.normal(0.0, params.depth_noise_std);
        row[u] = std::max(kSmallestNoisyDepth, static_cast<float>(noisy));
      }
    }
  }
}

}  // namespace corrmp
