// PNG export of RGB-D images (see rgbd_png.hpp).
#include "sim/render/rgbd_png.hpp"

#include <fmt/format.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <stdexcept>

namespace corrmp {
namespace {

void write_or_throw(const std::string& path, const cv::Mat& image) {
  bool written = false;
  try {
    written = cv::imwrite(path, image);
  } catch (const cv::Exception& error) {
    throw std::runtime_error(fmt::format("write_png: cannot write '{}': {}", path, error.what()));
  }
  if (!written) throw std::runtime_error(fmt::format("write_png: cannot write '{}'", path));
}

}  // namespace

void write_png(const RgbdImage& image, const std::string& rgb_path, const std::string& depth_path) {
  if (image.rgb.empty() || image.rgb.type() != CV_8UC3) {
    throw std::runtime_error(
        fmt::format("write_png: '{}': rgb must be a non-empty CV_8UC3 image", rgb_path));
  }
  cv::Mat bgr;
  cv::cvtColor(image.rgb, bgr, cv::COLOR_RGB2BGR);
  write_or_throw(rgb_path, bgr);
  if (depth_path.empty()) return;
  if (image.depth.empty() || image.depth.type() != CV_32FC1) {
    throw std::runtime_error(
        fmt::format("write_png: '{}': depth must be a non-empty CV_32FC1 image", depth_path));
  }
  cv::Mat millimetres;
  image.depth.convertTo(millimetres, CV_16UC1, 1000.0);  // rounds and saturates
  write_or_throw(depth_path, millimetres);
}

}  // namespace corrmp
