// Synthetic scene images for the autoencoder tests: a coloured square on a grey background at a
// continuous horizontal position, a stand-in for the paper's camera images whose relevant
// content (the corridor offset) is a position (Section III "Learning the Context").
#pragma once

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <vector>

#include "core/seeds.hpp"

namespace corrmp::testing {

/// A size x size RGB image: grey (128) background and a red square of side `side`, vertically
/// centred, covering columns [x, x + side) with fractional coverage of the edge columns.
inline cv::Mat square_image(double x, int size, int side) {
  cv::Mat image(size, size, CV_8UC3, cv::Scalar(128, 128, 128));
  const double colour[3] = {230, 40, 40};
  const int top = (size - side) / 2;
  for (int w = 0; w < size; ++w) {
    const double coverage =
        std::clamp(std::min(w + 1.0, x + side) - std::max<double>(w, x), 0.0, 1.0);
    for (int h = top; h < top + side; ++h) {
      auto& pixel = image.at<cv::Vec3b>(h, w);
      for (int c = 0; c < 3; ++c)
        pixel[c] = cv::saturate_cast<uchar>(coverage * colour[c] + (1.0 - coverage) * 128.0);
    }
  }
  return image;
}

struct SquareSet {
  std::vector<cv::Mat> images;
  std::vector<double> positions;
};

/// `count` images with positions uniform in [0, size - side].
inline SquareSet square_set(int count, int size, int side, Rng& rng) {
  SquareSet set;
  for (int i = 0; i < count; ++i) {
    set.positions.push_back(rng.uniform(0.0, size - side));
    set.images.push_back(square_image(set.positions.back(), size, side));
  }
  return set;
}

}  // namespace corrmp::testing
