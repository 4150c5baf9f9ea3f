// One picture from the simulated head camera: colour plus metric depth, pixel for
// pixel (the RGB-D image of paper Sec. IV-C; the colour image alone is the input of the
// "Learning the Context" autoencoder, Sec. III-B and IV-A).
#pragma once

#include <opencv2/core.hpp>

namespace corrmp {

struct RgbdImage {
  // CV_8UC3, channels in R, G, B order (not OpenCV's usual BGR: convert with
  // cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR) before cv::imwrite or cv::imshow).
  // Row 0 is the top of the image.
  cv::Mat rgb;
  // CV_32FC1, metres along the camera z axis (the optical axis, not the ray length);
  // 0 where nothing was hit. Same size and row order as rgb.
  cv::Mat depth;
};

}  // namespace corrmp
